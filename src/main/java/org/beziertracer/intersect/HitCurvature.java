package org.beziertracer.intersect;

import org.beziertracer.geometry.SurfaceCurvature;

/**
 * The curvature of the shapes that are not patches, in the layout of {@link SurfaceCurvature}:
 * a plane or a flat triangle has none; a sphere of radius r bends toward its centre, against its
 * outward normal, by {@code 1/r} in every direction ({@code k1 = k2 = −1/r}, {@code K = 1/r²}).
 * The principal directions of such umbilic points are any orthonormal pair across the normal.
 */
final class HitCurvature {
    private HitCurvature() {}

    /** An umbilic point of curvature {@code k} in every direction, normal {@code (nx, ny, nz)} (unit). */
    static void umbilic(double k, double nx, double ny, double nz, double[] out) {
        // d1: the axis least along n, made perpendicular to it (Gram–Schmidt)
        double ax = 0, ay = 0, az = 0;
        if (Math.abs(nx) <= Math.abs(ny) && Math.abs(nx) <= Math.abs(nz)) {
            ax = 1;
        } else if (Math.abs(ny) <= Math.abs(nz)) {
            ay = 1;
        } else {
            az = 1;
        }
        double dot = ax * nx + ay * ny + az * nz;
        double dx = ax - dot * nx, dy = ay - dot * ny, dz = az - dot * nz;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        SurfaceCurvature.store(k * k, k, k, k, nx, ny, nz, dx / len, dy / len, dz / len, out);
    }
}
