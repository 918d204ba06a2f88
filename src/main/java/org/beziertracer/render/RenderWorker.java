package org.beziertracer.render;

import org.beziertracer.intersect.SceneIntersector;

/**
 * Per-thread scratch and the tile loop: turns the pixels of one tile into camera rays, traces them
 * and adds the samples to the film. One per pool thread (kept by the thread), reused across renders;
 * nothing is allocated per ray or sample. It holds the render's scene only while its thread works
 * on a pass ({@link #release}).
 */
final class RenderWorker {
    /** Rows between two checks of the generation inside a tile. */
    static final int CHECK_ROWS = 4;

    private final WhittedTracer tracer;
    private final double[] ray = new double[6];
    private final double[] rgb = new double[3];
    private final double[] offset = new double[2];
    private int[] argb = new int[0];
    private ShadingScene bound;

    RenderWorker(SceneIntersector any) {
        tracer = new WhittedTracer(any);
    }

    /**
     * Renders one tile of one pass. Returns false when the render went stale midway (the tile is
     * then abandoned and nothing goes to the sink).
     */
    boolean renderTile(RenderState st, PassPlan.Pass pass, int x0, int y0, int w, int h, boolean display) {
        if (bound != st.shading) {
            tracer.bind(st.shading);
            bound = st.shading;
        }
        Film film = st.film;
        Camera camera = st.job.camera();
        int width = film.width(), height = film.height();
        int block = pass.block(), skip = pass.skipGrid();
        double threshold = st.job.options().adaptiveThreshold();
        for (int y = y0; y < y0 + h; y++) {
            if ((y - y0) % CHECK_ROWS == 0 && st.isStale()) {
                return false;
            }
            if (y % block != 0) {
                continue;
            }
            for (int x = x0; x < x0 + w; x += block) {
                if (skip > 0 && x % skip == 0 && y % skip == 0) {
                    continue;
                }
                if (pass.adaptive() && !differs(film, x, y, threshold)) {
                    continue;
                }
                for (int s = pass.sampleFrom(); s < pass.sampleTo(); s++) {
                    st.sampler.offset(x, y, s, offset);
                    camera.generateRay(x + offset[0], y + offset[1], width, height, ray);
                    tracer.trace(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], rgb);
                    film.addSample(x, y, rgb[0], rgb[1], rgb[2]);
                }
            }
        }
        st.primaryRays.add(tracer.primaryRays);
        st.shadowRays.add(tracer.shadowRays);
        st.secondaryRays.add(tracer.secondaryRays);
        tracer.primaryRays = 0;
        tracer.shadowRays = 0;
        tracer.secondaryRays = 0;
        if (display && st.sink.wantsTiles() && !st.isStale()) {
            if (argb.length < w * h) {
                argb = new int[st.job.options().tileSize() * st.job.options().tileSize()];
            }
            film.writeArgb(x0, y0, w, h, pass.firstSample() ? block : 1, argb, w);
            st.sink.tileDone(st.generation, x0, y0, w, h, argb, w);
        }
        return true;
    }

    /**
     * Lets go of the render's scene once this thread's share of a pass is done; the next tile binds
     * the scene again. A pool thread that got no tile of the newest render would otherwise keep an
     * older model's snapshot (its BVH, its triangles) reachable for as long as it stays idle.
     */
    void release() {
        tracer.unbind();
        bound = null;
    }

    /** True when the first sample of {@code (x, y)} differs from a 4-neighbour's by more than {@code threshold}. */
    private static boolean differs(Film film, int x, int y, double threshold) {
        int width = film.width(), height = film.height();
        float[] f = film.first;
        int o = 3 * (y * width + x);
        return x > 0 && far(f, o, o - 3, threshold) || x + 1 < width && far(f, o, o + 3, threshold)
                || y > 0 && far(f, o, o - 3 * width, threshold) || y + 1 < height && far(f, o, o + 3 * width, threshold);
    }

    private static boolean far(float[] f, int a, int b, double threshold) {
        return Math.abs(f[a] - f[b]) > threshold || Math.abs(f[a + 1] - f[b + 1]) > threshold
                || Math.abs(f[a + 2] - f[b + 2]) > threshold;
    }
}
