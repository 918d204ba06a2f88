package org.beziertracer.bench;

import java.util.concurrent.TimeUnit;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.render.FrameSink;
import org.beziertracer.render.FrameStats;
import org.beziertracer.render.Integrator;
import org.beziertracer.render.PathOptions;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderOptions;
import org.beziertracer.render.RenderSession;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;

/**
 * The app's exposure change: {@link RenderSession#setExposure} tone maps a finished path-traced film
 * of {@code width} pixels (the studio at 4:3, 1 sample a pixel, rendered once in the set-up) again
 * and hands every tile to a sink that copies it into a picture array as the app's {@code Picture}
 * does. One operation is one whole frame (ACES + sRGB per pixel, tile by tile under the display
 * lock); the exposure alternates between +1 and −1 stops so no call is a no-op. Average time in ms.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class RetoneBench {

    /** Picture width in pixels (height 3/4 of it); 1370 is a full-HD app window's picture. */
    @Param({"1370"})
    public int width;

    RenderSession session;
    int[] picture;
    int stride;
    double exposure = 1;

    @Setup
    public void setup() throws InterruptedException {
        SceneDocument doc = PathBench.scene("studio");
        int w = width, h = width * 3 / 4;
        stride = w;
        picture = new int[w * h];
        RenderSettings s = doc.settings();
        RenderSettings rs = new RenderSettings(w, h, 1, "jittered", s.method(), s.bvh(), s.shading(), s.checker(),
                s.shadows(), s.maxDepth());
        RenderOptions o = RenderOptions.defaults().withThreads(2).withProgressive(false)
                .withPath(PathOptions.defaults().withIntegrator(Integrator.PATH).withMaxDepth(4));
        RenderJob job = RenderJob.prepare(doc.scene(), rs, o);
        session = new RenderSession(2, new FrameSink() {
            @Override
            public void tileDone(int generation, int x0, int y0, int tw, int th, int[] argb, int tileStride) {
                for (int j = 0; j < th; j++) {
                    System.arraycopy(argb, j * tileStride, picture, (y0 + j) * stride + x0, tw);
                }
            }

            @Override
            public void passDone(int generation, int pass, int passCount, FrameStats stats) {}
        });
        session.render(job);
    }

    @TearDown
    public void close() {
        session.close();
    }

    @Benchmark
    public int retone() {
        exposure = -exposure;
        session.setExposure(exposure);
        return picture[picture.length / 2];
    }
}
