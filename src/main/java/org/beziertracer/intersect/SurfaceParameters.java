package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * A patch's own parameters {@code (s,t) ∈ [0,1]²} and its surface's {@code (u,v)}: a piece of a
 * free-form surface covers {@code [u0,u1]×[v0,v1]} of it ({@link SubPatchTable#patchDomain}), and
 * hits report {@code (u0 + s(u1−u0), v0 + t(v1−v0))}, the surface's own parameters (for a
 * B-spline, its knot range). For a plain patch ({@code [0,1]²}) nothing is computed, so its hits
 * stay bit for bit what the solvers found.
 */
final class SurfaceParameters {
    private SurfaceParameters() {}

    /** True when patch {@code k} covers exactly {@code [0,1]²}. */
    static boolean unit(SubPatchTable tab, int k) {
        double[] d = tab.patchDomain;
        int o = 4 * k;
        return d[o] == 0 && d[o + 1] == 1 && d[o + 2] == 0 && d[o + 3] == 1;
    }

    /** Surface u of patch {@code k}'s own parameter {@code s}. */
    static double u(SubPatchTable tab, int k, double s) {
        double[] d = tab.patchDomain;
        return d[4 * k] + (d[4 * k + 1] - d[4 * k]) * s;
    }

    /** Surface v of patch {@code k}'s own parameter {@code t}. */
    static double v(SubPatchTable tab, int k, double t) {
        double[] d = tab.patchDomain;
        return d[4 * k + 2] + (d[4 * k + 3] - d[4 * k + 2]) * t;
    }

    /** Patch {@code k}'s own parameter of surface {@code u} (the inverse of {@link #u}). */
    static double s(SubPatchTable tab, int k, double u) {
        double[] d = tab.patchDomain;
        return (u - d[4 * k]) / (d[4 * k + 1] - d[4 * k]);
    }

    /** Patch {@code k}'s own parameter of surface {@code v}. */
    static double t(SubPatchTable tab, int k, double v) {
        double[] d = tab.patchDomain;
        return (v - d[4 * k + 2]) / (d[4 * k + 3] - d[4 * k + 2]);
    }

    /** Turns a patch hit's own parameters into its surface's, unless the patch is plain. */
    static void toSurface(SubPatchTable tab, Hit hit) {
        int k = hit.index;
        if (!unit(tab, k)) {
            hit.u = u(tab, k, hit.u);
            hit.v = v(tab, k, hit.v);
        }
    }
}
