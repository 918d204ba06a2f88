package org.beziertracer.intersect;

import static org.beziertracer.geometry.SurfaceCurvature.D1;
import static org.beziertracer.geometry.SurfaceCurvature.D2;
import static org.beziertracer.geometry.SurfaceCurvature.GAUSSIAN;
import static org.beziertracer.geometry.SurfaceCurvature.K1;
import static org.beziertracer.geometry.SurfaceCurvature.K2;
import static org.beziertracer.geometry.SurfaceCurvature.MEAN;
import static org.beziertracer.geometry.SurfaceCurvature.NORMAL;

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
        out[GAUSSIAN] = k * k;
        out[MEAN] = k;
        out[K1] = k;
        out[K2] = k;
        out[NORMAL] = nx;
        out[NORMAL + 1] = ny;
        out[NORMAL + 2] = nz;
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
        out[D1] = dx / len;
        out[D1 + 1] = dy / len;
        out[D1 + 2] = dz / len;
        out[D2] = ny * out[D1 + 2] - nz * out[D1 + 1];
        out[D2 + 1] = nz * out[D1] - nx * out[D1 + 2];
        out[D2 + 2] = nx * out[D1 + 1] - ny * out[D1];
    }
}
