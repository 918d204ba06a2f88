package org.beziertracer.geometry;

import java.util.ArrayList;
import java.util.List;
import java.util.PriorityQueue;

/**
 * The maximum over {@code t ∈ [0,1]} of a measure {@code f(t)} computed from a few polynomials in
 * Bernstein form, certified by branch and bound: every segment of {@code [0,1]} carries an upper
 * bound of {@code f} proved from its polynomials' coefficients ({@link Measure#bound}); the segment
 * with the largest bound is halved (de Casteljau, {@link BernsteinPoly#halves}) and the measure is
 * sampled exactly at the new end point, until the largest bound is within
 * {@link #RELATIVE_GAP} (1 %) of the largest sample, or below an absolute floor. The answer is
 * then an upper bound of {@code f} over the whole interval, together with the worst sample and its
 * parameter — the bound is never below any value of {@code f}, and within 1 % of one.
 *
 * <p>Subdivision of Bernstein bounds converging to the range of a polynomial: J. M. Lane and R. F.
 * Riesenfeld, "Bounds on a polynomial", BIT 21 (1981) 112–117; the best-first branch and bound on
 * those bounds as in global optimisation with Bernstein expansions (J. Garloff, "The Bernstein
 * algorithm", Interval Computations 2 (1993) 154–168).
 *
 * <h2>Degenerate points</h2>
 * A segment whose bound the measure cannot give (the measure is undefined somewhere in it, e.g. a
 * normal that vanishes, {@link Measure#degenerate}) is split like any other; once it is shorter
 * than {@code 2^-}{@link #DEGENERATE_DEPTH} it is <i>excluded</i>: left out of the bound and
 * reported by its middle parameter ({@link Result#degenerate}). A segment that reaches
 * {@link #MAX_DEPTH} with a finite bound keeps it (the answer is then not within 1 %, and says so).
 *
 * <p>Stateless and thread-safe.
 */
public final class CertifiedMax {

    /** The bound is accepted within this fraction above the largest sample. */
    public static final double RELATIVE_GAP = 0.01;
    /** Segments shorter than {@code 2^-DEGENERATE_DEPTH} where the measure is undefined are excluded. */
    public static final int DEGENERATE_DEPTH = 24;
    /** Segments are not halved below {@code 2^-MAX_DEPTH}. */
    public static final int MAX_DEPTH = 50;

    private CertifiedMax() {}

    /** A non-negative measure of a few polynomials, with bounds proved from their coefficients. */
    public interface Measure {
        /**
         * An upper bound of the measure over the segment the polynomials describe (each
         * reparametrised to {@code [0,1]}): never below the measure anywhere in it; +∞ or NaN when
         * none can be given.
         */
        double bound(BernsteinPoly[] polys);

        /** The measure at the start ({@code atOne} false) or end of the segment, from the end coefficients; NaN where undefined. */
        double value(BernsteinPoly[] polys, boolean atOne);

        /** True when the measure may be undefined somewhere in the segment (then it may be excluded when tiny). */
        boolean degenerate(BernsteinPoly[] polys);
    }

    /**
     * The certified maximum.
     *
     * @param bound      upper bound of the measure over {@code [0,1]} minus the excluded points;
     *                   NaN when nothing could be sampled
     * @param worst      the largest sampled value
     * @param tWorst     where it was sampled
     * @param tight      true when {@code bound ≤ max(1.01·worst, floor)}
     * @param degenerate middles of the excluded segments (merged when closer than 1e-3), ascending
     * @param segments   segments made
     */
    public record Result(double bound, double worst, double tWorst, boolean tight, double[] degenerate, int segments) {}

    private record Segment(double a, double b, int depth, BernsteinPoly[] polys, double bound) {}

    /**
     * Bounds {@code f} over {@code [0,1]}.
     *
     * @param f           the measure
     * @param polys       its polynomials on {@code [0,1]}
     * @param floor       a bound at or below this is good enough whatever the samples
     * @param maxSegments stop after this many segments (the bound stays valid, maybe not tight)
     */
    public static Result maximise(Measure f, BernsteinPoly[] polys, double floor, int maxSegments) {
        PriorityQueue<Segment> queue = new PriorityQueue<>((x, y) -> Double.compare(key(y.bound), key(x.bound)));
        double[] worst = {Double.NEGATIVE_INFINITY, 0};
        sample(f.value(polys, false), 0, worst);
        sample(f.value(polys, true), 1, worst);
        queue.add(new Segment(0, 1, 0, polys, f.bound(polys)));
        List<Double> excluded = new ArrayList<>();
        double kept = Double.NEGATIVE_INFINITY; // bounds of segments at the depth cap
        int segments = 1;
        while (!queue.isEmpty()) {
            Segment s = queue.peek();
            double accept = Math.max(floor, (1 + RELATIVE_GAP) * worst[0]);
            if (key(s.bound) <= accept || segments >= maxSegments) {
                break;
            }
            queue.poll();
            boolean unbounded = !(s.bound < Double.POSITIVE_INFINITY);
            if (unbounded && s.depth >= DEGENERATE_DEPTH && f.degenerate(s.polys)) {
                excluded.add(0.5 * (s.a + s.b));
                continue;
            }
            if (s.depth >= MAX_DEPTH) {
                kept = Math.max(kept, unbounded ? Double.POSITIVE_INFINITY : s.bound);
                continue;
            }
            // Halve, sample the new end point, bound both halves
            double mid = 0.5 * (s.a + s.b);
            BernsteinPoly[] left = new BernsteinPoly[s.polys.length], right = new BernsteinPoly[s.polys.length];
            for (int k = 0; k < s.polys.length; k++) {
                BernsteinPoly[] h = s.polys[k].halves();
                left[k] = h[0];
                right[k] = h[1];
            }
            sample(f.value(left, true), mid, worst);
            queue.add(new Segment(s.a, mid, s.depth + 1, left, f.bound(left)));
            queue.add(new Segment(mid, s.b, s.depth + 1, right, f.bound(right)));
            segments++;
        }
        double top = queue.isEmpty() ? Double.NEGATIVE_INFINITY : key(queue.peek().bound);
        double bound = Math.max(Math.max(top, kept), worst[0]);
        if (worst[0] == Double.NEGATIVE_INFINITY) {
            bound = Double.NaN;
        }
        boolean tight = bound <= Math.max(floor, (1 + RELATIVE_GAP) * worst[0]);
        return new Result(bound, Math.max(0, worst[0]), worst[1], tight, merge(excluded), segments);
    }

    /** NaN sorts as +∞ (an unknown bound is the worst). */
    private static double key(double bound) {
        return Double.isNaN(bound) ? Double.POSITIVE_INFINITY : bound;
    }

    private static void sample(double v, double t, double[] worst) {
        if (v > worst[0]) {
            worst[0] = v;
            worst[1] = t;
        }
    }

    private static double[] merge(List<Double> ts) {
        double[] sorted = ts.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        List<Double> out = new ArrayList<>();
        for (double t : sorted) {
            if (out.isEmpty() || t - out.get(out.size() - 1) > 1e-3) {
                out.add(t);
            }
        }
        return out.stream().mapToDouble(Double::doubleValue).toArray();
    }
}
