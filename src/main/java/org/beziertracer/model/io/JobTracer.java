package org.beziertracer.model.io;

import java.util.Locale;

/**
 * The integrator of a render job and the path tracer's settings, as a job file's {@code settings} names
 * them ({@code integrator}, {@code pathDepth}, {@code clamp}, {@code exposure}; {@code docs/jobs.md}).
 * Each value is null when the job does not set it (the {@code render} command's default, or its option,
 * applies). Immutable; checked when built, with the same ranges as {@code render}'s options.
 *
 * @param integrator {@code "whitted"} or {@code "path"} (lower case), or null
 * @param pathDepth  the most bounces of a path, 1..{@value #MAX_PATH_DEPTH}, or null
 * @param clamp      the firefly clamp, finite and {@code >= 0} (0 = off), or null
 * @param exposure   stops before the path tracer's tone curve, -{@value #MAX_EXPOSURE}..{@value #MAX_EXPOSURE},
 *                   or null
 */
public record JobTracer(String integrator, Integer pathDepth, Double clamp, Double exposure) {

    /** Nothing set: {@code render}'s defaults (the Whitted tracer). */
    public static final JobTracer NONE = new JobTracer(null, null, null, null);
    /** Most bounces of a path (the path tracer's own limit). */
    public static final int MAX_PATH_DEPTH = 1024;
    /** Largest exposure in stops, either way. */
    public static final int MAX_EXPOSURE = 64;

    public JobTracer {
        if (integrator != null) {
            integrator = integrator.trim().toLowerCase(Locale.ROOT);
            if (!integrator.equals("whitted") && !integrator.equals("path")) {
                throw new IllegalArgumentException("unknown integrator '" + integrator + "': expected whitted or path");
            }
        }
        if (pathDepth != null && (pathDepth < 1 || pathDepth > MAX_PATH_DEPTH)) {
            throw new IllegalArgumentException("the path depth must be 1.." + MAX_PATH_DEPTH + ", got " + pathDepth);
        }
        if (clamp != null && !(clamp >= 0 && Double.isFinite(clamp))) {
            throw new IllegalArgumentException("the clamp must be a finite number >= 0 (0 = off), got " + clamp);
        }
        if (exposure != null && !(Math.abs(exposure) <= MAX_EXPOSURE)) {
            throw new IllegalArgumentException("the exposure must be -" + MAX_EXPOSURE + ".." + MAX_EXPOSURE
                    + " stops, got " + exposure);
        }
        if ((pathDepth != null || clamp != null || exposure != null) && !"path".equals(integrator)) {
            throw new IllegalArgumentException("pathDepth, clamp and exposure need \"integrator\": \"path\"");
        }
    }

    /** True when the job asks for the path tracer. */
    public boolean pathTraced() { return "path".equals(integrator); }
}
