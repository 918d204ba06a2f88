package org.beziertracer.intersect;

import java.util.Locale;

/** The ray–patch solvers, each with the {@link PatchLeaves} that run it at the BVH leaves. */
public enum Method {
    /** Bézier clipping (Nishita, Sederberg, Kakimoto 1990): exact, the default. */
    CLIPPING(ClippingLeaves::new),
    /** Newton iteration from the leaf's parameter-box centre (memoir ch. I 3.3.3.3). */
    NEWTON(NewtonLeaves::new),
    /** Recursive subdivision, then the control mesh as triangles (memoir ch. I 3.3.3.1): approximate. */
    SUBDIVISION(SubdivisionLeaves::new);

    /** Makes this method's leaves over a sub-patch table. */
    final PatchLeaves.Factory leaves;

    Method(PatchLeaves.Factory leaves) {
        this.leaves = leaves;
    }

    /** Parses {@code clipping|newton|subdivision} (case-insensitive) with a one-line error. */
    public static Method parse(String s) {
        for (Method m : values()) {
            if (m.name().equalsIgnoreCase(s.trim())) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown method '" + s + "': expected clipping, newton or subdivision");
    }

    public String label() { return name().toLowerCase(Locale.ROOT); }
}
