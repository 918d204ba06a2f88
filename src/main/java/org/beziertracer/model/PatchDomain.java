package org.beziertracer.model;

/**
 * The part {@code [u0,u1] × [v0,v1]} of a free-form surface's parameter domain that a Bézier
 * patch covers, and the surface's trim region (null when untrimmed). The patch's own parameters
 * {@code (s,t) ∈ [0,1]²} map to {@code (u0 + s(u1−u0), v0 + t(v1−v0))}; hits report those
 * surface parameters, and the trim curves live in them.
 */
public record PatchDomain(double u0, double u1, double v0, double v1, TrimRegion trim) {

    /** The unit square, untrimmed: what a patch without a domain has. */
    public static final PatchDomain UNIT = new PatchDomain(0, 1, 0, 1, null);

    public PatchDomain {
        if (!(Double.isFinite(u0) && Double.isFinite(u1) && Double.isFinite(v0) && Double.isFinite(v1)
                && u0 < u1 && v0 < v1)) {
            throw new IllegalArgumentException("a patch domain needs finite u0 < u1 and v0 < v1, got [" + u0 + ","
                    + u1 + "]x[" + v0 + "," + v1 + "]");
        }
    }

    /** True for {@code [0,1]²} without trimming, which behaves exactly like no domain at all. */
    public boolean isUnit() {
        return trim == null && u0 == 0 && u1 == 1 && v0 == 0 && v1 == 1;
    }

    /** The same box with another trim region. */
    public PatchDomain withTrim(TrimRegion region) {
        return new PatchDomain(u0, u1, v0, v1, region);
    }
}
