package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.model.Plane;
import org.beziertracer.model.Sphere;

/**
 * Planes and spheres (memoir ch. I 3.3.1–3.3.2) in flat arrays, intersected by formula.
 * Planes: {@code px,py,pz,nx,ny,nz, ax,ay,az, bx,by,bz, scale} (a, b: in-plane axes for the
 * texture coordinates). Spheres: {@code cx,cy,cz,r}. Immutable.
 */
final class AnalyticShapes {
    static final int PLANE_STRIDE = 13, SPHERE_STRIDE = 4;
    final double[] planes;
    final int planeCount;
    final double[] spheres;
    final int sphereCount;

    AnalyticShapes(List<Plane> planeList, List<Sphere> sphereList) {
        planeCount = planeList.size();
        planes = new double[PLANE_STRIDE * planeCount];
        for (int k = 0; k < planeCount; k++) {
            Plane p = planeList.get(k);
            double nx = p.normal().x(), ny = p.normal().y(), nz = p.normal().z();
            // in-plane axes: a ⟂ n from the smallest normal component, b = n × a
            double ax, ay, az;
            if (Math.abs(nx) <= Math.abs(ny) && Math.abs(nx) <= Math.abs(nz)) {
                ax = 0; ay = -nz; az = ny;
            } else if (Math.abs(ny) <= Math.abs(nz)) {
                ax = -nz; ay = 0; az = nx;
            } else {
                ax = -ny; ay = nx; az = 0;
            }
            double inv = 1 / Math.sqrt(ax * ax + ay * ay + az * az);
            ax *= inv; ay *= inv; az *= inv;
            double bx = ny * az - nz * ay, by = nz * ax - nx * az, bz = nx * ay - ny * ax;
            double[] row = {p.point().x(), p.point().y(), p.point().z(), nx, ny, nz, ax, ay, az, bx, by, bz,
                    1 / p.uvScale()};
            System.arraycopy(row, 0, planes, PLANE_STRIDE * k, PLANE_STRIDE);
        }
        sphereCount = sphereList.size();
        spheres = new double[SPHERE_STRIDE * sphereCount];
        for (int k = 0; k < sphereCount; k++) {
            Sphere s = sphereList.get(k);
            spheres[4 * k] = s.center().x();
            spheres[4 * k + 1] = s.center().y();
            spheres[4 * k + 2] = s.center().z();
            spheres[4 * k + 3] = s.radius();
        }
    }

    /** Ray parameter of the plane hit, or NaN when parallel. */
    double planeT(int k, TraceContext c) {
        int o = PLANE_STRIDE * k;
        double denom = planes[o + 3] * c.dx + planes[o + 4] * c.dy + planes[o + 5] * c.dz;
        if (denom == 0) {
            return Double.NaN;
        }
        return (planes[o + 3] * (planes[o] - c.ox) + planes[o + 4] * (planes[o + 1] - c.oy)
                + planes[o + 5] * (planes[o + 2] - c.oz)) / denom;
    }

    /** Nearest sphere hit parameter in (tMin, tMax), or NaN. Numerically careful quadratic. */
    double sphereT(int k, TraceContext c, double tMin, double tMax) {
        int o = SPHERE_STRIDE * k;
        double fx = c.ox - spheres[o], fy = c.oy - spheres[o + 1], fz = c.oz - spheres[o + 2];
        double r = spheres[o + 3];
        double a = c.dx * c.dx + c.dy * c.dy + c.dz * c.dz;
        double b = fx * c.dx + fy * c.dy + fz * c.dz; // half b
        // discriminant via |f - (f·d̂)d̂|² for accuracy (Haines et al., Ray Tracing Gems ch. 7)
        double proj = b / a;
        double lx = fx - proj * c.dx, ly = fy - proj * c.dy, lz = fz - proj * c.dz;
        double disc = r * r - (lx * lx + ly * ly + lz * lz);
        if (disc < 0) {
            return Double.NaN;
        }
        double q = -b - Math.copySign(Math.sqrt(a * disc), b);
        double ff = fx * fx + fy * fy + fz * fz - r * r;
        double t0 = q / a, t1 = q != 0 ? ff / q : t0;
        if (t0 > t1) {
            double tmp = t0; t0 = t1; t1 = tmp;
        }
        if (t0 > tMin && t0 < tMax) return t0;
        if (t1 > tMin && t1 < tMax) return t1;
        return Double.NaN;
    }

    void planePoint(int k, Hit hit, TraceContext c, SurfacePoint sp) {
        int o = PLANE_STRIDE * k;
        sp.px = c.ox + hit.t * c.dx; sp.py = c.oy + hit.t * c.dy; sp.pz = c.oz + hit.t * c.dz;
        sp.nx = planes[o + 3]; sp.ny = planes[o + 4]; sp.nz = planes[o + 5];
        sp.dpdux = planes[o + 6]; sp.dpduy = planes[o + 7]; sp.dpduz = planes[o + 8];
        sp.dpdvx = planes[o + 9]; sp.dpdvy = planes[o + 10]; sp.dpdvz = planes[o + 11];
    }

    /** Texture coordinates of a plane hit, in plane units / uvScale. */
    void planeUv(int k, double px, double py, double pz, Hit hit) {
        int o = PLANE_STRIDE * k;
        double qx = px - planes[o], qy = py - planes[o + 1], qz = pz - planes[o + 2];
        hit.u = (qx * planes[o + 6] + qy * planes[o + 7] + qz * planes[o + 8]) * planes[o + 12];
        hit.v = (qx * planes[o + 9] + qy * planes[o + 10] + qz * planes[o + 11]) * planes[o + 12];
    }

    void spherePoint(int k, Hit hit, TraceContext c, SurfacePoint sp) {
        int o = SPHERE_STRIDE * k;
        sp.px = c.ox + hit.t * c.dx; sp.py = c.oy + hit.t * c.dy; sp.pz = c.oz + hit.t * c.dz;
        double r = spheres[o + 3];
        double nx = (sp.px - spheres[o]) / r, ny = (sp.py - spheres[o + 1]) / r, nz = (sp.pz - spheres[o + 2]) / r;
        double inv = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz);
        sp.nx = nx * inv; sp.ny = ny * inv; sp.nz = nz * inv;
        // dp/du around z (phi), dp/dv along the meridian (theta)
        double phi = 2 * Math.PI;
        sp.dpdux = -phi * r * sp.ny; sp.dpduy = phi * r * sp.nx; sp.dpduz = 0;
        double rho = Math.sqrt(sp.nx * sp.nx + sp.ny * sp.ny);
        double cosPhi = rho > 0 ? sp.nx / rho : 1, sinPhi = rho > 0 ? sp.ny / rho : 0;
        sp.dpdvx = Math.PI * r * sp.nz * cosPhi; sp.dpdvy = Math.PI * r * sp.nz * sinPhi; sp.dpdvz = -Math.PI * r * rho;
    }

    /** Spherical texture coordinates: u = longitude / 2π, v = colatitude / π. */
    void sphereUv(int k, double px, double py, double pz, Hit hit) {
        int o = SPHERE_STRIDE * k;
        double r = spheres[o + 3];
        double nx = (px - spheres[o]) / r, ny = (py - spheres[o + 1]) / r, nz = (pz - spheres[o + 2]) / r;
        double u = Math.atan2(ny, nx) / (2 * Math.PI);
        hit.u = u < 0 ? u + 1 : u;
        hit.v = Math.acos(Math.max(-1, Math.min(1, nz))) / Math.PI;
    }
}
