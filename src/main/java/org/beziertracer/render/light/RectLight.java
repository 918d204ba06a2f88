package org.beziertracer.render.light;

/**
 * A parallelogram area light {@code corner + s·edge1 + t·edge2}, {@code s, t ∈ [0,1]}, emitting
 * uniform radiance {@code L} on the side of {@code edge1 × edge2}, sampled uniformly by area and
 * converted to solid angle: {@code pdf = d² / (A |cosθ_light|)} (pbrt-v4 §6.5.1; Veach 1997 §8.2).
 */
public final class RectLight implements Light {
    private final double ox, oy, oz, e1x, e1y, e1z, e2x, e2y, e2z, nx, ny, nz, area, lr, lg, lb;
    /** The dual basis of the edges in their plane: s = (p − corner)·a1, t = (p − corner)·a2. */
    private final double a1x, a1y, a1z, a2x, a2y, a2z;

    public RectLight(double[] corner, double[] edge1, double[] edge2, double lr, double lg, double lb) {
        ox = corner[0]; oy = corner[1]; oz = corner[2];
        e1x = edge1[0]; e1y = edge1[1]; e1z = edge1[2];
        e2x = edge2[0]; e2y = edge2[1]; e2z = edge2[2];
        double cx = e1y * e2z - e1z * e2y, cy = e1z * e2x - e1x * e2z, cz = e1x * e2y - e1y * e2x;
        area = Math.sqrt(cx * cx + cy * cy + cz * cz);
        if (!(area > 0) || !Double.isFinite(area) || !Double.isFinite(ox + oy + oz)) {
            throw new IllegalArgumentException("a rect light needs a finite corner and two finite edges that are not parallel");
        }
        if (!(lr >= 0 && lg >= 0 && lb >= 0) || !Double.isFinite(lr + lg + lb)) {
            throw new IllegalArgumentException("a light's radiance must be finite and >= 0");
        }
        nx = cx / area; ny = cy / area; nz = cz / area;
        this.lr = lr; this.lg = lg; this.lb = lb;
        // dual basis: a1 = (e2 × n) / A, a2 = (n × e1) / A
        a1x = (e2y * nz - e2z * ny) / area; a1y = (e2z * nx - e2x * nz) / area; a1z = (e2x * ny - e2y * nx) / area;
        a2x = (ny * e1z - nz * e1y) / area; a2y = (nz * e1x - nx * e1z) / area; a2z = (nx * e1y - ny * e1x) / area;
    }

    public double area() { return area; }

    @Override
    public boolean sample(double px, double py, double pz, double u1, double u2, LightSample out) {
        double qx = ox + u1 * e1x + u2 * e2x, qy = oy + u1 * e1y + u2 * e2y, qz = oz + u1 * e1z + u2 * e2z;
        double dx = qx - px, dy = qy - py, dz = qz - pz;
        double d2 = dx * dx + dy * dy + dz * dz;
        if (!(d2 > 0)) {
            return false;
        }
        double d = Math.sqrt(d2);
        double wx = dx / d, wy = dy / d, wz = dz / d;
        double cosLight = -(wx * nx + wy * ny + wz * nz);
        if (cosLight <= 0) {
            return false; // the back of the light
        }
        out.set(wx, wy, wz, d, lr, lg, lb, d2 / (area * cosLight), false);
        return true;
    }

    @Override
    public double pdf(double px, double py, double pz, double wx, double wy, double wz) {
        double t = planeT(px, py, pz, wx, wy, wz);
        if (!(t < Double.POSITIVE_INFINITY)) {
            return 0;
        }
        double cosLight = -(wx * nx + wy * ny + wz * nz);
        return t * t / (area * cosLight);
    }

    @Override
    public double hit(double px, double py, double pz, double wx, double wy, double wz, double[] le) {
        double t = planeT(px, py, pz, wx, wy, wz);
        if (t < Double.POSITIVE_INFINITY) {
            le[0] = lr; le[1] = lg; le[2] = lb;
        }
        return t;
    }

    /** Where the unit ray meets the front of the parallelogram; +∞ when it misses or meets the back. */
    private double planeT(double px, double py, double pz, double wx, double wy, double wz) {
        double denom = wx * nx + wy * ny + wz * nz;
        if (!(denom < 0)) {
            return Double.POSITIVE_INFINITY;
        }
        double t = ((ox - px) * nx + (oy - py) * ny + (oz - pz) * nz) / denom;
        if (!(t > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        double hx = px + t * wx - ox, hy = py + t * wy - oy, hz = pz + t * wz - oz;
        double s = hx * a1x + hy * a1y + hz * a1z, u = hx * a2x + hy * a2y + hz * a2z;
        return s >= 0 && s <= 1 && u >= 0 && u <= 1 ? t : Double.POSITIVE_INFINITY;
    }
}
