package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.RationalDeCasteljau;
import org.beziertracer.geometry.SubPatchTable;

/**
 * Newton's start on a leaf from the leaf's own second-order Taylor model: a start nearer the root
 * than the enclosure's parallelogram ({@link NewtonSolver#start}), so Newton on the patch needs
 * fewer evaluations of it. That pays where an evaluation is dear: leaves of patches with more
 * control points than a bicubic (a degree-9 evaluation costs about 0.35 µs, the model's start about
 * 0.04 µs). Bicubic and lower leaves keep the parallelogram start, which is cheaper than the
 * evaluation this would save.
 *
 * <p>Per leaf, {@link #STRIDE} floats in the leaf's own parameters {@code (s, t) ∈ [0,1]²}:
 * the point {@code S}, the first derivatives {@code S_s, S_t} and the second derivatives
 * {@code S_ss, S_st, S_tt} at the leaf's centre (the second by central differences of the first:
 * the model only has to be good, not exact). The start solves, for the ray's two planes,
 * {@code S + S_s·a + S_t·b + ½S_ss·a² + S_st·a·b + ½S_tt·b² = 0} by a few Newton steps on the
 * model from the centre, and is taken when it lands in the leaf; otherwise the parallelogram's
 * start stands. Only the start changes: the root is still Newton's on the patch itself, accepted
 * only where the leaf is proven single-root ({@link BezierClipper#intersect}), so the answer is the
 * same and depends on nothing but the ray and the leaf.
 *
 * <p>Storing a start in each leaf follows M. Geimer and O. Abert, "Interactive ray tracing of
 * trimmed bicubic Bézier surfaces without triangulation", WSCG 2005 (Newton starts kept in the
 * BVH's leaves); a quadratic model instead of a bilinear one is ours. With it, Newton's
 * evaluations a converged single-root leaf went from 2.96 to 2.17 on the degree-9 grid
 * (800×600 frame), from 3.05 to 2.49 at degree 5.
 */
final class LeafQuadratics {
    private LeafQuadratics() {}

    /** Floats a leaf: S, S_s, S_t, S_ss, S_st, S_tt. */
    static final int STRIDE = 18;
    /** Newton steps on the model. */
    static final int MODEL_STEPS = 4;

    /** True when leaves of a degree {@code n}×{@code m} polynomial patch get a model. */
    static boolean worthIt(int n, int m) {
        return (n + 1) * (m + 1) > 16;
    }

    /**
     * The models of {@code table}'s leaves (NaN first float: no model), or null when no leaf gets
     * one (every patch bicubic or smaller, or rational).
     */
    static float[] build(SubPatchTable table) {
        if (!needed(table)) {
            return null;
        }
        return EditedLeafData.built(table, STRIDE, LeafQuadratics::fill);
    }

    /** True when some leaf of {@code table} gets a model. */
    static boolean needed(SubPatchTable table) {
        for (int k = 0; k < table.patchCount(); k++) {
            if (table.patchDim[k] == 3 && worthIt(table.patchDegreeU[k], table.patchDegreeV[k])) {
                return true;
            }
        }
        return false;
    }

    /**
     * The models of {@code after}, an edit of {@code before} in the patches {@code edited}, given
     * {@code before}'s models {@code old}: only the edited patches' leaves are computed
     * ({@link EditedLeafData}); null when no leaf gets one.
     */
    static float[] edited(float[] old, SubPatchTable before, SubPatchTable after, int[] edited) {
        if (!needed(after)) {
            return null;
        }
        return old == null ? build(after) : EditedLeafData.of(old, before, after, edited, STRIDE, LeafQuadratics::fill);
    }

    private static void fill(SubPatchTable tab, float[] out, int from, int to) {
        double[] e = new double[9], plus = new double[9], minus = new double[9];
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        float[] box = tab.boxes;
        for (int s = from; s < to; s++) {
            int k = tab.parent[s], o = STRIDE * s;
            if (tab.patchDim[k] != 3 || !worthIt(tab.patchDegreeU[k], tab.patchDegreeV[k])) {
                out[o] = Float.NaN;
                continue;
            }
            double u0 = box[4 * s], du = box[4 * s + 1] - u0, v0 = box[4 * s + 2], dv = box[4 * s + 3] - v0;
            double uc = u0 + 0.5 * du, vc = v0 + 0.5 * dv, hu = 1e-3 * du, hv = 1e-3 * dv;
            evaluate(tab, k, uc, vc, e, scratch);
            for (int c = 0; c < 3; c++) {
                out[o + c] = (float) e[c];
                out[o + 3 + c] = (float) (e[3 + c] * du);
                out[o + 6 + c] = (float) (e[6 + c] * dv);
            }
            evaluate(tab, k, uc + hu, vc, plus, scratch);
            evaluate(tab, k, uc - hu, vc, minus, scratch);
            for (int c = 0; c < 3; c++) {
                out[o + 9 + c] = (float) ((plus[3 + c] - minus[3 + c]) / (2 * hu) * du * du);
                out[o + 12 + c] = (float) ((plus[6 + c] - minus[6 + c]) / (2 * hu) * du * dv);
            }
            evaluate(tab, k, uc, vc + hv, plus, scratch);
            evaluate(tab, k, uc, vc - hv, minus, scratch);
            for (int c = 0; c < 3; c++) {
                out[o + 15 + c] = (float) ((plus[6 + c] - minus[6 + c]) / (2 * hv) * dv * dv);
            }
        }
    }

    private static void evaluate(SubPatchTable tab, int k, double u, double v, double[] out, double[] scratch) {
        RationalDeCasteljau.pointAndDerivatives(tab.patchNets, tab.patchNetOffset[k], tab.patchDegreeU[k],
                tab.patchDegreeV[k], 3, u, v, out, scratch);
    }

    /** True when leaf {@code s} has a model. */
    static boolean has(float[] models, int s) {
        return !Float.isNaN(models[STRIDE * s]);
    }

    /**
     * Where the current ray of {@code ctx} meets leaf {@code s}'s model, in leaf parameters into
     * {@code ctx.clip[0..1]}; true when that lies in the leaf. Otherwise {@code ctx.clip} is left
     * as it was (the parallelogram's start).
     */
    static boolean start(TraceContext ctx, float[] models, int s) {
        int o = STRIDE * s;
        if (Float.isNaN(models[o])) {
            return false;
        }
        double cx = models[o] - ctx.ox, cy = models[o + 1] - ctx.oy, cz = models[o + 2] - ctx.oz;
        double f0 = ctx.n1x * cx + ctx.n1y * cy + ctx.n1z * cz, g0 = ctx.n2x * cx + ctx.n2y * cy + ctx.n2z * cz;
        double fs = along1(ctx, models, o + 3), gs = along2(ctx, models, o + 3);
        double ft = along1(ctx, models, o + 6), gt = along2(ctx, models, o + 6);
        double fss = along1(ctx, models, o + 9), gss = along2(ctx, models, o + 9);
        double fst = along1(ctx, models, o + 12), gst = along2(ctx, models, o + 12);
        double ftt = along1(ctx, models, o + 15), gtt = along2(ctx, models, o + 15);
        double a = 0, b = 0; // offsets from the leaf's centre
        for (int step = 0; step < MODEL_STEPS; step++) {
            double f = f0 + a * (fs + 0.5 * fss * a + fst * b) + b * (ft + 0.5 * ftt * b);
            double g = g0 + a * (gs + 0.5 * gss * a + gst * b) + b * (gt + 0.5 * gtt * b);
            double j11 = fs + fss * a + fst * b, j12 = ft + fst * a + ftt * b;
            double j21 = gs + gss * a + gst * b, j22 = gt + gst * a + gtt * b;
            double det = j11 * j22 - j12 * j21;
            if (!(Math.abs(det) > 0)) {
                return false;
            }
            a -= (f * j22 - g * j12) / det;
            b -= (g * j11 - f * j21) / det;
        }
        if (!(Math.abs(a) <= 0.5 && Math.abs(b) <= 0.5)) {
            return false;
        }
        ctx.clip[0] = 0.5 + a;
        ctx.clip[1] = 0.5 + b;
        return true;
    }

    private static double along1(TraceContext ctx, float[] m, int i) {
        return ctx.n1x * m[i] + ctx.n1y * m[i + 1] + ctx.n1z * m[i + 2];
    }

    private static double along2(TraceContext ctx, float[] m, int i) {
        return ctx.n2x * m[i] + ctx.n2y * m[i + 1] + ctx.n2z * m[i + 2];
    }
}
