package org.beziertracer.render;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.JobDocument;
import org.beziertracer.model.io.JobTracer;
import org.beziertracer.model.io.ModelFormatException;

/**
 * Renders frames and pieces of frames of a render job (issue 37, {@code docs/jobs.md}): the unit of work
 * of {@code render JOB.json} and of the Spark module. The intersector is built once; every frame's camera
 * is computed (and checked) when this is made. A piece ({@code frame}, {@link PixelWindow}) comes back
 * as {@link TilePixels}, byte-identical to the same pixels of the whole frame rendered on any machine
 * and thread count.
 *
 * <p>Immutable and thread-safe: {@link #render} may run from several threads at once, each with its own
 * {@link RenderSession}.
 */
public final class JobFrames {
    private final JobDocument doc;
    private final Scene scene;
    private final RenderJob base;
    private final List<Camera> cameras;

    /**
     * A job rendered with {@code scene}, {@code settings} and {@code options} (the document's, or the
     * command line's overrides of them; the seed and integrator come from {@code options}).
     *
     * @param fileName the job file's name, for the one-line error of a frame whose camera is invalid
     * @throws ModelFormatException {@code file: camera: frame F: …}
     */
    public JobFrames(JobDocument doc, Scene scene, RenderSettings settings, RenderOptions options, String fileName) {
        this.doc = doc;
        this.scene = scene;
        this.cameras = cameras(doc, scene, settings, fileName);
        this.base = RenderJob.prepare(scene, settings, options);
    }

    /** The job as {@code render JOB.json} renders it without options, on {@code threads} threads per piece. */
    public static JobFrames of(JobDocument doc, int threads, String fileName) {
        return new JobFrames(doc, doc.scene().scene(), doc.scene().settings(), options(doc, threads), fileName);
    }

    /** The {@code render} command's engine options for a job: one-shot passes, the job's seed and integrator. */
    public static RenderOptions options(JobDocument doc, int threads) {
        return RenderOptions.defaults().withThreads(threads).withProgressive(false).withPath(pathOptions(doc.tracer()))
                .withSeed(doc.seed());
    }

    /** The integrator and the path tracer's settings a job asks for (its unset values: the defaults). */
    public static PathOptions pathOptions(JobTracer t) {
        PathOptions p = PathOptions.defaults();
        if (!t.pathTraced()) {
            return p;
        }
        p = p.withIntegrator(Integrator.PATH);
        if (t.pathDepth() != null) {
            p = p.withMaxDepth(t.pathDepth());
        }
        return t.clamp() != null ? p.withClamp(t.clamp()) : p;
    }

    /**
     * The camera of every frame of the job, each checked (the scene's camera, or the fitted default, along
     * the job's camera path). Cheap: builds no intersector, so a driver can check a job with it.
     *
     * @throws ModelFormatException {@code file: camera: frame F: …}
     */
    public static List<Camera> cameras(JobDocument doc, Scene scene, RenderSettings settings, String fileName) {
        Camera base = scene.camera().map(Camera::new)
                .orElseGet(() -> RenderJob.defaultCamera(scene, (double) settings.width() / settings.height()));
        CameraSpec spec = new CameraSpec(base.eye(), base.target(), base.up(), base.fovDegrees(), base.orthoWidth());
        List<Camera> out = new ArrayList<>();
        for (int f = doc.firstFrame(); f <= doc.lastFrame(); f++) {
            if (doc.camera() == null) {
                out.add(base);
                continue;
            }
            try {
                out.add(new Camera(doc.camera().at(f, spec)));
            } catch (IllegalArgumentException e) {
                throw new ModelFormatException(fileName, "camera: frame " + f + ": " + e.getMessage());
            }
        }
        return out;
    }

    /**
     * {@code job} lit by the desktop app's default light when the scene has none (not the renderer's light
     * at the eye); the path tracer keeps its own rule (environment and area lights count as light).
     */
    public static RenderJob withDefaultLight(RenderJob job, Scene scene) {
        return scene.lights().isEmpty() && job.options().path().integrator() != Integrator.PATH
                ? job.withLights(List.of(new PointLight(DefaultLight.position(job.camera().spec(), scene.bounds()))))
                : job;
    }

    public JobDocument document() { return doc; }

    public int width() { return base.width(); }

    public int height() { return base.height(); }

    /** The number of frames, {@code lastFrame − firstFrame + 1}. */
    public int frameCount() { return cameras.size(); }

    /** The render of the pixels {@code window} of {@code frame} (a frame of the job). */
    public RenderJob job(int frame, PixelWindow window) {
        if (frame < doc.firstFrame() || frame > doc.lastFrame()) {
            throw new IllegalArgumentException("frame " + frame + " is not in the job's " + doc.firstFrame() + "-"
                    + doc.lastFrame());
        }
        return withDefaultLight(base.withCamera(cameras.get(frame - doc.firstFrame())).withWindow(window), scene);
    }

    /** Renders the pixels {@code window} of {@code frame} on {@code session}: the PNG's pixels and the linear floats. */
    public TilePixels render(RenderSession session, int frame, PixelWindow window) throws InterruptedException {
        RenderResult result = session.render(job(frame, window));
        return TilePixels.of(result, window, base.options().path().integrator(), exposure());
    }

    /** Renders tile {@code i}/{@code n} ({@link PixelWindow#tile}) of {@code frame} on a session of its own. */
    public TilePixels renderTile(int frame, int i, int n) throws InterruptedException {
        try (RenderSession session = new RenderSession(base.options().threads(), FrameSink.NONE)) {
            return render(session, frame, PixelWindow.tile(i, n, width(), height()));
        }
    }

    /** The evaluation kernel these frames render with ({@link org.beziertracer.math.LaneKernel#description}). */
    public String kernel() {
        return base.options().kernel().description();
    }

    /** Stops before the path tracer's tone curve (0 unless the job sets it). */
    public double exposure() {
        return doc.tracer().exposure() == null ? 0 : doc.tracer().exposure();
    }
}
