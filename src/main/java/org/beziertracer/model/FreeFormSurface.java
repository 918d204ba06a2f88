package org.beziertracer.model;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

import org.beziertracer.math.BezierDecomposition;

/**
 * An immutable free-form surface as a file describes it (an OBJ {@code surf}): Bézier or
 * B-spline ({@link SplineBasis}), rational or not, degrees 1..{@value BezierPatch#MAX_DEGREE}, the
 * parameter values of each direction ({@code parm}: knots or Bézier breakpoints), a control net of
 * {@code countU × countV} points (u fastest, {@code x y z}), an optional weight per point, the
 * parameter range {@code [u0,u1] × [v0,v1]} used (OBJ {@code surf s0 s1 t0 t1}, inside the knot
 * range) and an optional {@link TrimRegion}.
 *
 * <p>It is kept as the original so that writers put it back unchanged; the scene renders its
 * Bézier pieces, {@link #toPatches()}, obtained by knot insertion
 * ({@link BezierDecomposition}). Weights are kept as given, also when all are 1.
 */
public final class FreeFormSurface {

    private final SplineBasis basis;
    private final int degreeU, degreeV, countU, countV;
    private final double[] parmU, parmV, points, weights, range;
    private final TrimRegion trim;

    /**
     * @param points  {@code countU·countV} points as {@code x y z}, u fastest
     * @param weights null (polynomial) or one positive finite weight per point
     * @param range   {@code u0, u1, v0, v1}, with {@code u0 < u1}, {@code v0 < v1} inside the knot ranges
     * @param trim    null (untrimmed) or the trim loops
     * @throws IllegalArgumentException one line naming the problem
     */
    public FreeFormSurface(SplineBasis basis, int degreeU, int degreeV, double[] parmU, double[] parmV,
                           int countU, int countV, double[] points, double[] weights, double[] range, TrimRegion trim) {
        BezierPatch.checkDegree("u", degreeU);
        BezierPatch.checkDegree("v", degreeV);
        if (points.length != 3L * countU * countV) {
            throw new IllegalArgumentException("expected " + 3L * countU * countV + " coordinates for " + countU + "x"
                    + countV + " control points, got " + points.length);
        }
        check("u", basis.problem(degreeU, parmU, countU));
        check("v", basis.problem(degreeV, parmV, countV));
        for (double x : points) {
            if (!Double.isFinite(x)) {
                throw new IllegalArgumentException("control point coordinates must be finite, got " + x);
            }
        }
        if (weights != null) {
            BezierPatch.checkWeights(weights, countU * countV);
        }
        checkRange("u", range[0], range[1], basis.start(degreeU, parmU), basis.end(degreeU, parmU));
        checkRange("v", range[2], range[3], basis.start(degreeV, parmV), basis.end(degreeV, parmV));
        this.basis = basis;
        this.degreeU = degreeU;
        this.degreeV = degreeV;
        this.countU = countU;
        this.countV = countV;
        this.parmU = kept(parmU);
        this.parmV = kept(parmV);
        this.points = points.clone();
        this.weights = weights == null ? null : weights.clone();
        this.range = range.length >= 4 && Arrays.equals(range, 0, 4, UNIT_RANGE, 0, 4) ? UNIT_RANGE : Arrays.copyOf(range, 4);
        this.trim = trim;
    }

    /** The parameter values {0, 1} of a one-segment Bézier surface, shared by every surface that has them. */
    private static final double[] UNIT = {0, 1};
    /** The range [0,1]², shared alike. */
    private static final double[] UNIT_RANGE = {0, 1, 0, 1};

    /**
     * Parameter values as kept: a copy, or the shared {@link #UNIT} (never changed, never handed
     * out) for the values most surfaces of a big model have, one object less each.
     */
    private static double[] kept(double[] parm) {
        return Arrays.equals(parm, UNIT) ? UNIT : parm.clone();
    }

    private static void check(String direction, String problem) {
        if (problem != null) {
            throw new IllegalArgumentException("parm " + direction + ": " + problem);
        }
    }

    private static void checkRange(String direction, double lo, double hi, double start, double end) {
        if (!(lo < hi && lo >= start && hi <= end)) {
            throw new IllegalArgumentException("expected the surface range " + direction + "[" + lo + ", " + hi
                    + "] inside the knot range [" + start + ", " + end + "], found it outside (or empty)");
        }
    }

    public SplineBasis basis() { return basis; }

    public boolean rational() { return weights != null; }

    public int degreeU() { return degreeU; }

    public int degreeV() { return degreeV; }

    public int countU() { return countU; }

    public int countV() { return countV; }

    /** Parameter values in u as given (a copy). */
    public double[] parmU() { return parmU.clone(); }

    /** Parameter values in v as given (a copy). */
    public double[] parmV() { return parmV.clone(); }

    /** Control points {@code x y z}, u fastest (a copy). */
    public double[] points() { return points.clone(); }

    /** Weights (a copy), or null for a polynomial surface. */
    public double[] weights() { return weights == null ? null : weights.clone(); }

    /** {@code u0, u1, v0, v1} (a copy). */
    public double[] range() { return range.clone(); }

    /** The trim loops, or null. */
    public TrimRegion trim() { return trim; }

    /** How many Bézier pieces {@link #toPatches()} makes (the knot spans in the range), without making them. */
    public long pieceCount() {
        return (long) spans(parmU, range[0], range[1]) * spans(parmV, range[2], range[3]);
    }

    /**
     * The knot spans of {@code knots} in {@code (from, to)}: 1 + the distinct values strictly
     * between. The parameter values as given count the same as their knot vector (which only
     * repeats them).
     */
    private static int spans(double[] knots, double from, double to) {
        int count = 1;
        double last = from;
        for (double k : knots) {
            if (k > last && k < to) {
                count++;
                last = k;
            }
        }
        return count;
    }

    /**
     * The Bézier pieces, v piece major and u piece fastest, each with its {@link PatchDomain} (its
     * box in this surface's parameters and the trim region) and its {@link PatchOrigin}. A piece
     * whose weights all come out as exactly 1 is polynomial.
     */
    public List<BezierPatch> toPatches() {
        if (weights == null && basis == SplineBasis.BEZIER && parmU.length == 2 && parmV.length == 2
                && range[0] == parmU[0] && range[1] == parmU[1] && range[2] == parmV[0] && range[3] == parmV[1]) {
            // one polynomial Bézier net over the whole range (most surfaces of big models): the
            // points themselves, shared with the patch (both immutable), as the decomposition
            // would leave them
            PatchDomain domain = new PatchDomain(range[0], range[1], range[2], range[3], trim);
            return List.of(new BezierPatch(degreeU, degreeV, points, null, domain, new PatchOrigin(this, 0, 1), true));
        }
        int dim = weights == null ? 3 : 4;
        double[] pts = points;
        if (weights != null) {
            pts = new double[4 * countU * countV];
            for (int k = 0; k < countU * countV; k++) {
                double w = weights[k];
                pts[4 * k] = w * points[3 * k];
                pts[4 * k + 1] = w * points[3 * k + 1];
                pts[4 * k + 2] = w * points[3 * k + 2];
                pts[4 * k + 3] = w;
            }
        }
        BezierDecomposition.Patches pieces = BezierDecomposition.surface(degreeU, degreeV,
                basis.knotVector(degreeU, parmU), basis.knotVector(degreeV, parmV), countU, countV, pts, dim,
                range[0], range[1], range[2], range[3]);
        int total = pieces.nets().length;
        List<BezierPatch> out = new ArrayList<>(total);
        double[] bu = pieces.breaksU(), bv = pieces.breaksV();
        for (int k = 0; k < total; k++) {
            int a = k % pieces.countU(), b = k / pieces.countU();
            PatchDomain domain = new PatchDomain(bu[a], bu[a + 1], bv[b], bv[b + 1], trim);
            out.add(BezierPatch.fromNet(degreeU, degreeV, pieces.nets()[k], dim, domain,
                    new PatchOrigin(this, k, total), true)); // the nets are the decomposition's own
        }
        return out;
    }

    /** Equal descriptions: same basis, degrees, parameter values, points, weights, range and trim loops. */
    @Override
    public boolean equals(Object o) {
        return o instanceof FreeFormSurface s && s.basis == basis && s.degreeU == degreeU && s.degreeV == degreeV
                && s.countU == countU && s.countV == countV && Arrays.equals(s.parmU, parmU)
                && Arrays.equals(s.parmV, parmV) && Arrays.equals(s.points, points) && Arrays.equals(s.weights, weights)
                && Arrays.equals(s.range, range) && Objects.equals(s.trim, trim);
    }

    @Override
    public int hashCode() {
        return Objects.hash(basis, degreeU, degreeV, countU, countV, Arrays.hashCode(points), Arrays.hashCode(parmU));
    }

    @Override
    public String toString() {
        return (rational() ? "rational " : "") + basis.objName() + " surface of degree " + degreeU + "x" + degreeV
                + ", " + countU + "x" + countV + " control points" + (trim == null ? "" : ", trimmed");
    }
}
