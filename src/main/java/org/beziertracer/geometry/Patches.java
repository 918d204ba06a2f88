package org.beziertracer.geometry;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;

/**
 * Object-level conveniences over {@link BezierPatch} for set-up code, tools and tests. They
 * allocate (a net copy, scratch, the result); the hot path uses {@link DeCasteljau},
 * {@link RationalDeCasteljau} and {@link PatchNormals} directly on flat arrays. Rational patches
 * are handled through their homogeneous nets; a split or sub-patch keeps the weights and, for a
 * patch with a {@link PatchDomain}, maps it to the part it covers (the origin is dropped; a plain
 * patch gives plain pieces).
 */
public final class Patches {

    private Patches() {}

    /** {@code S(u,v)}. */
    public static Vec3 evaluate(BezierPatch p, double u, double v) {
        double[] out = new double[3];
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        if (p.isRational()) {
            RationalDeCasteljau.evaluate(homogeneousNet(p), 0, p.degreeU(), p.degreeV(), u, v, out, 0, scratch);
        } else {
            DeCasteljau.evaluate(p.copyNet(), 0, p.degreeU(), p.degreeV(), 3, u, v, out, 0, scratch);
        }
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
        PatchNormals.unitNormal(workingNet(p), 0, p.degreeU(), p.degreeV(), dim(p), u, v, out, 0,
                new double[DeCasteljau.SCRATCH_LENGTH]);
        return new Vec3(out[0], out[1], out[2]);
    }

    /** The halves {@code [0,t]} and {@code [t,1]} in u, each reparametrised to {@code [0,1]}. */
    public static BezierPatch[] splitU(BezierPatch p, double t) {
        double[] src = workingNet(p), lo = new double[src.length], hi = new double[src.length];
        DeCasteljau.splitU(src, 0, p.degreeU(), p.degreeV(), dim(p), t, lo, 0, hi, 0);
        return new BezierPatch[] {piece(p, lo, 0, t, 0, 1), piece(p, hi, t, 1, 0, 1)};
    }

    /** The halves {@code [0,t]} and {@code [t,1]} in v, each reparametrised to {@code [0,1]}. */
    public static BezierPatch[] splitV(BezierPatch p, double t) {
        double[] src = workingNet(p), lo = new double[src.length], hi = new double[src.length];
        DeCasteljau.splitV(src, 0, p.degreeU(), p.degreeV(), dim(p), t, lo, 0, hi, 0);
        return new BezierPatch[] {piece(p, lo, 0, 1, 0, t), piece(p, hi, 0, 1, t, 1)};
    }

    /** The sub-patch over {@code [u0,u1]×[v0,v1]}, reparametrised to {@code [0,1]²}. */
    public static BezierPatch subPatch(BezierPatch p, double u0, double u1, double v0, double v1) {
        double[] net = workingNet(p);
        DeCasteljau.subPatch(net, 0, p.degreeU(), p.degreeV(), dim(p), u0, u1, v0, v1, net, 0);
        return piece(p, net, u0, u1, v0, v1);
    }

    /** Flatness as in {@link NetMeasures#flatness(double[], int, int, int)} (of the Euclidean net). */
    public static double flatness(BezierPatch p) {
        return NetMeasures.flatness(p.copyNet(), 0, p.degreeU(), p.degreeV());
    }

    /** The homogeneous net {@code (w·x, w·y, w·z, w)} of the patch (weights 1 when polynomial). */
    public static double[] homogeneousNet(BezierPatch p) {
        int count = p.pointCount();
        double[] w = p.weights();
        if (w == null) {
            w = new double[count];
            java.util.Arrays.fill(w, 1);
        }
        double[] h = new double[4 * count];
        RationalDeCasteljau.toHomogeneous(p.copyNet(), 0, w, 0, count, h, 0);
        return h;
    }

    /** 4 for a rational patch (homogeneous net), else 3. */
    static int dim(BezierPatch p) {
        return p.isRational() ? 4 : 3;
    }

    /** The net the kernel works on: homogeneous for a rational patch, else the Euclidean net. */
    static double[] workingNet(BezierPatch p) {
        return p.isRational() ? homogeneousNet(p) : p.copyNet();
    }

    /** A patch from a working net, covering {@code [a,b]×[c,d]} of {@code p}'s own parameters. */
    private static BezierPatch piece(BezierPatch p, double[] net, double a, double b, double c, double d) {
        if (p.domain().isUnit()) {
            return BezierPatch.fromNet(p.degreeU(), p.degreeV(), net, dim(p), null, null);
        }
        PatchDomain dom = p.domain();
        double du = dom.u1() - dom.u0(), dv = dom.v1() - dom.v0();
        PatchDomain sub = new PatchDomain(dom.u0() + a * du, dom.u0() + b * du, dom.v0() + c * dv,
                dom.v0() + d * dv, dom.trim());
        return BezierPatch.fromNet(p.degreeU(), p.degreeV(), net, dim(p), sub, null);
    }

    private static double[] derivatives(BezierPatch p, double u, double v) {
        double[] out = new double[9];
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        if (p.isRational()) {
            RationalDeCasteljau.evaluateWithDerivatives(homogeneousNet(p), 0, p.degreeU(), p.degreeV(), u, v, out, 0,
                    scratch, 0);
        } else {
            DeCasteljau.evaluateWithDerivatives(p.copyNet(), 0, p.degreeU(), p.degreeV(), u, v, out, scratch);
        }
        return out;
    }
}
