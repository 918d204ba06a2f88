package org.beziertracer.render;

import java.util.Arrays;

import org.beziertracer.accel.RayPacket;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.math.LaneKernel;

/**
 * Per-thread scratch and the tile loop: turns the pixels of one tile into camera rays, traces them
 * and adds the samples to the film. One per pool thread (kept by the thread), reused across renders;
 * nothing is allocated per ray or sample. It holds the render's scene only while its thread works
 * on a pass ({@link #release}).
 */
final class RenderWorker {
    /**
     * Pixels of a pass's grid a side of a packet of camera rays traced together ({@link
     * RayPacket}); the generation is checked before each row of packets, so every
     * {@value} rows of the grid.
     */
    static final int PACKET = 4;

    private final WhittedTracer tracer;
    /** The path tracer and its query context, made on the first path-traced tile (a Whitted render never needs them). */
    private PathTracer pathTracer;
    /** The kernel of the tracer's query context ({@link #fits}). */
    private final LaneKernel kernel;
    private final double[] offset = new double[2];
    private final RayPacket packet = new RayPacket();
    /** The packet's rays (origin, direction) and their pixels (x, y); grown, never shrunk. */
    private double[] rays = new double[6 * PACKET * PACKET];
    private int[] pixels = new int[2 * PACKET * PACKET];
    /** The sample index of each ray of the packet (the path tracer seeds its numbers with it). */
    private int[] samples = new int[PACKET * PACKET];
    private double[] colours = new double[3 * PACKET * PACKET];
    private int[] argb = new int[0];
    private ShadingScene bound;

    RenderWorker(SceneIntersector any) {
        tracer = new WhittedTracer(any);
        kernel = any.options().kernel();
    }

    /**
     * True when this worker's scratch serves {@code job} as a worker made for it would: its query
     * context has the job's kernel (a spare worker of another session is reused only then).
     */
    boolean fits(RenderJob job) {
        return kernel == job.intersector().options().kernel();
    }

    /**
     * Renders one tile of one pass. Returns false when the render went stale midway (the tile is
     * then abandoned and nothing goes to the sink).
     */
    boolean renderTile(RenderState st, PassPlan.Pass pass, int x0, int y0, int w, int h, boolean display) {
        if (bound != st.shading) {
            tracer.bind(st.shading);
            if (st.path != null) {
                if (pathTracer == null) {
                    pathTracer = new PathTracer(st.job.intersector());
                }
                pathTracer.bind(st.shading, st.path);
            }
            bound = st.shading;
        }
        long seed = st.job.options().seed();
        Film film = st.film;
        Camera camera = st.job.camera();
        int block = pass.block(), skip = pass.skipGrid();
        double threshold = st.job.options().adaptiveThreshold();
        int span = PACKET * block;
        for (int gy = y0 + Math.floorMod(-y0, block); gy < y0 + h; gy += span) {
            if (st.isStale()) {
                return false;
            }
            int yEnd = Math.min(gy + span, y0 + h);
            for (int gx = x0; gx < x0 + w; gx += span) {
                int xEnd = Math.min(gx + span, x0 + w);
                // The packet: this pass's samples of up to PACKET × PACKET pixels of the pass's grid
                int n = 0;
                for (int y = gy; y < yEnd; y += block) {
                    // the skip grid is a power of two (PassPlan): a mask, not a division per pixel
                    boolean skipRow = skip > 0 && (y & (skip - 1)) == 0;
                    for (int x = gx; x < xEnd; x += block) {
                        if (skipRow && (x & (skip - 1)) == 0) {
                            continue;
                        }
                        if (pass.adaptive() && !differs(film, x, y, threshold)) {
                            continue;
                        }
                        for (int s = pass.sampleFrom(); s < pass.sampleTo(); s++) {
                            n = addRay(st, camera, x, y, s, n);
                        }
                    }
                }
                RayPacket together = n > 1 && tracer.gather(packet.of(rays, n)) ? packet : null;
                if (st.path != null) {
                    pathTracer.tracePacket(together, rays, pixels, samples, n, seed, colours);
                } else {
                    tracer.tracePacket(together, rays, n, colours);
                }
                for (int i = 0; i < n; i++) {
                    film.addSample(pixels[2 * i], pixels[2 * i + 1], colours[3 * i], colours[3 * i + 1], colours[3 * i + 2]);
                }
            }
        }
        tracer.addCounts(st);
        if (pathTracer != null) {
            pathTracer.addCounts(st);
        }
        if (display && st.sink.wantsTiles() && !st.isStale()) {
            if (argb.length < w * h) {
                argb = new int[st.job.options().tileSize() * st.job.options().tileSize()];
            }
            synchronized (st.displayLock) {
                // one tile under the lock that a new exposure's retone takes (RenderState.retone)
                film.writeArgb(x0, y0, w, h, pass.firstSample() ? block : 1, argb, w, st.toneScale);
                st.sink.tileDone(st.generation, x0, y0, w, h, argb, w);
            }
        }
        return true;
    }

    /** The tracer's query context (tests read its work counters). */
    TraceContext context() {
        return tracer.context();
    }

    /** Makes the camera ray of sample {@code s} of pixel {@code (x, y)} the packet's ray {@code n}; returns n + 1. */
    private int addRay(RenderState st, Camera camera, int x, int y, int s, int n) {
        if (6 * n + 6 > rays.length) {
            rays = Arrays.copyOf(rays, 2 * rays.length);
            pixels = Arrays.copyOf(pixels, 2 * pixels.length);
            samples = Arrays.copyOf(samples, 2 * samples.length);
            colours = new double[rays.length / 2];
        }
        st.sampler.offset(x, y, s, offset);
        // the whole image's camera, also when the film holds only a window of it
        camera.generateRay(x + offset[0], y + offset[1], st.job.width(), st.job.height(), rays, 6 * n);
        pixels[2 * n] = x;
        pixels[2 * n + 1] = y;
        samples[n] = s;
        return n + 1;
    }

    /**
     * Makes this worker's query contexts work as new ones would ({@link TraceContext#forgetHistory}):
     * for a worker taken over from a closed session, so that a render's work does not depend on the
     * renders its worker served before.
     */
    void forgetHistory() {
        tracer.context().forgetHistory();
        if (pathTracer != null) {
            pathTracer.context().forgetHistory();
        }
    }

    /**
     * Lets go of the render's scene once this thread's share of a pass is done; the next tile binds
     * the scene again. A pool thread that got no tile of the newest render would otherwise keep an
     * older model's snapshot (its BVH, its triangles) reachable for as long as it stays idle.
     */
    void release() {
        tracer.unbind();
        if (pathTracer != null) {
            pathTracer.unbind();
        }
        bound = null;
    }

    /**
     * True when the first sample of {@code (x, y)} differs from a 4-neighbour's by more than {@code threshold}.
     * Neighbours outside the film are not compared: the film is the whole image, or a window grown by one
     * pixel ({@link RenderJob#filmWindow()}), whose own edge pixels are not kept.
     */
    private static boolean differs(Film film, int x, int y, double threshold) {
        int width = film.width(), height = film.height();
        int lx = x - film.x0(), ly = y - film.y0();
        float[] f = film.first;
        int o = 3 * (ly * width + lx);
        return lx > 0 && far(f, o, o - 3, threshold) || lx + 1 < width && far(f, o, o + 3, threshold)
                || ly > 0 && far(f, o, o - 3 * width, threshold) || ly + 1 < height && far(f, o, o + 3 * width, threshold);
    }

    private static boolean far(float[] f, int a, int b, double threshold) {
        return Math.abs(f[a] - f[b]) > threshold || Math.abs(f[a + 1] - f[b + 1]) > threshold
                || Math.abs(f[a + 2] - f[b + 2]) > threshold;
    }
}
