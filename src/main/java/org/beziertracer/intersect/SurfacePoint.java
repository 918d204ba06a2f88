package org.beziertracer.intersect;

/**
 * The geometry at a hit, evaluated once for the final hit: position, parametric derivatives and
 * the unit normal {@code dpdu × dpdv} (not flipped toward the ray; for planes and spheres the
 * outward normal). Mutable, one per thread.
 */
public final class SurfacePoint {
    public double px, py, pz;
    public double dpdux, dpduy, dpduz;
    public double dpdvx, dpdvy, dpdvz;
    public double nx, ny, nz;
    public double u, v;
    public int kind, index;
}
