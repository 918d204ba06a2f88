package org.beziertracer.cli;

import java.io.PrintWriter;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Callable;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;

import org.beziertracer.intersect.HeapBudget;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code info [--accel] MODEL_OR_SCENE}: prints patch count, the degree histogram, the rational and
 * trimmed patches and the free-form surfaces they came from ({@link SurfaceSummary}), the
 * control-point bounding box and, for a scene, its planes, spheres and lights.
 * The reader's notes follow the model line, one {@code note: …} each ({@link ReadNotes}).
 * Without {@code --accel} that is all: the file's summary, as soon as it is read (a 10 MB CAD
 * file in well under a second, where splitting it and building its BVH took as long again).
 * With {@code --accel} the command also splits the patches and builds the BVH of the default
 * settings (after the heap check of {@link HeapBudget}) and prints their figures:
 * <pre>
 * model: teapot-room
 * patches: 32
 * degrees: 3x3 (32)
 * rational patches: 0
 * trimmed patches: 0
 * surfaces: 0
 * control-point bounds: x[-120,141] y[-80,80] z[0,120]
 * objects: 1 plane, 2 spheres, 1 light
 * sub-patches: 1566
 * bvh: 3131 nodes, depth 14
 * build: 12.3 ms (split + BVH)
 * acceleration data: 1,234,567 bytes (1.2 MB, 38,580 a patch): sub-patches 1,100,000, BVH 134,567
 * </pre>
 * Degrees are listed as {@code nxm (count)}, sorted by u then v degree; the objects line appears
 * when there are any. The last four lines come with {@code --accel} only; the last is the heap the acceleration data holds (the sub-patch table
 * and the BVH of the default settings), not counting the model's patches. Anything {@link SceneFiles#load} opens is accepted. A file that cannot be
 * read ends the command with one error line and exit code 1 (see {@link CliErrors}).
 */
@Command(name = "info", mixinStandardHelpOptions = true,
        description = "Prints patch count, degrees, rational and trimmed patches, free-form surfaces and their "
                + "Bézier pieces and control-point bounding box of a model or scene; with --accel also its "
                + "sub-patch and BVH figures (with the bytes they hold).")
final class InfoCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "MODEL_OR_SCENE", descriptionKey = CliText.INPUT)
    String model;

    @Option(names = "--accel", description = "also split the patches and build the BVH, and print their figures "
            + "(sub-patches, nodes, depth, build time, bytes held); takes as long again as the read on a big model")
    boolean accel;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        SceneDocument doc = SceneFiles.load(model, Method::parse);
        Scene scene = doc.scene();
        PrintWriter out = spec.commandLine().getOut();
        out.println("model: " + model);
        ReadNotes.show(doc, out);
        out.println("patches: " + scene.patchCount());
        out.println("degrees: " + degreeHistogram(scene));
        SurfaceSummary.lines(scene).forEach(out::println);
        out.println("control-point bounds: " + (scene.patchCount() == 0 ? "none" : scene.controlBounds()));
        if (!scene.meshes().isEmpty()) {
            out.println("meshes: " + count(scene.meshes().size(), "mesh") + ", " + scene.triangleCount()
                    + (scene.triangleCount() == 1 ? " triangle" : " triangles") + ", bounds " + meshBounds(scene));
        }
        if (!scene.planes().isEmpty() || !scene.spheres().isEmpty() || !scene.lights().isEmpty()) {
            out.println("objects: " + count(scene.planes().size(), "plane") + ", "
                    + count(scene.spheres().size(), "sphere") + ", " + count(scene.lights().size(), "light"));
        }
        if (!accel) {
            out.flush();
            return 0;
        }
        HeapBudget.require(model, scene, IntersectOptions.defaults());
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        out.println("sub-patches: " + si.subPatchCount());
        if (!scene.meshes().isEmpty() || !scene.spheres().isEmpty()) {
            out.println("bvh primitives: " + si.primitiveCount() + " (sub-patches, mesh triangles and spheres)");
        }
        out.println("bvh: " + si.nodeCount() + " nodes, depth " + si.depth());
        out.println(String.format(java.util.Locale.ROOT, "build: %.1f ms (split + BVH)", si.buildMillis()));
        out.println(heldLine(si, scene.patchCount()));
        out.flush();
        return 0;
    }

    /** The box of every mesh's vertices. */
    private static org.beziertracer.math.Aabb meshBounds(Scene scene) {
        org.beziertracer.math.Aabb box = org.beziertracer.math.Aabb.EMPTY;
        for (var m : scene.meshes()) {
            box = box.union(m.bounds());
        }
        return box;
    }

    /**
     * {@code acceleration data: 1,234,567 bytes (1.2 MB, 38,580 a patch): sub-patches 1,100,000,
     * BVH 134,567}: the heap the built structures hold, not counting the model's own patches.
     */
    static String heldLine(SceneIntersector si, int patchCount) {
        long leaves = si.leafBytes(), nodes = si.accelBytes(), total = leaves + nodes;
        return String.format(java.util.Locale.ROOT, "acceleration data: %,d bytes (%.1f MB, %,d a patch): "
                + "sub-patches %,d, BVH %,d", total, total / (1024.0 * 1024.0),
                patchCount == 0 ? 0 : total / patchCount, leaves, nodes);
    }

    private static String count(int n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }

    /** {@code "3x3 (30), 1x2 (2)"}-style histogram, sorted by u degree then v degree. */
    static String degreeHistogram(Scene scene) {
        Map<Integer, Integer> counts = new TreeMap<>();
        for (BezierPatch p : scene.patches()) {
            counts.merge(p.degreeU() * 100 + p.degreeV(), 1, Integer::sum);
        }
        StringBuilder sb = new StringBuilder();
        for (Map.Entry<Integer, Integer> e : counts.entrySet()) {
            if (sb.length() > 0) {
                sb.append(", ");
            }
            sb.append(e.getKey() / 100).append('x').append(e.getKey() % 100).append(" (").append(e.getValue()).append(")");
        }
        return sb.toString();
    }
}
