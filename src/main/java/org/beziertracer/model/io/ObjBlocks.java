package org.beziertracer.model.io;

import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;

/**
 * Turns a finished OBJ {@code curv2 … end} or {@code surf … end} block ({@link ObjFreeForm.Block})
 * into a {@link TrimCurve} or a {@link FreeFormSurface}, with one-line errors naming the line at
 * fault: the {@code parm} line for a parameter vector that does not fit, the block's first line
 * otherwise. Stateless.
 */
final class ObjBlocks {
    private ObjBlocks() {}

    static TrimCurve curve(ObjFreeForm.Block b, ObjVertices vertices, String file) {
        double[] parm = parm(b, b.parmU, "u", file);
        int count = b.refs.length;
        String problem = b.basis.problem(b.degreeU, parm, count);
        if (problem != null) {
            throw new ModelFormatException(file, b.parmU != null ? b.parmULine : b.line, "parm u: " + problem);
        }
        double[] points = new double[2 * count];
        double[] weights = b.rational ? new double[count] : null;
        for (int k = 0; k < count; k++) {
            points[2 * k] = vertices.param(b.refs[k], 0);
            points[2 * k + 1] = vertices.param(b.refs[k], 1);
            if (weights != null) {
                weights[k] = vertices.param(b.refs[k], 2);
            }
        }
        try {
            return new TrimCurve(b.basis, b.degreeU, parm, points, weights);
        } catch (IllegalArgumentException e) {
            throw new ModelFormatException(file, b.line, e.getMessage());
        }
    }

    static FreeFormSurface surface(ObjFreeForm.Block b, ObjVertices vertices, String file) {
        double[] pu = parm(b, b.parmU, "u", file), pv = parm(b, b.parmV, "v", file);
        int n = b.degreeU, m = b.degreeV;
        long countU, countV;
        if (b.basis == SplineBasis.BEZIER) {
            countU = (long) (pu.length - 1) * n + 1;
            countV = (long) (pv.length - 1) * m + 1;
            if (countU * countV != b.refs.length) {
                int su = pu.length - 1, sv = pv.length - 1;
                throw new ModelFormatException(file, b.line, "expected " + countU * countV
                        + " control-point indices for a degree " + n + "x" + m + " surf of " + su + "x" + sv
                        + " segments ((" + su + "·" + n + "+1)(" + sv + "·" + m + "+1)), found " + b.refs.length
                        + (b.parmU == null || b.parmV == null ? " (parm u / parm v give the segment counts)" : ""));
            }
        } else {
            countU = pu.length - n - 1L;
            countV = pv.length - m - 1L;
            if (countU < 1 || countV < 1 || countU * countV != b.refs.length) {
                throw new ModelFormatException(file, b.line, "expected (" + pu.length + "−" + n + "−1)·(" + pv.length
                        + "−" + m + "−1) = " + Math.max(0, countU) * Math.max(0, countV)
                        + " control-point indices for the knot vectors of parm u (" + pu.length + " knots) and parm v ("
                        + pv.length + " knots) of a degree " + n + "x" + m + " B-spline, found " + b.refs.length
                        + " (a knot vector of the wrong length, or the wrong number of points)");
            }
        }
        check(b, b.basis.problem(n, pu, (int) countU), "u", b.parmULine, file);
        check(b, b.basis.problem(m, pv, (int) countV), "v", b.parmVLine, file);
        checkRange(b, "u", b.range[0], b.range[1], b.basis.start(n, pu), b.basis.end(n, pu), file);
        checkRange(b, "v", b.range[2], b.range[3], b.basis.start(m, pv), b.basis.end(m, pv), file);
        int count = b.refs.length;
        double[] points = new double[3 * count];
        double[] weights = b.rational ? new double[count] : null;
        for (int k = 0; k < count; k++) {
            for (int c = 0; c < 3; c++) {
                points[3 * k + c] = vertices.vertex(b.refs[k], c);
            }
            if (weights != null) {
                weights[k] = vertices.vertex(b.refs[k], 3);
            }
        }
        try {
            return new FreeFormSurface(b.basis, n, m, pu, pv, (int) countU, (int) countV, points, weights, b.range,
                    b.trim());
        } catch (IllegalArgumentException e) {
            throw new ModelFormatException(file, b.line, e.getMessage());
        }
    }

    /** The block's parameter values in one direction; a Bézier block without them spans [0,1]. */
    private static double[] parm(ObjFreeForm.Block b, double[] given, String direction, String file) {
        if (given == null && b.basis == SplineBasis.BSPLINE) {
            throw new ModelFormatException(file, b.line, "expected parm " + direction + " (the knot vector) in the "
                    + b.keyword() + " … end block of a B-spline, found none");
        }
        return ObjFreeForm.Block.orDefault(given);
    }

    private static void check(ObjFreeForm.Block b, String problem, String direction, int parmLine, String file) {
        if (problem != null) {
            throw new ModelFormatException(file, parmLine > 0 ? parmLine : b.line, "parm " + direction + ": " + problem);
        }
    }

    private static void checkRange(ObjFreeForm.Block b, String direction, double lo, double hi, double start,
                                   double end, String file) {
        if (!(lo < hi && lo >= start && hi <= end)) {
            throw new ModelFormatException(file, b.line, "expected the surf range " + direction + "["
                    + NumberText.format(lo) + "," + NumberText.format(hi) + "] inside the parameter range ["
                    + NumberText.format(start) + "," + NumberText.format(end) + "] of parm " + direction
                    + ", found it " + (lo < hi ? "outside" : "empty"));
        }
    }
}
