package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * A patch's own parameters {@code (s,t) ∈ [0,1]²} and its surface's {@code (u,v)}: a piece of a
 * free-form surface covers {@code [u0,u1]×[v0,v1]} of it ({@link SubPatchTable#patchDomain}, four
 * doubles per patch), and hits report {@code (u0 + s(u1−u0), v0 + t(v1−v0))}, the surface's own
 * parameters (for a B-spline, its knot range). For a plain patch ({@code [0,1]²}) nothing is
 * computed, so its hits stay bit for bit what the solvers found.
 */
final class SurfaceParameters {
    private SurfaceParameters() {}

    /** True when patch {@code k} covers exactly {@code [0,1]²}. */
    static boolean unit(double[] domain, int k) {
        int o = 4 * k;
        return domain[o] == 0 && domain[o + 1] == 1 && domain[o + 2] == 0 && domain[o + 3] == 1;
    }

    /** Surface u of patch {@code k}'s own parameter {@code s}. */
    static double u(double[] domain, int k, double s) {
        return domain[4 * k] + (domain[4 * k + 1] - domain[4 * k]) * s;
    }

    /** Surface v of patch {@code k}'s own parameter {@code t}. */
    static double v(double[] domain, int k, double t) {
        return domain[4 * k + 2] + (domain[4 * k + 3] - domain[4 * k + 2]) * t;
    }

    /** Patch {@code k}'s own parameter of surface {@code u} (the inverse of {@link #u}). */
    static double s(double[] domain, int k, double u) {
        return (u - domain[4 * k]) / (domain[4 * k + 1] - domain[4 * k]);
    }

    /** Patch {@code k}'s own parameter of surface {@code v}. */
    static double t(double[] domain, int k, double v) {
        return (v - domain[4 * k + 2]) / (domain[4 * k + 3] - domain[4 * k + 2]);
    }

    /** Turns a patch hit's own parameters into its surface's, unless the patch is plain. */
    static void toSurface(double[] domain, Hit hit) {
        int k = hit.index;
        if (!unit(domain, k)) {
            hit.u = u(domain, k, hit.u);
            hit.v = v(domain, k, hit.v);
        }
    }
}
