package org.beziertracer.render;

import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;

import org.beziertracer.geometry.Tessellator;

/**
 * Engine settings that are not part of a scene file.
 *
 * @param threads            worker threads, 1..256 (default {@code availableProcessors()})
 * @param tileSize           tile side in pixels, a multiple of 8, 8..256 (default 32)
 * @param progressive        coarse preview passes first (1 ray per 8×8, 4×4, 2×2 block, then every pixel);
 *                           false: straight to full resolution (the CLI)
 * @param passesPerFrame     the memoir's "interactivity": tiles go to the sink after every
 *                           {@code passesPerFrame}-th pass (and after the last), 1..16
 * @param filter             reconstruction filter (box or tent)
 * @param adaptiveThreshold  adaptive sampler: a pixel gets its extra samples when its first sample differs
 *                           from a 4-neighbour's by more than this in some linear channel
 * @param minAttenuation     adaptive depth control: a reflected or refracted ray is not traced when the product
 *                           of the attenuations along its path is below this (default 1/256)
 * @param seed               seed of the jittered and adaptive samplers
 * @param tessellate         0: exact Bézier intersection (default); {@code K ≥ 1}: every patch is rendered as a
 *                           uniform {@code K×K} grid of triangle pairs with analytic vertex normals
 *                           ({@link org.beziertracer.intersect.IntersectOptions#tessellate()}), through the
 *                           same BVH and shading
 * @param kernel             the evaluation kernel of the intersector ({@link Kernels#best} unless chosen):
 *                           SIMD or scalar, the same picture either way
 * @param analysis           the settings of the surface-analysis views ({@link ShadingMode#isAnalysis()})
 * @param path               the integrator and the path tracer's settings ({@link PathOptions#defaults()}: Whitted)
 */
public record RenderOptions(int threads, int tileSize, boolean progressive, int passesPerFrame, PixelFilter filter,
                            double adaptiveThreshold, double minAttenuation, long seed, int tessellate,
                            LaneKernel kernel, Analysis analysis, PathOptions path) {

    public static final int MAX_THREADS = 256;

    public RenderOptions {
        if (threads < 1 || threads > MAX_THREADS) {
            throw new IllegalArgumentException("threads must be 1.." + MAX_THREADS + ", got " + threads);
        }
        if (tileSize < 8 || tileSize > 256 || tileSize % 8 != 0) {
            throw new IllegalArgumentException("tile size must be a multiple of 8 in 8..256, got " + tileSize);
        }
        if (passesPerFrame < 1 || passesPerFrame > 16) {
            throw new IllegalArgumentException("passes per frame must be 1..16, got " + passesPerFrame);
        }
        if (filter == null) {
            throw new IllegalArgumentException("filter is required");
        }
        if (!(adaptiveThreshold >= 0) || !Double.isFinite(adaptiveThreshold)) {
            throw new IllegalArgumentException("adaptive threshold must be finite and >= 0, got " + adaptiveThreshold);
        }
        if (!(minAttenuation > 0 && minAttenuation < 1)) {
            throw new IllegalArgumentException("minimum attenuation must be in (0,1), got " + minAttenuation);
        }
        if (tessellate < 0 || tessellate > Tessellator.MAX_SEGMENTS) {
            throw new IllegalArgumentException("tessellate must be 0 (exact) or 1.." + Tessellator.MAX_SEGMENTS
                    + ", got " + tessellate);
        }
        java.util.Objects.requireNonNull(kernel, "kernel");
        java.util.Objects.requireNonNull(analysis, "analysis");
        java.util.Objects.requireNonNull(path, "path");
    }

    /** With the default path settings (the Whitted integrator). */
    public RenderOptions(int threads, int tileSize, boolean progressive, int passesPerFrame, PixelFilter filter,
                         double adaptiveThreshold, double minAttenuation, long seed, int tessellate,
                         LaneKernel kernel, Analysis analysis) {
        this(threads, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation, seed, tessellate,
                kernel, analysis, PathOptions.defaults());
    }

    /** With the integrator and path tracer settings {@code p}. */
    public RenderOptions withPath(PathOptions p) {
        return new RenderOptions(threads, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation,
                seed, tessellate, kernel, analysis, p);
    }

    /** With the default analysis settings ({@link Analysis#defaults()}). */
    public RenderOptions(int threads, int tileSize, boolean progressive, int passesPerFrame, PixelFilter filter,
                         double adaptiveThreshold, double minAttenuation, long seed, int tessellate, LaneKernel kernel) {
        this(threads, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation, seed, tessellate,
                kernel, Analysis.defaults());
    }

    /** With the kernel chosen at start ({@link Kernels#best}). */
    public RenderOptions(int threads, int tileSize, boolean progressive, int passesPerFrame, PixelFilter filter,
                         double adaptiveThreshold, double minAttenuation, long seed, int tessellate) {
        this(threads, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation, seed, tessellate,
                Kernels.best());
    }

    /** All processors, 32-pixel tiles, progressive, every pass shown, box filter, threshold 0.05, 1/256, exact. */
    public static RenderOptions defaults() {
        return new RenderOptions(Runtime.getRuntime().availableProcessors(), 32, true, 1, PixelFilter.BOX,
                0.05, 1.0 / 256, 1, 0);
    }

    public RenderOptions withThreads(int n) {
        return new RenderOptions(n, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation, seed, tessellate, kernel, analysis, path);
    }

    public RenderOptions withProgressive(boolean on) {
        return new RenderOptions(threads, tileSize, on, passesPerFrame, filter, adaptiveThreshold, minAttenuation, seed, tessellate, kernel, analysis, path);
    }

    public RenderOptions withPassesPerFrame(int n) {
        return new RenderOptions(threads, tileSize, progressive, n, filter, adaptiveThreshold, minAttenuation, seed, tessellate, kernel, analysis, path);
    }

    public RenderOptions withFilter(PixelFilter f) {
        return new RenderOptions(threads, tileSize, progressive, passesPerFrame, f, adaptiveThreshold, minAttenuation, seed, tessellate, kernel, analysis, path);
    }

    public RenderOptions withTileSize(int size) {
        return new RenderOptions(threads, size, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation, seed, tessellate, kernel, analysis, path);
    }

    /** 0 = exact; {@code K ≥ 1} = uniform {@code K×K} tessellation per patch. */
    public RenderOptions withTessellate(int k) {
        return new RenderOptions(threads, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation, seed, k, kernel, analysis, path);
    }

    /** The same options with another evaluation kernel (the same picture, another speed). */
    public RenderOptions withKernel(LaneKernel k) {
        return new RenderOptions(threads, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation,
                seed, tessellate, k, analysis, path);
    }

    /** With the analysis views' settings {@code a}. */
    public RenderOptions withAnalysis(Analysis a) {
        return new RenderOptions(threads, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation,
                seed, tessellate, kernel, a, path);
    }

    /** With the jittered and adaptive samplers' seed {@code s} (a job file's {@code seed}). */
    public RenderOptions withSeed(long s) {
        return new RenderOptions(threads, tileSize, progressive, passesPerFrame, filter, adaptiveThreshold, minAttenuation,
                s, tessellate, kernel, analysis, path);
    }

    /** True in tessellated (triangle mesh) mode. */
    public boolean tessellated() { return tessellate > 0; }
}
