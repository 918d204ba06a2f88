package org.beziertracer.geometry;

/**
 * How patches are pre-split into sub-patches.
 *
 * @param enabled            false: one sub-patch per whole patch (the "no sub-patch BVH" mode)
 * @param flatnessTolerance  a sub-patch is flat enough when {@link NetMeasures#flatness} is at
 *                           most this fraction of its control-box diagonal
 * @param maxDepth           cap on the number of successive halvings (so at most
 *                           {@code 2^maxDepth} sub-patches per patch)
 * @param criterion          a further test a flat enough sub-patch must pass to be a leaf (a
 *                           solver's own refinement; {@link LeafCriterion#NONE}: none)
 * @param fine               up to bicubic, split on to the fine tolerance and cap
 *                           ({@link #FINE_FLATNESS}, {@link #FINE_DEPTH}); a scene of more than
 *                           {@link #FINE_PATCHES} patches is split without ({@link #forPatches})
 */
public record SplitOptions(boolean enabled, double flatnessTolerance, int maxDepth, LeafCriterion criterion,
                           boolean fine) {

    public SplitOptions {
        if (!(flatnessTolerance > 0) || !Double.isFinite(flatnessTolerance)) {
            throw new IllegalArgumentException("flatness tolerance must be positive, got " + flatnessTolerance);
        }
        if (maxDepth < 0 || maxDepth > 16) {
            throw new IllegalArgumentException("split depth must be 0..16, got " + maxDepth);
        }
        if (criterion == null) {
            throw new IllegalArgumentException("a leaf criterion is required (LeafCriterion.NONE for none)");
        }
    }

    /** With the fine split up to bicubic (it applies to flatness-only splits, {@link #degreeAware}). */
    public SplitOptions(boolean enabled, double flatnessTolerance, int maxDepth, LeafCriterion criterion) {
        this(enabled, flatnessTolerance, maxDepth, criterion, true);
    }

    /** Splitting by flatness alone (with the fine split up to bicubic). */
    public SplitOptions(boolean enabled, double flatnessTolerance, int maxDepth) {
        this(enabled, flatnessTolerance, maxDepth, LeafCriterion.NONE);
    }

    /**
     * Up to bicubic, a flatness-only split goes on to this fraction of {@link #flatnessTolerance},
     * with {@value #FINE_DEPTH} more halvings allowed ({@link #flatnessFor}, {@link #maxDepthFor}),
     * in scenes of at most {@link #FINE_PATCHES} patches. A flatter leaf is more often proved
     * single-root, and Newton's start from its corners is closer to the root: on the strongly curved
     * bicubic arch (32 leaves at the base tolerance, 142 at the fine one) the clipping searches and
     * Newton's evaluations fall by more than the deeper traversal costs (one thread, min of 14
     * frames, alternating: 182–183 against 140–151 ms; the teapot, 1,566 leaves against 6,468:
     * 151–153 against 144–149 ms). See docs/performance-journal.md, "Sixth pass".
     */
    public static final double FINE_FLATNESS = 0.4;
    /** Extra halvings of the fine split ({@link #FINE_FLATNESS}). */
    public static final int FINE_DEPTH = 2;
    /**
     * Scenes with more patches are split without the fine split ({@link #forPatches}): 512 patches
     * at the fine cap's 256 leaves each are the scene-relative budget
     * ({@link SubPatchTable#LEAF_BUDGET}). A big scene's rays per leaf are few, its build time and
     * memory count: 100 teapots keep their 93,400 leaves.
     */
    public static final int FINE_PATCHES = 512;

    /** These options for a scene of {@code patches} patches: without the fine split past {@link #FINE_PATCHES}. */
    public SplitOptions forPatches(int patches) {
        return patches > FINE_PATCHES && fine ? new SplitOptions(enabled, flatnessTolerance, maxDepth, criterion, false)
                : this;
    }

    /**
     * Adaptive splitting with the defaults tuned for Bézier clipping on the teapot (see
     * docs/performance-journal.md, "Sub-patch tuning"): flatness 0.05 of the box diagonal, at most 6
     * halvings, and the {@link #fine} split up to bicubic in scenes of at most
     * {@link #FINE_PATCHES} patches (the figures below are without it). Against the former
     * 0.05 / 8 it makes 1,566 instead of 3,856 teapot sub-patches for the same work per ray (1.18
     * vs 1.16 solver calls, 2.29 vs 2.21 clip iterations) and no measurable change in rays/s, with a smaller BVH and a faster split. Coarser settings
     * (0.1 / 5) are as fast for clipping but make Newton's one-root-per-leaf start miss nearer
     * roots on wavy degree-9 patches ({@code BezierClipperTest}), so 6 is the floor for now.
     */
    public static SplitOptions defaults() { return new SplitOptions(true, 0.05, 6); }

    /**
     * The flatness tolerance for a degree {@code n}×{@code m} net: {@link #flatnessTolerance} up to
     * bicubic, scaled by {@value #FINE_FLATNESS} for the {@link #fine} split, and scaled by
     * {@code 3 / max(n, m)} above bicubic, so higher-degree leaves end closer to their corners'
     * bilinear patch. The work on a leaf grows with its degree
     * (a clip iteration projects and restricts {@code (n+1)(m+1)} points, a Newton step evaluates
     * them), while a flatter leaf is more often proved single-root and solved by Newton from its
     * corners without clipping: on the 10×10-point wavy grid (degree 9) this cut the exact frame by
     * about a third (see docs/performance-journal.md, "Issue 9"). A split with a solver's own
     * {@link #criterion} (Newton's refinement, which halves the waves of a high-degree patch itself)
     * keeps its tolerance.
     */
    public double flatnessFor(int n, int m) {
        int d = Math.max(n, m);
        if (!degreeAware()) {
            return flatnessTolerance;
        }
        if (d <= 3) {
            return fine ? flatnessTolerance * FINE_FLATNESS : flatnessTolerance;
        }
        return flatnessTolerance * 3 / d;
    }

    /** True when {@link #flatnessFor} and {@link #maxDepthFor} adapt to the degree: flatness-only splits. */
    public boolean degreeAware() {
        return criterion == LeafCriterion.NONE;
    }

    /**
     * The depth cap for a degree {@code n}×{@code m} net: {@link #maxDepth} up to bicubic, plus
     * {@value #FINE_DEPTH} for the {@link #fine} split (no split when {@link #maxDepth} is 0), and
     * above bicubic two halvings (one per direction) for each doubling of {@code max(n, m)}
     * beyond 3, rounded up, at most 16: degree 4..6 gets +2, 7..12 +4, 13..15 +6. Past {@link #maxDepth} the splitter refines a net above bicubic only where it is near flat
     * by {@link #flatnessTolerance} (see {@link PatchSplitter}), so a net far from flat stays near
     * {@code 2^maxDepth} pieces. A split with a solver's own {@link #criterion} keeps its cap.
     */
    public int maxDepthFor(int n, int m) {
        int d = Math.max(n, m);
        if (maxDepth == 0 || !degreeAware()) {
            return maxDepth;
        }
        if (d <= 3) {
            return fine ? Math.min(16, maxDepth + FINE_DEPTH) : maxDepth;
        }
        int doublings = 32 - Integer.numberOfLeadingZeros((d - 1) / 3); // ceil(log2(d / 3))
        return Math.min(16, maxDepth + 2 * doublings);
    }

    /** One sub-patch per patch. */
    public static SplitOptions wholePatches() { return new SplitOptions(false, 1, 0); }
}
