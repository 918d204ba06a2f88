package org.beziertracer.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStream;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.beziertracer.model.io.FilePaths;
import org.beziertracer.intersect.HeapBudget;
import org.beziertracer.intersect.Hit;
import org.beziertracer.geometry.SurfaceCurvature;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.SurfacePoint;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.beziertracer.model.io.AtomicFiles;
import org.beziertracer.model.io.BuiltIns;
import org.beziertracer.model.io.IoReasons;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code trace MODEL_OR_SCENE}: intersects rays with a model or scene and prints one CSV line a
 * ray: {@code index,hit,t,patch,u,v,x,y,z,nx,ny,nz}. When the scene has planes or spheres, a last
 * column {@code object} says what was hit ({@code patch 3}, {@code plane 0}, {@code sphere 1}),
 * and {@code patch} is empty for planes and spheres. Rays are read one a line as
 * {@code ox oy oz dx dy dz} ({@code #} comments and blank lines skipped), or generated with
 * {@code --random N}.
 */
@Command(name = "trace", mixinStandardHelpOptions = true,
        description = "Intersects rays (ox oy oz dx dy dz, one a line) with a model or scene; prints CSV hits.")
final class TraceCommand implements Callable<Integer> {

    static final String HEADER = "index,hit,t,patch,u,v,x,y,z,nx,ny,nz";

    private static final String[] KINDS = {"patch", "plane", "sphere", "mesh"};

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MODEL_OR_SCENE", descriptionKey = CliText.INPUT)
    String model;

    @Option(names = "--method", paramLabel = "METHOD", defaultValue = "clipping",
            completionCandidates = MethodLabels.class,
            description = "ray-patch solver: ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE})")
    String method;

    @Option(names = "--no-bvh", description = "no sub-patch BVH: test whole patches in a list")
    boolean noBvh;

    @Option(names = "--tessellate", paramLabel = "K", defaultValue = "0",
            description = "intersect a uniform KxK triangle tessellation of every patch instead of the exact "
                    + "surface (0 = exact, the default); normals interpolated from the analytic vertex normals")
    int tessellate;

    @Option(names = {"-i", "--input"}, paramLabel = "RAYS", description = "ray file (default: standard input)")
    Path input;

    @Option(names = {"-o", "--output"}, paramLabel = "HITS", description = "CSV output, written atomically: a failed or stopped trace leaves the old file (default: standard output)")
    Path output;

    @Option(names = "--random", paramLabel = "N", description = "instead of reading rays, trace N random rays "
            + "from a sphere around the model toward points in its bounding box")
    Integer random;

    @Option(names = "--seed", defaultValue = "1", description = "seed for --random (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--curvature", description = "add the curvature at each hit: columns gaussian, mean, k1, k2 "
            + "(principal curvatures, k1 ≥ k2, signed against the reported normal: positive where the surface bends "
            + "toward it) and the principal directions d1x..d1z, d2x..d2z (unit; d2 = n × d1)")
    boolean curvature;

    @Option(names = "--stats", description = "print build and trace timings to standard error")
    boolean stats;

    /** Standard output is checked for failed writes every 4096 rays. */
    private static final long STDOUT_CHECK_MASK = 4095;

    /** Rays and hits traced so far, and the time spent in the intersector. */
    private long rays, hits, traceNanos;

    @Override
    public Integer call() throws IOException {
        Method m = Method.parse(method);
        if (random != null && (random < 0 || random > 100_000_000)) {
            throw new IllegalArgumentException("--random must be 0..100000000, got " + random);
        }
        if (random != null && input != null) {
            throw new IllegalArgumentException("--random N and -i RAYS exclude each other: trace N random rays, "
                    + "or the rays of the file");
        }
        if (input != null && input.toString().isEmpty()) {
            throw new IllegalArgumentException("-i: the ray file name is empty");
        }
        if (output != null && output.toString().isEmpty()) {
            throw new IllegalArgumentException("-o: the output file name is empty");
        }
        refuseOutputOverInput();
        Scene scene = ReadNotes.show(SceneFiles.load(model, Method::parse), spec.commandLine().getErr()).scene();
        boolean objects = !scene.planes().isEmpty() || !scene.spheres().isEmpty() || !scene.meshes().isEmpty();
        IntersectOptions io = IntersectOptions.defaults().withMethod(m).withBvh(!noBvh).withTessellate(tessellate);
        HeapBudget.require(model, scene, io);
        SceneIntersector si = SceneIntersector.build(scene, io);
        TraceContext ctx = si.newContext();
        try (RaySource source = random != null ? new RandomRays(aimBox(scene), random, seed)
                : new RayFile(openInput(), input == null ? "stdin" : input.toString())) {
            if (output == null) {
                Writer out = new BufferedWriter(spec.commandLine().getOut(), 1 << 16);
                trace(si, ctx, source, objects, out);
                out.flush(); // standard output stays open
            } else {
                // Like the PNGs: a failed or killed trace leaves the old file as it was
                AtomicFiles.write(output, out -> trace(si, ctx, source, objects, out));
            }
        }
        if (stats) {
            double ms = traceNanos / 1e6;
            spec.commandLine().getErr().println(String.format(Locale.ROOT,
                    "trace: %d rays, %d hits, method %s, bvh %s, %d %s, %d BVH nodes, depth %d, "
                            + "build %.2f ms, trace %.1f ms, %.0f rays/s, %.2f leaf tests and %.2f clip steps per ray",
                    rays, hits, tessellate > 0 ? "tessellated " + tessellate + "x" + tessellate : m.label(), !noBvh,
                    si.primitiveCount(), tessellate > 0 ? "triangles" : "sub-patches", si.nodeCount(), si.depth(),
                    si.buildMillis(), ms, rays / Math.max(ms, 1e-9) * 1000,
                    ctx.solverCalls / Math.max(1.0, rays), ctx.clipIterations / Math.max(1.0, rays)));
        }
        return 0;
    }

    /** Traces every ray of {@code source}, writing the header and one CSV line a ray to {@code out}. */
    private void trace(SceneIntersector si, TraceContext ctx, RaySource source, boolean objects, Writer out)
            throws IOException {
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double[] bend = curvature ? new double[SurfaceCurvature.LENGTH] : null;
        out.write((objects ? HEADER + ",object" : HEADER) + (curvature ? "," + CURVATURE_HEADER : ""));
        out.write('\n');
        StringBuilder line = new StringBuilder(256);
        double[] ray = new double[6];
        while (source.next(ray)) {
            long t0 = System.nanoTime();
            boolean found = si.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0,
                    Double.POSITIVE_INFINITY, hit);
            if (found) {
                si.surfacePoint(ctx, hit, sp);
                if (curvature) {
                    si.curvature(ctx, hit, sp, bend);
                }
            }
            traceNanos += System.nanoTime() - t0;
            if (found) {
                hits++;
            }
            csvLine(line, rays, found ? hit : null, sp, objects);
            if (curvature) {
                curvatureColumns(line, found ? bend : null);
            }
            line.append('\n');
            out.append(line);
            rays++;
            if (output == null && (rays & STDOUT_CHECK_MASK) == 0) {
                out.flush();
                if (StandardOutput.closedPipe(spec.commandLine().getOut())) {
                    return; // the reader left (| head): stop quietly, as Unix tools do
                }
                String failed = StandardOutput.failure(spec.commandLine().getOut());
                if (failed != null) { // stop early: a full disk takes no more
                    throw new IOException(failed);
                }
            }
        }
    }

    /**
     * Refuses {@code -o} naming the ray file or the model: the hits would replace what is being
     * read (only files that exist can be the same).
     */
    private void refuseOutputOverInput() {
        if (output == null) {
            return;
        }
        if (input != null && sameFile(input, output)) {
            throw new IllegalArgumentException("-o " + FilePaths.text(output) + " is the ray file -i " + FilePaths.text(input)
                    + ": the hits would replace the rays; choose another output file");
        }
        Path modelFile = modelPath();
        if (modelFile != null && sameFile(modelFile, output)) {
            throw new IllegalArgumentException("-o " + FilePaths.text(output) + " is the model " + model
                    + ": the hits would replace it; choose another output file");
        }
    }

    /** The model argument as a path, or null when it names a built-in or no valid path. */
    private Path modelPath() {
        if (BuiltIns.find(model).isPresent()) {
            return null;
        }
        return FilePaths.find(model).orElse(null);
    }

    /** True when both files exist and are one file (same path, a link, a hard link). */
    static boolean sameFile(Path a, Path b) {
        try {
            return Files.exists(a) && Files.exists(b) && Files.isSameFile(a, b);
        } catch (IOException e) {
            return false;
        }
    }

    /** One CSV line (without its newline) for ray number {@code ray}: its hit, or empty fields for a miss. */
    private static void csvLine(StringBuilder line, long ray, Hit hit, SurfacePoint sp, boolean objects) {
        line.setLength(0);
        line.append(ray).append(',');
        if (hit != null) {
            line.append("1,").append(hit.t).append(',');
            if (hit.kind == Hit.PATCH) {
                line.append(hit.index);
            }
            line.append(',')
                    .append(hit.u).append(',').append(hit.v).append(',')
                    .append(sp.px).append(',').append(sp.py).append(',').append(sp.pz).append(',')
                    .append(sp.nx).append(',').append(sp.ny).append(',').append(sp.nz);
        } else {
            line.append("0,,,,,,,,,,");
        }
        if (objects) {
            line.append(',');
            if (hit != null) {
                line.append(KINDS[hit.kind]).append(' ').append(hit.index);
            }
        }
    }

    static final String CURVATURE_HEADER = "gaussian,mean,k1,k2,d1x,d1y,d1z,d2x,d2y,d2z";

    /** The curvature columns of a hit ({@link SceneIntersector#curvature}), or empty ones for a miss. */
    private static void curvatureColumns(StringBuilder line, double[] c) {
        if (c == null) {
            line.append(",,,,,,,,,,");
            return;
        }
        line.append(',').append(c[SurfaceCurvature.GAUSSIAN]).append(',').append(c[SurfaceCurvature.MEAN])
                .append(',').append(c[SurfaceCurvature.K1]).append(',').append(c[SurfaceCurvature.K2]);
        for (int k = 0; k < 3; k++) {
            line.append(',').append(c[SurfaceCurvature.D1 + k]);
        }
        for (int k = 0; k < 3; k++) {
            line.append(',').append(c[SurfaceCurvature.D2 + k]);
        }
    }

    private InputStream openInput() throws IOException {
        if (input == null) {
            return System.in;
        }
        if (Files.isDirectory(input)) {
            throw new IOException(FilePaths.text(input) + ": is a folder, not a ray file");
        }
        if (!Files.exists(input)) {
            throw new IOException(FilePaths.text(input) + ": no such ray file");
        }
        try { // a file, or a device or pipe (/dev/stdin, <(…)): read as it comes
            return Files.newInputStream(input);
        } catch (IOException e) {
            throw new IOException(FilePaths.text(input) + ": cannot read: " + IoReasons.of(e));
        }
    }

    /** The box random rays aim into: the patches' control points, the meshes and the spheres. */
    static Aabb aimBox(Scene scene) {
        Aabb box = scene.bounds();
        for (Sphere s : scene.spheres()) {
            double r = s.radius();
            box = box.union(s.center().add(new Vec3(-r, -r, -r))).union(s.center().add(new Vec3(r, r, r)));
        }
        if (box.isEmpty()) {
            throw new IllegalArgumentException("--random needs patches, meshes or spheres to aim at; this scene has"
                    + " only planes");
        }
        return box;
    }
}
