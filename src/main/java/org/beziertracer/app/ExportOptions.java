package org.beziertracer.app;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.render.SamplerKind;

/**
 * What File → Export Image… renders: the size in pixels, the samples per pixel, the sampler and
 * the integrator — the Whitted renderer, or the path tracer with an optional time budget (it then
 * stops at the samples or at the time, whichever comes first).
 *
 * @param seconds path tracer: the time budget in seconds, 0 for none (at most {@value #MAX_SECONDS})
 * @throws IllegalArgumentException one line naming the value, when it is out of range
 */
public record ExportOptions(int width, int height, int spp, SamplerKind sampler, boolean pathTraced, int seconds) {

    /** The longest time budget: a day. */
    public static final int MAX_SECONDS = 86_400;

    public ExportOptions {
        if (width < 1 || width > RenderSettings.MAX_SIZE || height < 1 || height > RenderSettings.MAX_SIZE) {
            throw new IllegalArgumentException("the image size must be 1.." + RenderSettings.MAX_SIZE + " pixels a side, got "
                    + width + "×" + height);
        }
        if ((long) width * height > RenderSettings.MAX_PIXELS) {
            throw new IllegalArgumentException("an image of " + width + "×" + height + " pixels is too big (at most "
                    + RenderSettings.MAX_PIXELS / 1_000_000 + " million pixels)");
        }
        if (spp < 1 || spp > RenderSettings.MAX_SPP) {
            throw new IllegalArgumentException("samples per pixel must be 1.." + RenderSettings.MAX_SPP + ", got " + spp);
        }
        if (sampler == null) {
            throw new IllegalArgumentException("choose a sampler: regular, jittered or adaptive");
        }
        if (seconds < 0 || seconds > MAX_SECONDS) {
            throw new IllegalArgumentException("the time limit must be 0.." + MAX_SECONDS + " seconds (0 = none), got "
                    + seconds);
        }
        if (seconds > 0 && !pathTraced) {
            throw new IllegalArgumentException("a time limit needs the path tracer");
        }
    }

    /** A Whitted export. */
    public ExportOptions(int width, int height, int spp, SamplerKind sampler) {
        this(width, height, spp, sampler, false, 0);
    }

    /** The first offer: the picture's size, 16 jittered samples per pixel, Whitted. */
    static ExportOptions first(int width, int height) {
        return new ExportOptions(width, height, 16, SamplerKind.JITTERED);
    }

    /** The first offer while the picture is path traced: its target samples, jittered, no time limit. */
    static ExportOptions first(int width, int height, Settings s) {
        return s.pathTraced() ? new ExportOptions(width, height, s.level(Level.PATH_SAMPLES), SamplerKind.JITTERED, true, 0)
                : first(width, height);
    }
}
