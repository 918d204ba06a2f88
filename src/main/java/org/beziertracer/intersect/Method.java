package org.beziertracer.intersect;

import java.util.Locale;

/** The ray–patch solvers. */
public enum Method {
    /** Bézier clipping (Nishita, Sederberg, Kakimoto 1990): exact, the default. */
    CLIPPING,
    /** Newton iteration from the leaf's parameter-box centre (memoir ch. I 3.3.3.3). */
    NEWTON,
    /** Recursive subdivision, then the control mesh as triangles (memoir ch. I 3.3.3.1): approximate. */
    SUBDIVISION;

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
