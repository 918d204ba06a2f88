package org.beziertracer.app;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CancellationException;

import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.AtomicFiles;
import org.beziertracer.render.Camera;
import org.beziertracer.render.FrameSink;
import org.beziertracer.render.FrameStats;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderResult;
import org.beziertracer.render.RenderSession;
import org.beziertracer.render.RenderOptions;
import org.beziertracer.render.Failures;
import org.beziertracer.render.Integrator;
import org.beziertracer.render.PathOptions;
import org.beziertracer.render.Pfm;
import org.beziertracer.render.ToneMap;

/**
 * File → Export Image…: asks for the size, samples per pixel, sampler and integrator (Whitted, or
 * the path tracer with an optional time budget), then for the file, and renders the current model
 * as seen now — same view, shading, method and light — off screen, on a background task with a
 * progress bar and Cancel in the status bar; the PNG (path traced: through {@link ToneMap}) or, for
 * a {@code .pfm} file name, the linear image ({@link Pfm}) is written atomically; the PNG of a
 * path-traced image takes the app's exposure ({@link Settings#exposure()}) (a cancelled or
 * failed export leaves no file). The PNG is encoded by the desktop
 * ({@link ImageEncoder}; this layer has no image library). UI thread only.
 */
public final class ImageExport {

    /** Turns finished pixels into the bytes of an image file (the desktop's PNG encoder). */
    public interface ImageEncoder {
        /** {@code argb[y * width + x]}, sRGB, alpha 255. */
        AtomicFiles.BinaryContent encode(int width, int height, int[] argb);
    }

    private final AppModel app;
    private final BackgroundTasks io;
    private ExportOptions last;

    ImageExport(AppModel app, BackgroundTasks io) {
        this.app = app;
        this.io = io;
    }

    /** Asks what and where (two dialogs), then renders and writes off the UI thread. */
    public void export(ImageEncoder encoder) {
        ExportOptions offer = last != null ? last
                : ExportOptions.first(app.view().width(), app.view().height(), app.settings().current());
        ExportOptions o = app.dialogs().exportOptions(offer);
        if (o == null) {
            return;
        }
        last = o;
        Path p = app.dialogs().chooseSave("Export image", "png", "pfm");
        if (p != null) {
            exportTo(p, o, encoder);
        }
    }

    /** Renders with {@code o} and writes the PNG to {@code p} (no questions). */
    public void exportTo(Path p, ExportOptions o, ImageEncoder encoder) {
        Settings s = app.settings().current();
        Scene scene = app.document().scene();
        CameraSpec camera = app.view().view().camera((double) o.width() / o.height());
        List<PointLight> lights = LightRig.lights(s, camera, app.view().view().framing());
        Task task = new Task("exporting " + p.getFileName());
        app.status().task(task);
        io.submit(task, () -> {
            RenderResult r = render(scene, camera, lights, s, o, task);
            if (isPfm(p)) {
                AtomicFiles.writeBytes(p, out -> out.write(Pfm.encode(r.film(), r.window())));
            } else {
                // path traced: the app's exposure, so the PNG has the bytes of render --exposure E
                int[] argb = o.pathTraced() ? ToneMap.argb(r.film(), s.exposure()) : r.argb();
                AtomicFiles.writeBytes(p, encoder.encode(o.width(), o.height(), argb));
            }
            return p;
        }, done -> {
            app.status().endTask(task);
            app.status().message("exported " + o.width() + "×" + o.height() + " image to " + p);
        }, e -> {
            app.status().endTask(task);
            if (e instanceof CancellationException) {
                app.status().message("export of " + p.getFileName() + " cancelled");
            } else {
                app.dialogs().error("Cannot export " + p.getFileName(), Failures.describe(e));
            }
        });
    }

    /** Renders one image off screen, reporting how many tiles of how many are done. */
    static RenderResult render(Scene scene, CameraSpec camera, List<PointLight> lights, Settings s, ExportOptions o,
                               Task task) throws InterruptedException {
        RenderSettings base = RenderChoices.renderSettings(s, o.width(), o.height());
        RenderSettings rs = new RenderSettings(o.width(), o.height(), o.spp(), o.sampler().label(), base.method(),
                base.bvh(), base.shading(), base.checker(), base.shadows(), base.maxDepth());
        RenderOptions options = RenderOptions.defaults().withProgressive(false).withTessellate(s.tessellate())
                .withPath(pathOptions(o));
        SceneIntersector si = SceneIntersector.build(scene, RenderChoices.intersectOptions(s));
        RenderJob job = new RenderJob(si, new Camera(camera), rs, options, lights);
        int tile = options.tileSize();
        long tiles = (long) ((o.width() + tile - 1) / tile) * ((o.height() + tile - 1) / tile);
        long total = tiles * passes(o);
        java.util.concurrent.atomic.AtomicLong done = new java.util.concurrent.atomic.AtomicLong();
        FrameSink progress = new FrameSink() {
            @Override
            public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {
                task.progress((double) done.incrementAndGet() / total);
            }

            @Override
            public void passDone(int generation, int pass, int passCount, FrameStats stats) {}
        };
        try (RenderSession session = new RenderSession(options.threads(), progress)) {
            return session.render(job);
        }
    }

    /** The integrator of an export: Whitted, or the path tracer's defaults with the export's time budget. */
    static PathOptions pathOptions(ExportOptions o) {
        PathOptions p = PathOptions.defaults();
        return o.pathTraced() ? p.withIntegrator(Integrator.PATH).withBudgetMillis(1000L * o.seconds()) : p;
    }

    /** True for a file name that asks for the linear .pfm image (any case). */
    static boolean isPfm(Path p) {
        return p.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".pfm");
    }

    /** Passes of a one-shot render with these options: the first sample, then the extra samples. */
    private static int passes(ExportOptions o) {
        if (o.spp() == 1) {
            return 1;
        }
        if (o.pathTraced() && o.seconds() > 0) {
            return o.spp(); // one sample a pass, so the budget can stop it
        }
        if (o.sampler() == org.beziertracer.render.SamplerKind.ADAPTIVE) {
            return 2;
        }
        int n = 1;
        for (int from = 1; from < o.spp(); from *= 2) {
            n++;
        }
        return n;
    }
}
