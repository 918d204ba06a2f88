package org.beziertracer.geometry;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;

/**
 * Object-level conveniences over {@link BezierPatch} for set-up code, tools and tests. They
 * allocate (a net copy, scratch, the result); the hot path uses {@link DeCasteljau} and
 * {@link PatchNormals} directly on flat arrays.
 */
public final class Patches {

    private Patches() {}

    /** {@code S(u,v)}. */
    public static Vec3 evaluate(BezierPatch p, double u, double v) {
        double[] out = new double[3];
        DeCasteljau.evaluate(p.copyNet(), 0, p.degreeU(), p.degreeV(), 3, u, v, out, 0,
                new double[DeCasteljau.SCRATCH_LENGTH]);
        return new Vec3(out[0], out[1], out[2]);
    }

    /** {@code ∂S/∂u} at {@code (u,v)}. */
    public static Vec3 dpdu(BezierPatch p, double u, double v) {
        double[] out = derivatives(p, u, v);
        return new Vec3(out[3], out[4], out[5]);
    }

    /** {@code ∂S/∂v} at {@code (u,v)}. */
    public static Vec3 dpdv(BezierPatch p, double u, double v) {
        double[] out = derivatives(p, u, v);
        return new Vec3(out[6], out[7], out[8]);
    }

    /** Unit normal with the degenerate-point fallback of {@link PatchNormals}. */
    public static Vec3 normal(BezierPatch p, double u, double v) {
        double[] out = new double[3];
        PatchNormals.unitNormal(p.copyNet(), 0, p.degreeU(), p.degreeV(), u, v, out, 0,
                new double[DeCasteljau.SCRATCH_LENGTH]);
        return new Vec3(out[0], out[1], out[2]);
    }

    /** The halves {@code [0,t]} and {@code [t,1]} in u, each reparametrised to {@code [0,1]}. */
    public static BezierPatch[] splitU(BezierPatch p, double t) {
        double[] src = p.copyNet(), lo = new double[src.length], hi = new double[src.length];
        DeCasteljau.splitU(src, 0, p.degreeU(), p.degreeV(), 3, t, lo, 0, hi, 0);
        return new BezierPatch[] {new BezierPatch(p.degreeU(), p.degreeV(), lo),
                new BezierPatch(p.degreeU(), p.degreeV(), hi)};
    }

    /** The halves {@code [0,t]} and {@code [t,1]} in v, each reparametrised to {@code [0,1]}. */
    public static BezierPatch[] splitV(BezierPatch p, double t) {
        double[] src = p.copyNet(), lo = new double[src.length], hi = new double[src.length];
        DeCasteljau.splitV(src, 0, p.degreeU(), p.degreeV(), 3, t, lo, 0, hi, 0);
        return new BezierPatch[] {new BezierPatch(p.degreeU(), p.degreeV(), lo),
                new BezierPatch(p.degreeU(), p.degreeV(), hi)};
    }

    /** The sub-patch over {@code [u0,u1]×[v0,v1]}, reparametrised to {@code [0,1]²}. */
    public static BezierPatch subPatch(BezierPatch p, double u0, double u1, double v0, double v1) {
        double[] net = p.copyNet();
        DeCasteljau.subPatch(net, 0, p.degreeU(), p.degreeV(), 3, u0, u1, v0, v1, net, 0);
        return new BezierPatch(p.degreeU(), p.degreeV(), net);
    }

    /** Flatness as in {@link NetMeasures#flatness(double[], int, int, int)}. */
    public static double flatness(BezierPatch p) {
        return NetMeasures.flatness(p.copyNet(), 0, p.degreeU(), p.degreeV());
    }

    private static double[] derivatives(BezierPatch p, double u, double v) {
        double[] out = new double[9];
        DeCasteljau.evaluateWithDerivatives(p.copyNet(), 0, p.degreeU(), p.degreeV(), u, v, out,
                new double[DeCasteljau.SCRATCH_LENGTH]);
        return out;
    }
}
