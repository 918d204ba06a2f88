package org.beziertracer.cli;

import org.beziertracer.math.Kernels;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.function.IntSupplier;

import org.beziertracer.geometry.Tessellator;
import org.beziertracer.intersect.HeapBudget;
import org.beziertracer.intersect.Method;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.PointLight;
import org.beziertracer.render.DefaultLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.FilePaths;
import org.beziertracer.model.io.JobFiles;
import org.beziertracer.model.io.JobTracer;
import org.beziertracer.render.JobFrames;
import org.beziertracer.model.io.SceneFiles;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.render.Camera;
import org.beziertracer.render.Film;
import org.beziertracer.render.Integrator;
import org.beziertracer.render.PathOptions;
import org.beziertracer.render.Pfm;
import org.beziertracer.render.RadianceHdr;
import org.beziertracer.render.ToneMap;
import org.beziertracer.model.io.AtomicFiles;
import org.beziertracer.render.FrameSink;
import org.beziertracer.render.ImageDifference;
import org.beziertracer.render.PixelFilter;
import org.beziertracer.render.PixelProbe;
import org.beziertracer.render.PixelWindow;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.AnalysisRange;
import org.beziertracer.render.RenderOptions;
import org.beziertracer.render.RenderProgress;
import org.beziertracer.render.RenderResult;
import org.beziertracer.render.RenderSession;

import com.google.gson.Gson;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code render MODEL_OR_SCENE -o OUT.png}: ray traces a model or scene into a PNG. Options override
 * the scene's settings, camera and lights; a model or scene without lights is lit as the desktop app
 * lights it by default ({@link DefaultLight}). {@code --stats} prints one JSON line; {@code --pixel x,y}
 * prints the full trace of one pixel. While rendering, a progress bar goes to standard error when
 * it is a terminal (not with {@code --quiet}). Bad values end with one error line and exit code 1.
 */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = "Ray traces a model or scene into a PNG image (or a linear .hdr or .pfm, for the path tracer).")
final class RenderCommand implements Callable<Integer> {

    static final int MAX_REPEAT = 1000;
    /** A pixel differs from the other method's when a channel differs by more than this share of the range (issue #10). */
    static final double DIFFERENCE_PERCENT = 10;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MODEL_OR_SCENE", descriptionKey = CliText.INPUT)
    String model;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT.png",
            description = "PNG to write (atomically), or .hdr (Radiance RGBE) or .pfm for the linear image; required unless --pixel")
    Path output;

    @Option(names = "--integrator", paramLabel = "whitted|path",
            description = "Whitted ray tracing or physically based path tracing (default: the job's, else whitted)")
    String integrator;

    @Option(names = "--clamp", paramLabel = "X",
            description = "path tracer: scale each sample down so no channel exceeds X, against fireflies (0 = off, the default)")
    Double clamp;

    @Option(names = "--exposure", paramLabel = "EV",
            description = "path tracer: exposure in stops before the ACES tone curve of the PNG (default: 0)")
    Double exposure;

    @Option(names = "--seed", paramLabel = "N",
            description = "seed of the jittered and adaptive samplers, a whole number (default: the job's, else 1)")
    Long seed;

    @Option(names = "--size", paramLabel = "WxH", description = "image size, e.g. 800x600 (default: the scene's)")
    String size;

    @Option(names = "--spp", paramLabel = "N", description = "samples per pixel, 1..1024 (default: the scene file's, else 1)")
    Integer spp;

    @Option(names = "--sampler", paramLabel = "regular|jittered|adaptive", description = "sample placement (default: the scene file's, else regular)")
    String sampler;

    @Option(names = "--filter", paramLabel = "box|tent", defaultValue = "box", description = "pixel filter (default: ${DEFAULT-VALUE})")
    String filter;

    @Option(names = "--method", paramLabel = "METHOD", completionCandidates = MethodLabels.class,
            description = "ray-patch solver: ${COMPLETION-CANDIDATES} (default: the scene's)")
    String method;

    @Option(names = "--no-bvh", description = "no sub-patch BVH: test whole patches in a list")
    boolean noBvh;

    @Option(names = "--tessellate", paramLabel = "K", defaultValue = "0",
            description = "render a uniform KxK triangle tessellation of every patch instead of the exact "
                    + "surface (0 = exact, the default; at most 1024), same BVH and shading")
    int tessellate;

    @Option(names = "--kernel", paramLabel = "auto|scalar|simd", defaultValue = "auto",
            description = "evaluation kernel: SIMD needs Java started with --add-modules jdk.incubator.vector; "
                    + "the picture is the same either way (default: ${DEFAULT-VALUE})")
    String kernel;

    @Option(names = "--shading", paramLabel = "phong|flat|normals|uv|patch-id",
            description = "shading mode (default: the scene file's, else phong; --analysis for the analysis views)")
    String shading;

    @picocli.CommandLine.Mixin
    AnalysisOptions analysisOptions = new AnalysisOptions();

    @picocli.CommandLine.Mixin
    PieceOptions pieceOptions = new PieceOptions();

    @Option(names = "--texture", paramLabel = "checker[:N]|none", description = "checker texture on the patches, N squares per side (default 8)")
    String texture;

    @Option(names = "--eye", paramLabel = "x,y,z", description = "camera position")
    String eye;

    @Option(names = "--target", paramLabel = "x,y,z", description = "point looked at")
    String target;

    @Option(names = "--up", paramLabel = "x,y,z", description = "camera up vector")
    String up;

    @Option(names = "--fov", paramLabel = "DEG", description = "horizontal field of view; 0 = orthographic")
    Double fov;

    @Option(names = "--light", paramLabel = "x,y,z", description = "a white point light (repeatable; replaces the scene's)")
    List<String> lights = new ArrayList<>();

    @Option(names = "--no-shadows", description = "no shadow rays")
    boolean noShadows;

    @Option(names = "--depth", paramLabel = "N", description = "maximum reflection/refraction depth, 0..32 (default: the scene "
            + "file's, else 5); for the path tracer the most bounces of a path, 1..1024 (default 16)")
    Integer depth;

    @Option(names = "--threads", paramLabel = "N", description = "worker threads (default: available processors)")
    Integer threads;

    @Option(names = "--repeat", paramLabel = "K", defaultValue = "1", description = "render K frames (for timing)")
    int repeat;

    @Option(names = "--stats", description = "print one JSON line of statistics to standard output")
    boolean stats;

    @Option(names = "--pixel", paramLabel = "x,y", description = "trace this pixel and print every ray, hit and shading term")
    String pixel;

    @Option(names = "--difference-to", paramLabel = "METHOD", completionCandidates = MethodLabels.class,
            description = "also render with this method (${COMPLETION-CANDIDATES}); write the pixels that differ "
                    + "by more than 10 %% in red over a dimmed image and print their count")
    String differenceTo;

    @Option(names = {"-q", "--quiet"}, description = "no progress bar (shown on standard error only when it is a terminal)")
    boolean quiet;

    /** A job file's integrator settings, under the command line's ({@link #tracer()}); none without a job. */
    JobTracer jobTracer = JobTracer.NONE;

    /** Samples of one frame (width × height × spp), the progress bar's first total. */
    private long samplesPerFrame;

    /** Columns of the terminal on standard error, 0 when it is not a terminal; tests replace it. */
    IntSupplier stderrColumns = StandardError::terminalColumns;

    @Override
    public Integer call() throws IOException, InterruptedException {
        if (JobFiles.isJob(model)) {
            return new JobRender(this).run();
        }
        if (pieceOptions.frames != null) {
            throw new IllegalArgumentException("--frames needs a job file (a .json file with \"job\": 1)");
        }
        checkArguments();
        int threadCount = threadCount();
        RenderOptions options = options(threadCount);
        SceneDocument doc = ReadNotes.show(SceneFiles.load(model, Method::parse), spec.commandLine().getErr());
        RenderSettings settings = settings(doc.settings());
        checkMemory(settings);
        this.samplesPerFrame = (long) settings.width() * settings.height() * settings.spp();
        Scene scene = withLights(doc.scene());
        HeapBudget.require(model, scene, RenderJob.intersectOptions(settings, options));
        PixelWindow window = pieceOptions.window(settings.width(), settings.height());
        RenderJob job = RenderJob.prepare(scene, settings, options);
        job = withDefaultLight(job.withCamera(camera(job.camera())).withWindow(window), scene);
        RenderJob otherJob = differenceTo == null ? null : other(scene, settings, options, job);
        PrintWriter out = spec.commandLine().getOut();
        if (pixel != null) {
            int[] xy = ints("--pixel", pixel, 2, ",");
            PixelProbe.trace(job, xy[0], xy[1], out::println);
            out.flush();
            if (output == null) {
                return 0;
            }
        }
        double[] frameMillis = new double[repeat];
        RenderResult result = null;
        try (ProgressBarDisplay bar = progressBar();
             RenderSession session = new RenderSession(threadCount, FrameSink.NONE,
                     bar == null ? RenderProgress.NONE : bar)) {
            for (int k = 0; k < repeat; k++) {
                result = session.render(job);
                frameMillis[k] = result.stats().millis();
            }
            if (differenceTo != null) {
                int[] argb = difference(session.render(otherJob).argb(), result.argb(), out);
                PngWriter.write(output, window.width(), window.height(), argb);
            }
        }
        if (differenceTo == null) {
            write(result, options, window);
        }
        if (stats) {
            out.println(statsJson(job, settings, threadCount, result, frameMillis));
            out.flush();
        }
        return 0;
    }

    int threadCount() {
        return threads == null ? Runtime.getRuntime().availableProcessors() : threads;
    }

    /** The engine options the command line asks for. */
    RenderOptions options(int threadCount) {
        RenderOptions o = RenderOptions.defaults().withThreads(threadCount).withProgressive(false)
                .withFilter(PixelFilter.parse(filter)).withTessellate(tessellate)
                .withKernel("auto".equalsIgnoreCase(kernel) ? Kernels.best() : Kernels.named(kernel))
                .withAnalysis(analysisOptions.settings()).withPath(JobFrames.pathOptions(tracer()));
        return seed == null ? o : o.withSeed(seed);
    }

    private boolean pathTraced() { return tracer().pathTraced(); }

    /**
     * The integrator and the path tracer's settings: {@code --integrator}, {@code --depth} (for the path
     * tracer), {@code --clamp} and {@code --exposure} over a job's, each checked with one line.
     */
    JobTracer tracer() {
        String i = integrator != null ? Integrator.parse(integrator).label() : jobTracer.integrator();
        boolean path = "path".equals(i);
        if (!path && (clamp != null || exposure != null)) {
            throw new IllegalArgumentException("--clamp and --exposure need --integrator path");
        }
        if (!path) {
            return new JobTracer(i, null, null, null);
        }
        if (depth != null && (depth < 1 || depth > PathOptions.MAX_DEPTH)) {
            throw new IllegalArgumentException("--depth must be 1.." + PathOptions.MAX_DEPTH
                    + " for the path tracer, got " + depth);
        }
        if (clamp != null && (!(clamp >= 0) || !Double.isFinite(clamp))) {
            throw new IllegalArgumentException("--clamp must be a finite number >= 0 (0 = off), got " + clamp);
        }
        if (exposure != null && (!Double.isFinite(exposure) || Math.abs(exposure) > JobTracer.MAX_EXPOSURE)) {
            throw new IllegalArgumentException("--exposure must be -64..64 stops, got " + exposure);
        }
        return new JobTracer(i, depth != null ? depth : jobTracer.pathDepth(), clamp != null ? clamp : jobTracer.clamp(),
                exposure != null ? exposure : jobTracer.exposure());
    }

    /** Stops before the path tracer's tone curve. */
    double exposure() {
        JobTracer t = tracer();
        return t.exposure() == null ? 0 : t.exposure();
    }

    /**
     * The image: a .hdr (Radiance RGBE) or .pfm of the linear film; a PNG through the ACES curve for the path tracer, as
     * the Whitted renderer's clamp-and-encode otherwise.
     */
    void write(RenderResult result, RenderOptions options, PixelWindow window) throws IOException {
        Film film = result.film();
        if (isPfm(output)) {
            AtomicFiles.writeBytes(output, out -> out.write(Pfm.encode(film, window)));
        } else if (isHdr(output)) {
            AtomicFiles.writeBytes(output, out -> out.write(RadianceHdr.encode(film, window)));
        } else if (options.path().integrator() == Integrator.PATH) {
            PngWriter.write(output, window.width(), window.height(), ToneMap.argb(film, window, exposure()));
        } else {
            PngWriter.write(output, window.width(), window.height(), result.argb());
        }
    }

    private static boolean isPfm(Path p) {
        return p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".pfm");
    }

    private static boolean isHdr(Path p) {
        return p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".hdr");
    }

    /** The options' own checks, before anything is read: one line each. */
    void checkArguments() {
        if (output == null && pixel == null) {
            throw new IllegalArgumentException("missing -o OUT.png");
        }
        if (output != null && output.toString().isEmpty()) {
            throw new IllegalArgumentException("-o: the file name is empty; -o needs a .png file name");
        }
        if (output != null && (output.getFileName() == null || Files.isDirectory(output))) {
            throw new IllegalArgumentException(FilePaths.text(output) + ": is a folder; -o needs a .png file name");
        }
        if (output != null && !output.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png")
                && !isPfm(output) && !isHdr(output)) {
            throw new IllegalArgumentException(FilePaths.text(output) + ": the output must be a .png (or .hdr or .pfm) file");
        }
        tracer();
        if (pixel != null && pathTraced()) {
            throw new IllegalArgumentException("--pixel traces the Whitted renderer; it does not take --integrator path");
        }
        if (differenceTo != null && pathTraced()) {
            throw new IllegalArgumentException("--difference-to compares Whitted renders; it does not take --integrator path");
        }
        if (method != null) {
            Method.parse(method);
        }
        if (differenceTo != null) {
            Method.parse(differenceTo);
        }
        if (repeat < 1 || repeat > MAX_REPEAT) {
            throw new IllegalArgumentException("--repeat must be 1.." + MAX_REPEAT + ", got " + repeat);
        }
        pieceOptions.check();
        if (tessellate < 0 || tessellate > Tessellator.MAX_SEGMENTS) {
            throw new IllegalArgumentException("--tessellate must be 0 (exact) or 1.." + Tessellator.MAX_SEGMENTS
                    + ", got " + tessellate);
        }
    }

    /** {@code scene} with the lights of {@code --light} instead of its own, when there are any. */
    Scene withLights(Scene scene) {
        if (lights.isEmpty()) {
            return scene;
        }
        List<PointLight> list = new ArrayList<>();
        for (String l : lights) {
            list.add(new PointLight(vec("--light", l)));
        }
        return scene.toBuilder().lights(list).build();
    }

    /** {@link JobFrames#withDefaultLight}. */
    static RenderJob withDefaultLight(RenderJob job, Scene scene) {
        return JobFrames.withDefaultLight(job, scene);
    }

    /** The same view rendered with the method of {@code --difference-to}. */
    private RenderJob other(Scene scene, RenderSettings s, RenderOptions options, RenderJob job) {
        RenderSettings o = new RenderSettings(s.width(), s.height(), s.spp(), s.sampler(),
                differenceTo.trim().toLowerCase(Locale.ROOT), s.bvh(), s.shading(), s.checker(), s.shadows(), s.maxDepth());
        return RenderJob.prepare(scene, o, options).withCamera(job.camera()).withLights(job.lights()).withWindow(job.window());
    }

    /** Prints how many pixels of {@code mine} differ from {@code theirs}; the overlay image. */
    private int[] difference(int[] theirs, int[] mine, PrintWriter out) {
        int n = ImageDifference.count(mine, theirs, DIFFERENCE_PERCENT);
        out.printf(Locale.ROOT, "%d of %d pixels differ from %s by more than %.0f %%%n", n, mine.length,
                differenceTo.trim().toLowerCase(Locale.ROOT), DIFFERENCE_PERCENT);
        out.flush();
        return ImageDifference.overlay(mine, theirs, DIFFERENCE_PERCENT);
    }

    /** The progress bar on standard error, or null with --quiet or when standard error is not a terminal. */
    private ProgressBarDisplay progressBar() {
        return progressBar(repeat);
    }

    /** A progress bar over {@code frameCount} frames, or null (see {@link #progressBar()}). */
    ProgressBarDisplay progressBar(int frameCount) {
        int columns = quiet ? 0 : stderrColumns.getAsInt();
        return columns == 0 ? null : new ProgressBarDisplay(spec.commandLine().getErr(), columns, frameCount,
                samplesPerFrame);
    }

    RenderSettings settings(RenderSettings s) {
        int w = s.width(), h = s.height();
        if (size != null) {
            int[] wh = ints("--size", size, 2, "[xX]");
            w = wh[0];
            h = wh[1];
        }
        int checker = s.checker();
        if (texture != null) {
            checker = texture(texture);
        }
        return new RenderSettings(w, h, spp != null ? spp : s.spp(), sampler != null ? sampler : s.sampler(),
                method != null ? method : s.method(), !noBvh && s.bvh(),
                analysisOptions.shading(shading != null ? shading : s.shading()),
                checker, !noShadows && s.shadows(), depth != null && !pathTraced() ? depth : s.maxDepth());
    }

    /** {@code checker} (8 squares), {@code checker:N}, or {@code none}. */
    static int texture(String text) {
        String t = text.trim().toLowerCase(Locale.ROOT);
        if (t.equals("none")) {
            return 0;
        }
        if (t.equals("checker")) {
            return 8;
        }
        if (t.startsWith("checker:")) {
            try {
                int n = Integer.parseInt(t.substring("checker:".length()));
                if (n >= 1 && n <= 10_000) {
                    return n;
                }
            } catch (NumberFormatException e) {
                // fall through to the error below
            }
        }
        throw new IllegalArgumentException("--texture must be checker, checker:N (N = 1..10000) or none, got '" + text + "'");
    }

    private Camera camera(Camera base) {
        Camera c = base;
        if (eye != null || target != null || up != null) {
            Vec3 e = eye != null ? vec("--eye", eye) : base.eye();
            Vec3 t = target != null ? vec("--target", target) : base.target();
            Vec3 u = up != null ? vec("--up", up) : base.up();
            double f = fov != null ? fov : base.fovDegrees();
            return f == 0 ? Camera.orthographic(e, t, u, base.isOrthographic() ? base.orthoWidth()
                    : base.withFov(0).orthoWidth()) : Camera.lookAt(e, t, u, f);
        }
        if (fov != null) {
            c = c.withFov(fov);
        }
        return c;
    }

    /** Refuses an image whose buffers would not fit in the heap (instead of an OutOfMemoryError). */
    static void checkMemory(RenderSettings s) {
        HeapBudget.require(null, s.width() + "x" + s.height() + " pixels",
                Film.bytesFor(s.width(), s.height()) + 12L * s.width() * s.height());
    }

    static Vec3 vec(String option, String text) {
        String[] parts = text.split(",", -1);
        if (parts.length != 3) {
            throw new IllegalArgumentException(option + " must be x,y,z, got '" + text + "'");
        }
        double[] v = new double[3];
        for (int k = 0; k < 3; k++) {
            try {
                v[k] = Double.parseDouble(parts[k].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(option + " must be x,y,z numbers, got '" + text + "'");
            }
            if (!Double.isFinite(v[k])) {
                throw new IllegalArgumentException(option + " must be finite, got '" + text + "'");
            }
        }
        return new Vec3(v[0], v[1], v[2]);
    }

    static int[] ints(String option, String text, int count, String separator) {
        String[] parts = text.trim().split(separator, -1);
        String form = count == 2 && separator.contains("x") ? "WIDTHxHEIGHT" : "x,y";
        if (parts.length != count) {
            throw new IllegalArgumentException(option + " must be " + form + ", got '" + text + "'");
        }
        int[] v = new int[count];
        for (int k = 0; k < count; k++) {
            try {
                v[k] = Integer.parseInt(parts[k].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(option + " must be " + form + " (whole numbers), got '" + text + "'");
            }
        }
        return v;
    }

    private static String statsJson(RenderJob job, RenderSettings s, int threadCount, RenderResult last,
                                    double[] frameMillis) {
        double[] sorted = frameMillis.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        double median = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("width", s.width());
        m.put("height", s.height());
        m.put("spp", s.spp());
        m.put("sampler", s.sampler());
        m.put("threads", threadCount);
        m.put("method", s.method());
        m.put("bvh", s.bvh());
        m.put("tessellate", job.options().tessellate());
        m.put("shading", s.shading());
        m.put("integrator", job.options().path().integrator().label());
        if (job.options().path().integrator() == Integrator.PATH) {
            m.put("pathDepth", job.options().path().maxDepth());
            m.put("samplesPerSecond", round(median > 0 ? (double) s.width() * s.height() * s.spp() / (median / 1e3) : 0));
        }
        if (job.shading().needsCurvature()) {
            m.put("analysisRange", AnalysisRange.of(job));
        }
        m.put("shadows", s.shadows());
        m.put("kernel", job.intersector().options().kernel().description());
        m.put("primaryRays", last.stats().primaryRays());
        m.put("shadowRays", last.stats().shadowRays());
        m.put("secondaryRays", last.stats().secondaryRays());
        m.put("totalRays", last.stats().totalRays());
        m.put("solverCalls", last.stats().work().solverCalls());
        m.put("clipSteps", last.stats().work().clipSteps());
        m.put("patchEvaluations", last.stats().work().evaluations());
        m.put("laneEvaluations", last.stats().work().laneEvaluations());
        m.put("buildMillis", round(job.intersector().buildMillis()));
        m.put("frameMillis", Arrays.stream(frameMillis).map(RenderCommand::round).toArray());
        m.put("renderMillis", round(median));
        m.put("mraysPerSecond", round(median > 0 ? last.stats().totalRays() / (median * 1e3) : 0));
        m.put("subPatches", job.intersector().subPatchCount());
        m.put("bvhNodes", job.intersector().nodeCount());
        m.put("triangles", job.intersector().triangleCount());
        return new Gson().toJson(m);
    }

    private static double round(double v) {
        return Math.round(v * 1000) / 1000.0;
    }
}
