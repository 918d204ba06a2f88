package org.beziertracer.app;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.render.SamplerKind;

/**
 * What File → Export Image… renders: the size in pixels, the samples per pixel and the sampler.
 *
 * @throws IllegalArgumentException one line naming the value, when it is out of range
 */
public record ExportOptions(int width, int height, int spp, SamplerKind sampler) {

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
    }

    /** The first offer: the picture's size, 16 jittered samples per pixel. */
    static ExportOptions first(int width, int height) {
        return new ExportOptions(width, height, 16, SamplerKind.JITTERED);
    }
}
