package org.beziertracer.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.Callable;

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
import org.beziertracer.model.io.Echo;
import org.beziertracer.model.io.IoReasons;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;
import org.beziertracer.model.io.TextSource;

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

    @Option(names = {"-o", "--output"}, paramLabel = "HITS", description = "CSV output (default: standard output)")
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

    @Override
    public Integer call() throws IOException {
        Method m = Method.parse(method);
        if (random != null && (random < 0 || random > 100_000_000)) {
            throw new IllegalArgumentException("--random must be 0..100000000, got " + random);
        }
        Scene scene = ReadNotes.show(SceneFiles.load(model, Method::parse), spec.commandLine().getErr()).scene();
        boolean objects = !scene.planes().isEmpty() || !scene.spheres().isEmpty() || !scene.meshes().isEmpty();
        IntersectOptions io = IntersectOptions.defaults().withMethod(m).withBvh(!noBvh).withTessellate(tessellate);
        HeapBudget.require(model, scene, io);
        SceneIntersector si = SceneIntersector.build(scene, io);
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double[] bend = curvature ? new double[SurfaceCurvature.LENGTH] : null;
        long rays = 0, hits = 0;
        long traceNanos = 0;
        try (Writer out = openOutput()) {
            out.write((objects ? HEADER + ",object" : HEADER) + (curvature ? "," + CURVATURE_HEADER : ""));
            out.write('\n');
            StringBuilder line = new StringBuilder(256);
            double[] ray = new double[6];
            RaySource source = random != null ? new RandomRays(aimBox(scene), random, seed)
                    : new RayFile(openInput(), input == null ? "stdin" : input.toString());
            try (source) {
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
                }
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

    private Writer openOutput() throws IOException {
        if (output == null) {
            return new BufferedWriter(spec.commandLine().getOut(), 1 << 16) {
                @Override
                public void close() throws IOException {
                    flush(); // do not close System.out
                }
            };
        }
        if (output.getParent() != null && !Files.isDirectory(output.getParent())) {
            throw new IOException(output + ": cannot write: the folder " + output.getParent() + " does not exist");
        }
        try {
            return Files.newBufferedWriter(output, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IOException(output + ": cannot write: " + IoReasons.of(e));
        }
    }

    private InputStream openInput() throws IOException {
        if (input == null) {
            return System.in;
        }
        if (!Files.isRegularFile(input)) {
            throw new IOException(input + ": no such ray file");
        }
        return Files.newInputStream(input);
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

    /** A stream of rays. */
    interface RaySource extends AutoCloseable {
        boolean next(double[] ray) throws IOException;

        @Override
        void close() throws IOException;
    }

    /** Rays from text, one a line; errors name the source and line. */
    static final class RayFile implements RaySource {
        private final InputStream in;
        private final TextSource text;
        private final String name;

        /** Rays of {@code in} (closed by {@link #close()} unless it is standard input). */
        RayFile(InputStream in, String name) {
            this.in = in;
            this.text = new TextSource(in, name);
            this.name = name;
        }

        @Override
        public boolean next(double[] ray) throws IOException {
            String line;
            while ((line = text.readLine()) != null) {
                int lineNumber = text.lineNumber();
                int hash = line.indexOf('#');
                String text = (hash >= 0 ? line.substring(0, hash) : line).trim();
                if (text.isEmpty()) {
                    continue;
                }
                String[] parts = text.split("\\s+");
                if (parts.length != 6) {
                    throw new IllegalArgumentException(name + ":" + lineNumber + ": expected 6 numbers "
                            + "'ox oy oz dx dy dz', found " + parts.length + " fields");
                }
                for (int k = 0; k < 6; k++) {
                    try {
                        ray[k] = Double.parseDouble(parts[k]);
                    } catch (NumberFormatException e) {
                        throw new IllegalArgumentException(name + ":" + lineNumber + ": expected a number for "
                                + "oxoyozdxdydz".substring(2 * k, 2 * k + 2) + ", found " + Echo.quote(parts[k]));
                    }
                    if (!Double.isFinite(ray[k])) {
                        throw new IllegalArgumentException(name + ":" + lineNumber + ": "
                                + "oxoyozdxdydz".substring(2 * k, 2 * k + 2) + " must be finite, found "
                                + Echo.quote(parts[k]));
                    }
                }
                if (ray[3] == 0 && ray[4] == 0 && ray[5] == 0) {
                    throw new IllegalArgumentException(name + ":" + lineNumber + ": the ray direction is zero");
                }
                double big = Math.max(Math.abs(ray[3]), Math.max(Math.abs(ray[4]), Math.abs(ray[5])));
                if (big < 1e-300 || big > 1e300) {
                    throw new IllegalArgumentException(name + ":" + lineNumber + ": the ray direction's length must be "
                            + "between 1e-300 and 1e300, found a largest component of " + big);
                }
                return true;
            }
            return false;
        }

        @Override
        public void close() throws IOException {
            if (in != System.in) {
                in.close();
            }
        }
    }

    /** Seeded random rays from a sphere around the box toward points inside it. */
    static final class RandomRays implements RaySource {
        private final Aabb box;
        private final Random rnd;
        private long left;

        RandomRays(Aabb box, long count, long seed) {
            this.box = box;
            this.rnd = new Random(seed);
            this.left = count;
        }

        @Override
        public boolean next(double[] ray) {
            if (left-- <= 0) {
                return false;
            }
            double r = box.diagonal();
            double cx = box.center().x(), cy = box.center().y(), cz = box.center().z();
            double gx = rnd.nextGaussian(), gy = rnd.nextGaussian(), gz = rnd.nextGaussian();
            double len = Math.sqrt(gx * gx + gy * gy + gz * gz);
            ray[0] = cx + r * gx / len;
            ray[1] = cy + r * gy / len;
            ray[2] = cz + r * gz / len;
            double tx = box.minX() + rnd.nextDouble() * (box.maxX() - box.minX());
            double ty = box.minY() + rnd.nextDouble() * (box.maxY() - box.minY());
            double tz = box.minZ() + rnd.nextDouble() * (box.maxZ() - box.minZ());
            ray[3] = tx - ray[0];
            ray[4] = ty - ray[1];
            ray[5] = tz - ray[2];
            return true;
        }

        @Override
        public void close() {}
    }
}
