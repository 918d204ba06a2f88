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

    /** Copies every field of {@code o}. */
    public void set(SurfacePoint o) {
        px = o.px; py = o.py; pz = o.pz;
        dpdux = o.dpdux; dpduy = o.dpduy; dpduz = o.dpduz;
        dpdvx = o.dpdvx; dpdvy = o.dpdvy; dpdvz = o.dpdvz;
        nx = o.nx; ny = o.ny; nz = o.nz;
        u = o.u; v = o.v;
        kind = o.kind; index = o.index;
    }
}
