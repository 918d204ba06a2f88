package org.beziertracer.render;

import java.util.Locale;

/** How radiance is computed: the memoir's Whitted tracer (the default) or the path tracer. */
public enum Integrator {
    WHITTED, PATH;

    public String label() { return name().toLowerCase(Locale.ROOT); }

    public static Integrator parse(String s) {
        String v = s == null ? "" : s.trim().toLowerCase(Locale.ROOT);
        for (Integrator i : values()) {
            if (i.label().equals(v)) {
                return i;
            }
        }
        throw new IllegalArgumentException("unknown integrator '" + s + "': expected whitted or path");
    }
}
