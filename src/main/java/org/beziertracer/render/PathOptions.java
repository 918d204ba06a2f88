package org.beziertracer.render;

/**
 * The path tracer's settings.
 *
 * @param integrator     which integrator renders (Whitted by default)
 * @param maxDepth       the most bounces a path makes, 1..{@value #MAX_DEPTH}
 * @param clamp          each sample's colour is scaled down so that no channel exceeds this (fireflies);
 *                       0 = off
 * @param mis            multiple importance sampling of lights and BSDFs (Veach 1997); false: light
 *                       sampling alone for every light it can reach (the emission a BSDF sample meets
 *                       then counts only after a delta bounce)
 * @param rouletteDepth  bounces before Russian roulette may end a path
 */
public record PathOptions(Integrator integrator, int maxDepth, double clamp, boolean mis, int rouletteDepth) {
    public static final int MAX_DEPTH = 1024;

    public PathOptions {
        if (integrator == null) {
            throw new IllegalArgumentException("integrator is required");
        }
        if (maxDepth < 1 || maxDepth > MAX_DEPTH) {
            throw new IllegalArgumentException("path depth must be 1.." + MAX_DEPTH + ", got " + maxDepth);
        }
        if (!(clamp >= 0) || Double.isNaN(clamp)) {
            throw new IllegalArgumentException("clamp must be >= 0 (0 = off), got " + clamp);
        }
        if (rouletteDepth < 0) {
            throw new IllegalArgumentException("roulette depth must be >= 0, got " + rouletteDepth);
        }
    }

    /** Whitted; for the path tracer depth 16, no clamp, MIS on, roulette after 3 bounces. */
    public static PathOptions defaults() { return new PathOptions(Integrator.WHITTED, 16, 0, true, 3); }

    public PathOptions withIntegrator(Integrator i) { return new PathOptions(i, maxDepth, clamp, mis, rouletteDepth); }

    public PathOptions withMaxDepth(int d) { return new PathOptions(integrator, d, clamp, mis, rouletteDepth); }

    public PathOptions withClamp(double c) { return new PathOptions(integrator, maxDepth, c, mis, rouletteDepth); }

    public PathOptions withMis(boolean on) { return new PathOptions(integrator, maxDepth, clamp, on, rouletteDepth); }

    public PathOptions withRouletteDepth(int d) { return new PathOptions(integrator, maxDepth, clamp, mis, d); }
}
