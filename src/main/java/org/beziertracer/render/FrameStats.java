package org.beziertracer.render;

/**
 * Ray counts, work counts and time of one render (a generation), cumulative up to the pass reported.
 *
 * @param primaryRays   camera rays
 * @param shadowRays    shadow (any-hit) rays
 * @param secondaryRays reflected and refracted rays
 * @param millis        wall-clock time since the render started
 * @param work          what the intersector did for those rays
 * @param analysisLow, analysisHigh the ends of a curvature view's colour scale ({@link AnalysisRange}),
 *                      the legend of the picture; 0 and 1 for the other views
 */
public record FrameStats(long primaryRays, long shadowRays, long secondaryRays, double millis, Work work,
                         double analysisLow, double analysisHigh) {

    /** Stats of a view without a colour scale. */
    public FrameStats(long primaryRays, long shadowRays, long secondaryRays, double millis, Work work) {
        this(primaryRays, shadowRays, secondaryRays, millis, work, 0, 1);
    }

    /**
     * The intersector's work: leaf-solver calls, Bézier clipping steps and patch evaluations (with
     * first derivatives). On one thread they repeat exactly from run to run, where times on a shared
     * machine do not, so a change's effect can be counted; on several threads a little of the work
     * (which proofs a thread skips after they failed for it lately) depends on how the tiles fell.
     * {@code laneEvaluations}: those of the evaluations made for several lanes of a ray batch at
     * once (SIMD registers with the vector kernel; the same count with either kernel).
     */
    public record Work(long solverCalls, long clipSteps, long evaluations, long laneEvaluations) {}

    public long totalRays() { return primaryRays + shadowRays + secondaryRays; }

    /** Millions of rays (all kinds) per second of wall-clock time. */
    public double mraysPerSecond() { return millis > 0 ? totalRays() / (millis * 1e3) : 0; }
}
