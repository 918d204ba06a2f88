package org.beziertracer.render;

import java.util.Locale;

/**
 * Traces the samples of one pixel with a {@link TraceLog}, printing every ray, hit and shading term
 * (the {@code render --pixel x,y} debug trace; pbrt's {@code --debugstart} in spirit). The colour
 * it returns is exactly what the renderer puts in that pixel.
 */
public final class PixelProbe {
    private PixelProbe() {}

    /**
     * Traces pixel {@code (x, y)} of {@code job} and returns its linear RGB (the mean of its samples;
     * with the adaptive sampler, the first sample only, as neighbours are not known here).
     */
    public static double[] trace(RenderJob job, int x, int y, TraceLog log) {
        if (x < 0 || y < 0 || x >= job.width() || y >= job.height()) {
            throw new IllegalArgumentException("pixel " + x + "," + y + " is outside the " + job.width() + "x"
                    + job.height() + " image");
        }
        WhittedTracer tracer = WhittedTracer.forJob(job);
        tracer.setLog(log);
        PixelSampler sampler = new PixelSampler(job.sampler(), job.options().filter(), job.settings().spp(),
                job.options().seed());
        int spp = job.sampler() == SamplerKind.ADAPTIVE ? 1 : job.settings().spp();
        double[] offset = new double[2], ray = new double[6], rgb = new double[3], sum = new double[3];
        log.line("camera " + job.camera());
        for (int s = 0; s < spp; s++) {
            sampler.offset(x, y, s, offset);
            job.camera().generateRay(x + offset[0], y + offset[1], job.width(), job.height(), ray);
            log.line(String.format(Locale.ROOT, "sample %d at (%.4f, %.4f)", s, x + offset[0], y + offset[1]));
            tracer.trace(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], rgb);
            log.line(String.format(Locale.ROOT, "sample %d colour (linear) = (%.5f, %.5f, %.5f)", s, rgb[0], rgb[1], rgb[2]));
            for (int c = 0; c < 3; c++) {
                sum[c] += rgb[c];
            }
        }
        for (int c = 0; c < 3; c++) {
            sum[c] /= spp;
        }
        int argb = Srgb.argb((float) sum[0], (float) sum[1], (float) sum[2]);
        log.line(String.format(Locale.ROOT, "pixel %d,%d: linear (%.5f, %.5f, %.5f) -> sRGB #%06X; rays: %d primary, %d shadow, "
                        + "%d secondary", x, y, sum[0], sum[1], sum[2], argb & 0xFFFFFF, tracer.primaryRays(),
                tracer.shadowRays(), tracer.secondaryRays()));
        return sum;
    }
}
