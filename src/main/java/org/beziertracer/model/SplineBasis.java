package org.beziertracer.model;

import org.beziertracer.math.KnotVector;

/**
 * How the parameter values of a free-form curve or surface (the OBJ {@code parm} statement) are
 * read. A {@link #BSPLINE} takes them as its knot vector. A {@link #BEZIER} curve of degree
 * {@code p} takes them as the breakpoints {@code t_0 < … < t_K} of {@code K} Bézier segments with
 * {@code K·p + 1} control points, neighbouring segments sharing an end point; that is the
 * B-spline with each inner breakpoint {@code p} times and each end {@code p + 1} times
 * ({@link #knotVector}), so both kinds go through the same Bézier extraction.
 */
public enum SplineBasis {
    BEZIER("bezier"), BSPLINE("bspline");

    private final String objName;

    SplineBasis(String objName) {
        this.objName = objName;
    }

    /** The name in an OBJ {@code cstype} statement. */
    public String objName() { return objName; }

    /**
     * Null when {@code parm} suits {@code pointCount} control points of degree {@code degree},
     * else one line naming the problem.
     */
    public String problem(int degree, double[] parm, int pointCount) {
        if (this == BSPLINE) {
            return KnotVector.problem(degree, parm, pointCount);
        }
        if (parm.length < 2) {
            return "expected at least 2 parameter values (the ends of the segments), found " + parm.length;
        }
        for (int k = 0; k < parm.length; k++) {
            if (!Double.isFinite(parm[k]) || (k > 0 && !(parm[k] > parm[k - 1]))) {
                return "expected increasing finite parameter values, found " + parm[k]
                        + (k > 0 ? " after " + parm[k - 1] : "");
            }
        }
        long expected = (long) (parm.length - 1) * degree + 1;
        if (pointCount != expected) {
            return "expected " + expected + " control points for " + (parm.length - 1) + " Bézier segment(s) of degree "
                    + degree + " (segments·degree + 1), found " + pointCount;
        }
        return null;
    }

    /** The start of the parameter range these values give: {@link KnotVector#start} of {@link #knotVector}, without making it. */
    public double start(int degree, double[] parm) {
        return this == BSPLINE ? KnotVector.start(degree, parm) : parm[0];
    }

    /** The end of the parameter range these values give: {@link KnotVector#end} of {@link #knotVector}, without making it. */
    public double end(int degree, double[] parm) {
        return this == BSPLINE ? KnotVector.end(degree, parm) : parm[parm.length - 1];
    }

    /** The B-spline knot vector of these parameter values (a copy for {@link #BSPLINE}). */
    public double[] knotVector(int degree, double[] parm) {
        if (this == BSPLINE) {
            return parm.clone();
        }
        int segments = parm.length - 1;
        double[] knots = new double[(segments + 1) * degree + 2];
        int k = 0;
        for (int s = 0; s <= segments; s++) {
            int times = s == 0 || s == segments ? degree + 1 : degree;
            for (int r = 0; r < times; r++) {
                knots[k++] = parm[s];
            }
        }
        return knots;
    }
}
