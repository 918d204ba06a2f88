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
 * @param exposure       stops of exposure before the ACES curve ({@link ToneMap}) of the tiles a
 *                       progressive render shows (-64..64; the CLI's {@code --exposure})
 * @param budgetMillis   a time budget: a render stops after the first extra-sample pass that ends
 *                       this long after it started, and reports that pass as its last (0 = none; the
 *                       first sample of every pixel is always traced)
 */
public record PathOptions(Integrator integrator, int maxDepth, double clamp, boolean mis, int rouletteDepth,
                          double exposure, long budgetMillis) {
    public static final int MAX_DEPTH = 1024;
    /** Most stops of {@link #exposure} either way. */
    public static final double MAX_EXPOSURE = 64;

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
        if (!(Math.abs(exposure) <= MAX_EXPOSURE)) {
            throw new IllegalArgumentException("exposure must be -64..64 stops, got " + exposure);
        }
        if (budgetMillis < 0) {
            throw new IllegalArgumentException("time budget must be >= 0 ms (0 = none), got " + budgetMillis);
        }
    }

    /** No exposure, no time budget. */
    public PathOptions(Integrator integrator, int maxDepth, double clamp, boolean mis, int rouletteDepth) {
        this(integrator, maxDepth, clamp, mis, rouletteDepth, 0, 0);
    }

    /** Whitted; for the path tracer depth 16, no clamp, MIS on, roulette after 3 bounces. */
    public static PathOptions defaults() { return new PathOptions(Integrator.WHITTED, 16, 0, true, 3); }

    public PathOptions withIntegrator(Integrator i) {
        return new PathOptions(i, maxDepth, clamp, mis, rouletteDepth, exposure, budgetMillis);
    }

    public PathOptions withMaxDepth(int d) {
        return new PathOptions(integrator, d, clamp, mis, rouletteDepth, exposure, budgetMillis);
    }

    public PathOptions withClamp(double c) {
        return new PathOptions(integrator, maxDepth, c, mis, rouletteDepth, exposure, budgetMillis);
    }

    public PathOptions withMis(boolean on) {
        return new PathOptions(integrator, maxDepth, clamp, on, rouletteDepth, exposure, budgetMillis);
    }

    public PathOptions withRouletteDepth(int d) {
        return new PathOptions(integrator, maxDepth, clamp, mis, d, exposure, budgetMillis);
    }

    /** With {@code ev} stops of exposure for the tiles shown while rendering. */
    public PathOptions withExposure(double ev) {
        return new PathOptions(integrator, maxDepth, clamp, mis, rouletteDepth, ev, budgetMillis);
    }

    /** With a time budget of {@code millis} (0 = none). */
    public PathOptions withBudgetMillis(long millis) {
        return new PathOptions(integrator, maxDepth, clamp, mis, rouletteDepth, exposure, millis);
    }

    /** True when the path tracer renders (not Whitted). */
    public boolean traced() { return integrator == Integrator.PATH; }
}
