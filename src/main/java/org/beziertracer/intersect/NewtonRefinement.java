package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.LeafCriterion;
import org.beziertracer.geometry.NetMeasures;
import org.beziertracer.geometry.SplitOptions;

/**
 * The Newton method's leaves: refined until Newton converges from the leaf's start (W. Martin,
 * E. Cohen, R. Fish, P. Shirley, "Practical ray tracing of trimmed NURBS surfaces", JGT 5(1),
 * 2000, §2.1: "for Newton to converge both swiftly and reliably, the initial guess must be
 * suitably close to the actual root"; they refine by a curvature heuristic with an empirical
 * constant, we test the convergence itself).
 *
 * <p>A sub-patch is a leaf when, first, it is a leaf of the default split (flat to
 * {@link #FLATNESS} of its size, or {@link #FLAT_DEPTH} halvings deep), and second, Newton as
 * {@link NewtonSolver} runs it — from the start the leaf's parallelogram gives, confined to the
 * leaf's overlapped domain — converges to the aimed point for every probe ray: rays aimed at the
 * points {@code (s,t) ∈ {0.1, 0.5, 0.9}²} of the leaf along the normal and tilted by
 * {@link #TILT_DEGREES} toward ±Su and ±Sv. Where it does not (a twisted bilinear patch that is
 * "flat" by the bilinear measure, the waves of a high-degree patch), the leaf is halved again, up
 * to {@link #MAX_DEPTH} halvings. Points where the normal vanishes (a collapsed edge) are not
 * probed. Newton's iterates map exactly under an affine change of parameters, so the probes run
 * on the sub-patch's own net and parameters.
 *
 * <p>Stateless apart from one scratch context per splitting thread.
 */
final class NewtonRefinement implements LeafCriterion {

    /** Flatness of the default split (fraction of the control-box diagonal), kept as the first test. */
    static final double FLATNESS = 0.05;
    /** Depth of the default split: flatness is not asked for beyond it. */
    static final int FLAT_DEPTH = 6;
    /** Most halvings for the Newton criterion. */
    static final int MAX_DEPTH = 10;
    /** Tilt of the probe rays from the normal. */
    static final double TILT_DEGREES = 60;
    /** Probe points, in the leaf's own parameters. */
    private static final double[] PROBES = {0.1, 0.5, 0.9};
    /** How close (in the leaf's parameters) the probe's root must come back. */
    private static final double AIM = 1e-6;

    /** The Newton method's split options. */
    static final SplitOptions SPLIT = new SplitOptions(true, 1, MAX_DEPTH, new NewtonRefinement());

    private static final ThreadLocal<TraceContext> CONTEXT = ThreadLocal.withInitial(TraceContext::new);

    private NewtonRefinement() {}

    @Override
    public boolean accepts(double[] net, int n, int m, double size, int depth) {
        if (depth < FLAT_DEPTH && NetMeasures.flatness(net, 0, n, m) > FLATNESS * size) {
            return false;
        }
        TraceContext ctx = CONTEXT.get();
        double[] frame = new double[NewtonLeafRecords.STRIDE];
        NewtonLeafRecords.frame(net, 0, n, m, false, frame, 0);
        float[] rec = NewtonLeafRecords.leaf(frame);
        double[] e = new double[9];
        for (double s : PROBES) {
            for (double t : PROBES) {
                DeCasteljau.evaluateWithDerivatives(net, 0, n, m, s, t, e, ctx.scratch);
                for (int dir = 0; dir < 5; dir++) {
                    if (aim(ctx, e, dir, size) && !converges(ctx, net, n, m, rec, s, t, size)) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    /**
     * Sets the probe ray {@code dir} (0: against the normal; 1..4: tilted toward +Su, +Sv, −Su,
     * −Sv) through the point of {@code e} (S, Su, Sv) and returns true; false when the point has
     * no normal or no such tangent (a collapsed edge), so there is nothing to aim along.
     */
    private static boolean aim(TraceContext ctx, double[] e, int dir, double size) {
        double nx = e[4] * e[8] - e[5] * e[7], ny = e[5] * e[6] - e[3] * e[8], nz = e[3] * e[7] - e[4] * e[6];
        double nl = Math.sqrt(nx * nx + ny * ny + nz * nz);
        int tangent = dir == 1 || dir == 3 ? 3 : 6;
        double tl = Math.sqrt(e[tangent] * e[tangent] + e[tangent + 1] * e[tangent + 1] + e[tangent + 2] * e[tangent + 2]);
        if (!(nl > 0) || !(tl > 0)) {
            return false;
        }
        double tilt = dir == 0 ? 0 : Math.toRadians(TILT_DEGREES) * (dir <= 2 ? 1 : -1);
        double c = Math.cos(tilt), w = Math.sin(tilt) / tl;
        double dx = -c * nx / nl + w * e[tangent], dy = -c * ny / nl + w * e[tangent + 1];
        double dz = -c * nz / nl + w * e[tangent + 2];
        ctx.setRay(e[0] - size * dx, e[1] - size * dy, e[2] - size * dz, dx, dy, dz);
        return true;
    }

    /** Newton from the leaf's start for the ray in {@code ctx} comes back to {@code (s,t)}. */
    private static boolean converges(TraceContext ctx, double[] net, int n, int m, float[] rec, double s, double t,
                                     double size) {
        double[] w = ctx.newton;
        NewtonSolver.setDomain(w, 0, 1, 0, 1);
        double tolerance = PatchLeaves.RELATIVE_TOLERANCE * size;
        if (NewtonSolver.start(ctx, rec, 0, 0, Double.POSITIVE_INFINITY, tolerance) == NewtonSolver.MISS) {
            return false;
        }
        return NewtonSolver.iterate(ctx, net, 0, -1, n, m, 3, ctx.clip[0], ctx.clip[1], w, tolerance) == NewtonSolver.CONVERGED
                && Math.abs(ctx.rootU - s) <= AIM && Math.abs(ctx.rootV - t) <= AIM;
    }
}
