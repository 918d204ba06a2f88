package org.beziertracer.render;

import java.util.ArrayList;
import java.util.List;

/**
 * The passes of one render, in order.
 *
 * <p>Progressive: the first sample of the pixels on an 8-pixel grid (each filling its 8×8 block
 * on screen), then of the remaining pixels on the 4-, 2- and 1-pixel grids, so every pixel's first
 * sample is traced exactly once. One-shot: a single first-sample pass over all pixels. Then the
 * extra samples: regular and jittered add samples {@code [1,2), [2,4), [4,8) …} up to spp in
 * successive passes; adaptive adds samples {@code [1, spp)} in one pass, only to pixels whose first
 * sample differs from a neighbour's. Each pixel receives the same samples in the same order either
 * way, so a progressive render ends on exactly the one-shot image.
 *
 * <p>One sample a pass ({@link #of(boolean, SamplerKind, int, boolean)}): the extra samples come one
 * a pass, {@code [1,2), [2,3) …}, so a progressive path-traced picture refines after every sample
 * of every pixel (the desktop app's Path Traced mode); the per-pixel order, and so the image, is
 * the same again.
 */
final class PassPlan {
    /** Coarsest progressive block. */
    static final int COARSEST = 8;

    /**
     * One pass.
     *
     * @param block      first-sample passes: pixels on this grid; extra passes: 1 (a power of two)
     * @param skipGrid   first-sample passes: pixels on this coarser grid were done before (0: none;
     *                   else a power of two, which the render worker masks with)
     * @param sampleFrom first sample index traced
     * @param sampleTo   one past the last sample index
     * @param adaptive   extra samples only where the first sample differs from a neighbour's
     */
    record Pass(int block, int skipGrid, int sampleFrom, int sampleTo, boolean adaptive) {
        boolean firstSample() { return sampleFrom == 0; }
    }

    private PassPlan() {}

    static List<Pass> of(boolean progressive, SamplerKind sampler, int spp) {
        return of(progressive, sampler, spp, false);
    }

    /** The passes; with {@code onePerPass} the regular and jittered extra samples come one a pass. */
    static List<Pass> of(boolean progressive, SamplerKind sampler, int spp, boolean onePerPass) {
        List<Pass> passes = new ArrayList<>();
        if (progressive) {
            for (int b = COARSEST; b >= 1; b /= 2) {
                passes.add(new Pass(b, b == COARSEST ? 0 : 2 * b, 0, 1, false));
            }
        } else {
            passes.add(new Pass(1, 0, 0, 1, false));
        }
        if (spp > 1) {
            if (sampler == SamplerKind.ADAPTIVE) {
                passes.add(new Pass(1, 0, 1, spp, true));
            } else {
                for (int from = 1; from < spp; from = onePerPass ? from + 1 : 2 * from) {
                    passes.add(new Pass(1, 0, from, onePerPass ? from + 1 : Math.min(2 * from, spp), false));
                }
            }
        }
        return passes;
    }
}
