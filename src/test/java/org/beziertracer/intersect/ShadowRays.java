package org.beziertracer.intersect;

import java.util.Random;

/** Shadow rays for the tests: the side of a hit a ray arrived on, and random directions leaving it. */
final class ShadowRays {
    private ShadowRays() {}

    /** A shadow ray leaving hit {@code from} (shaded into the caller's surface point) from {@code o} along {@code l}, up to {@code far}. */
    record ShadowRay(Hit from, double nx, double ny, double nz, double ox, double oy, double oz, double lx, double ly,
                     double lz, double far) {}

    /**
     * A camera-like ray from outside {@code si}'s scene toward a random point of its box; at its hit
     * (shaded into {@code sp}, as the renderer keeps it) a shadow ray leaving the point on the side
     * the camera ray came from, offset along the normal by 10⁻⁶ of the scene as the renderer does,
     * in a {@link #leaving} direction, reaching three scene sizes; null when the camera ray misses.
     */
    static ShadowRay atRandomHit(SceneIntersector si, TraceContext ctx, Random rnd, boolean grazing, double lift,
                                 SurfacePoint sp) {
        var b = si.scene().controlBounds();
        double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
        double tx = b.minX() + rnd.nextDouble() * (b.maxX() - b.minX());
        double ty = b.minY() + rnd.nextDouble() * (b.maxY() - b.minY());
        double tz = b.minZ() + rnd.nextDouble() * (b.maxZ() - b.minZ());
        return atHit(si, ctx, rnd, tx, ty, tz, dx, dy, dz, grazing, lift, sp);
    }

    /** As {@link #atRandomHit}, the camera-like ray aimed at {@code t} along {@code d}. */
    static ShadowRay atHit(SceneIntersector si, TraceContext ctx, Random rnd, double tx, double ty, double tz,
                           double dx, double dy, double dz, boolean grazing, double lift, SurfacePoint sp) {
        double size = si.scene().controlBounds().diagonal(), eps = 1e-6 * size;
        Hit hit = new Hit();
        if (!si.closestHit(ctx, tx - 2 * size * dx, ty - 2 * size * dy, tz - 2 * size * dz, dx, dy, dz, 0,
                Double.POSITIVE_INFINITY, hit)) {
            return null;
        }
        si.surfacePoint(ctx, hit, sp);
        double[] n = facing(sp, dx, dy, dz);
        double[] l = leaving(rnd, n, grazing, lift);
        return new ShadowRay(hit, n[0], n[1], n[2], sp.px + eps * n[0], sp.py + eps * n[1], sp.pz + eps * n[2],
                l[0], l[1], l[2], 3 * size / Math.sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]));
    }

    /** The unit normal at {@code sp}, turned toward the side the ray {@code d} arrived from. */
    static double[] facing(SurfacePoint sp, double dx, double dy, double dz) {
        double sign = sp.nx * dx + sp.ny * dy + sp.nz * dz > 0 ? -1 : 1;
        return new double[] {sign * sp.nx, sign * sp.ny, sign * sp.nz};
    }

    /**
     * A random direction on the side of the unit normal {@code n}: Gaussian, or, when
     * {@code grazing}, at most about 5° above the tangent plane; lifted by {@code lift} times its
     * tangential length in any case.
     */
    static double[] leaving(Random rnd, double[] n, boolean grazing, double lift) {
        double lx = rnd.nextGaussian(), ly = rnd.nextGaussian(), lz = rnd.nextGaussian();
        double along = lx * n[0] + ly * n[1] + lz * n[2];
        lx -= along * n[0];
        ly -= along * n[1];
        lz -= along * n[2];
        double side = Math.sqrt(lx * lx + ly * ly + lz * lz);
        double up = (grazing ? 0.09 * rnd.nextDouble() * side : Math.abs(along)) + lift * side;
        return new double[] {lx + up * n[0], ly + up * n[1], lz + up * n[2]};
    }
}
