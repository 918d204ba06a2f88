package org.beziertracer.model.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraPath;
import org.beziertracer.model.RenderSettings;

/**
 * Job files (issue 37, {@code docs/jobs.md}): one JSON document with {@code "job": 1} naming a scene
 * (built-in, path relative to the job file, or inline), render settings, sampler seed, camera path,
 * frames and output pattern. Read strictly like scene files ({@link SceneFiles}); every bad value fails
 * with one line {@code job.json: camera.turntable.frames: expected …}, before anything renders.
 *
 * <p>Stateless and thread-safe.
 */
public final class JobFiles {
    private JobFiles() {}

    /** The job-file format version this program reads. */
    public static final int VERSION = 1;
    /** Most frames in one job. */
    public static final int MAX_FRAMES = 1_000_000;

    /**
     * True when {@code nameOrPath} is a {@code .json} file whose top level has a {@code "job"} key (a
     * file that cannot be read or parsed, or is larger than a scene file may be, is left to the scene
     * reader, which names the problem).
     */
    public static boolean isJob(String nameOrPath) {
        if (!nameOrPath.toLowerCase(Locale.ROOT).endsWith(".json")) {
            return false;
        }
        try {
            Path file = Path.of(nameOrPath);
            if (!Files.isRegularFile(file) || Files.size(file) > ReadLimits.DEFAULT.bytesInMemory()) {
                return false;
            }
            JsonNode root = JsonNode.parse(Files.readString(file), nameOrPath);
            return root.keys().contains("job");
        } catch (IOException | IllegalArgumentException e) {
            return false;
        }
    }

    /**
     * Reads a job file and the scene it names.
     *
     * @param methods checks the settings' method name as {@link SceneFiles#load(String, java.util.function.Consumer)}
     * @throws ModelFormatException one line naming the file (and the key) for any problem
     */
    public static JobDocument load(Path file, java.util.function.Consumer<String> methods) {
        String fileName = file.toString();
        if (!Files.isRegularFile(file)) {
            throw new ModelFormatException(fileName, Files.isDirectory(file) ? "is a folder, not a file" : "no such file");
        }
        String json;
        try (InputStream in = Files.newInputStream(file)) {
            json = new TextSource(in, fileName, ReadLimits.DEFAULT, Files.size(file)).readAll("a job file");
        } catch (IOException e) {
            throw new ModelFormatException(fileName, "cannot read: " + IoReasons.of(e));
        }
        return parse(json, fileName, file.toAbsolutePath().getParent(), methods);
    }

    /** Parses job-file text; relative paths resolve against {@code baseDir}. */
    public static JobDocument parse(String json, String fileName, Path baseDir,
                                    java.util.function.Consumer<String> methods) {
        JsonNode root = JsonNode.parse(json, fileName);
        root.keys();
        checkVersion(root);
        root.object("job", "description", "scene", "settings", "seed", "camera", "frames", "output");
        if (root.has("description")) {
            root.get("description").asString();
        }
        SceneDocument scene = scene(root.require("scene"), baseDir);
        RenderSettings settings = root.has("settings")
                ? SceneReader.settings(root.get("settings"), scene.settings(), TRACER_KEYS) : scene.settings();
        JobTracer tracer = root.has("settings") ? tracer(root.get("settings")) : JobTracer.NONE;
        try {
            methods.accept(settings.method());
        } catch (IllegalArgumentException e) {
            throw (root.has("settings") && root.get("settings").has("method") ? root.get("settings").get("method") : root)
                    .error(Echo.cutQuoted(e.getMessage()));
        }
        long seed = root.has("seed") ? root.get("seed").asInt() : 1;
        CameraPath camera = root.has("camera") ? camera(root.get("camera")) : null;
        int first = camera == null ? 1 : camera.firstFrame(), last = camera == null ? 1 : camera.lastFrame();
        if (root.has("frames")) {
            JsonNode f = root.get("frames");
            int[] range = frames(f);
            first = range[0];
            last = range[1];
        }
        Path output = null;
        if (root.has("output")) {
            output = output(root.get("output"), baseDir, last > first);
        }
        return new JobDocument(new SceneDocument(scene.scene(), settings, scene.notes()), tracer, seed, camera, first, last,
                output);
    }

    /** The integrator keys of a job's {@code settings}, beside a scene's render keys. */
    private static final String[] TRACER_KEYS = {"integrator", "pathDepth", "clamp", "exposure"};

    /** The integrator keys of {@code settings}; an error names the key that is wrong. */
    private static JobTracer tracer(JsonNode settings) {
        JsonNode i = settings.get("integrator"), d = settings.get("pathDepth"), c = settings.get("clamp"),
                e = settings.get("exposure");
        String integrator = i == null ? null : SceneReader.build(i, () -> new JobTracer(i.asString(), null, null, null))
                .integrator();
        Integer depth = d == null ? null : SceneReader.build(d, () -> new JobTracer("path", d.asInt(), null, null))
                .pathDepth();
        Double clamp = c == null ? null : SceneReader.build(c, () -> new JobTracer("path", null, c.asDouble(), null))
                .clamp();
        Double exposure = e == null ? null
                : SceneReader.build(e, () -> new JobTracer("path", null, null, e.asDouble())).exposure();
        for (JsonNode n : new JsonNode[] {d, c, e}) {
            if (n != null && !"path".equals(integrator)) {
                throw n.error("needs \"integrator\": \"path\" in the same settings");
            }
        }
        return new JobTracer(integrator, depth, clamp, exposure);
    }

    private static void checkVersion(JsonNode root) {
        JsonNode v = root.get("job");
        if (v == null) {
            throw root.error("missing key \"job\" (a job file starts with \"job\": " + VERSION + ")");
        }
        if (!v.isNumber() || v.asDouble() != VERSION) {
            throw v.error("unsupported job version " + v.text() + " (this program reads version " + VERSION + ")");
        }
    }

    /** A built-in name or a path (relative to the job file), or an inline scene object. */
    private static SceneDocument scene(JsonNode s, Path baseDir) {
        if (s.isString()) {
            String name = s.asString();
            if (BuiltIns.find(name).isPresent()) {
                return SceneFiles.load(name);
            }
            Path p;
            try {
                p = Path.of(name);
            } catch (InvalidPathException e) {
                throw s.error("not a valid file name: " + Echo.quote(name));
            }
            if (!p.isAbsolute() && baseDir != null) {
                p = baseDir.resolve(p);
            }
            if (!Files.isRegularFile(p)) {
                throw s.error("not a built-in name and no such file: " + Echo.quote(name));
            }
            return SceneFiles.load(p.toString());
        }
        return new SceneReader(baseDir, ReadLimits.DEFAULT).read(s);
    }

    private static CameraPath camera(JsonNode c) {
        c.object("turntable", "keyframes");
        if (c.has("turntable") == c.has("keyframes")) {
            throw c.error("expected exactly one of \"turntable\" and \"keyframes\"");
        }
        if (c.has("turntable")) {
            JsonNode t = c.get("turntable").object("frames", "axis", "center", "degrees");
            JsonNode n = t.require("frames");
            int frames = n.asInt();
            if (frames < 1 || frames > MAX_FRAMES) {
                throw n.expected("a frame count from 1 to " + MAX_FRAMES);
            }
            Vec3 axis = t.has("axis") ? vec(t.get("axis")) : Vec3.Z;
            if (axis.length() == 0 || !Double.isFinite(axis.length())) {
                throw t.get("axis").expected("a nonzero direction of finite length");
            }
            Vec3 center = t.has("center") ? vec(t.get("center")) : null;
            double degrees = t.has("degrees") ? t.get("degrees").asDouble() : 360;
            return new CameraPath.Turntable(frames, axis, center, degrees);
        }
        JsonNode list = c.get("keyframes");
        List<JsonNode> items = list.array();
        if (items.isEmpty()) {
            throw list.expected("at least one keyframe");
        }
        List<CameraPath.Keyframe> keys = new ArrayList<>();
        for (JsonNode k : items) {
            k.object("frame", "eye", "target", "up", "fov");
            JsonNode f = k.require("frame");
            int frame = f.asInt();
            if (frame < 0 || frame > MAX_FRAMES) {
                throw f.expected("a frame number from 0 to " + MAX_FRAMES);
            }
            if (!keys.isEmpty() && frame <= keys.get(keys.size() - 1).frame()) {
                throw f.error("keyframes must be in increasing frame order, found " + frame + " after "
                        + keys.get(keys.size() - 1).frame());
            }
            Vec3 eye = vec(k.require("eye")), target = vec(k.require("target"));
            Vec3 up = k.has("up") ? vec(k.get("up")) : Vec3.Z;
            double fov = k.has("fov") ? k.get("fov").asDouble() : SceneFiles.DEFAULT_FOV;
            if (!(fov > 0 && fov < 179)) {
                throw k.get("fov").expected("a field of view above 0 and below 179 degrees");
            }
            keys.add(SceneReader.build(k, () -> new CameraPath.Keyframe(frame, eye, target, up, fov)));
        }
        return new CameraPath.Keyframes(keys);
    }

    private static int[] frames(JsonNode f) {
        int[] range;
        if (f.isNumber()) {
            int a = f.asInt();
            range = new int[] {a, a};
        } else {
            try {
                range = FramePattern.range(f.asString(), "frames");
            } catch (IllegalArgumentException e) {
                throw f.error(e.getMessage().substring("frames ".length()));
            }
        }
        if (range[0] < 0 || range[1] > MAX_FRAMES) {
            throw f.expected("frames from 0 to " + MAX_FRAMES);
        }
        return range;
    }

    private static Path output(JsonNode o, Path baseDir, boolean manyFrames) {
        String text = o.asString();
        Path p;
        try {
            p = Path.of(text);
        } catch (InvalidPathException e) {
            throw o.error("not a valid file name: " + Echo.quote(text));
        }
        if (p.getFileName() == null || !p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png")) {
            throw o.error("the output must be a .png file name, found " + Echo.quote(text));
        }
        if (manyFrames && !FramePattern.numbered(p)) {
            throw o.error("several frames need a # in the file name for the frame number, found " + Echo.quote(text));
        }
        return p.isAbsolute() || baseDir == null ? p : baseDir.resolve(p);
    }

    private static Vec3 vec(JsonNode n) {
        double[] v = n.asNumbers(3);
        return new Vec3(v[0], v[1], v[2]);
    }
}
