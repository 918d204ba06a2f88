package org.beziertracer.render;

/**
 * Ray counts and time of one render (a generation), cumulative up to the pass reported.
 *
 * @param primaryRays   camera rays
 * @param shadowRays    shadow (any-hit) rays
 * @param secondaryRays reflected and refracted rays
 * @param millis        wall-clock time since the render started
 */
public record FrameStats(long primaryRays, long shadowRays, long secondaryRays, double millis) {

    public long totalRays() { return primaryRays + shadowRays + secondaryRays; }

    /** Millions of rays (all kinds) per second of wall-clock time. */
    public double mraysPerSecond() { return millis > 0 ? totalRays() / (millis * 1e3) : 0; }
}
