package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.beziertracer.math.Bounds;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Placement;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link SubPatchTable#build(List, SplitOptions, List)} with instances: a model used several times
 * by similarities is split once (the work is counted), its placed patches' leaves hold their
 * surface as a fresh split's do, and a placement that is not a similarity splits its patches itself.
 */
class InstancedSplitTest {

    /** {@code p ↦ s·R·p + t}, R a rotation about z by {@code degrees} then about x by {@code tilt}; s per axis. */
    record Affine(double degrees, double tilt, double[] scale, double[] shift) implements Placement {
        @Override
        public void mapPoints(double[] xyz, int offset, int count) {
            double c = Math.cos(Math.toRadians(degrees)), s = Math.sin(Math.toRadians(degrees));
            double ct = Math.cos(Math.toRadians(tilt)), st = Math.sin(Math.toRadians(tilt));
            for (int i = offset; i < offset + 3 * count; i += 3) {
                double x = scale[0] * xyz[i], y = scale[1] * xyz[i + 1], z = scale[2] * xyz[i + 2];
                double x1 = c * x - s * y, y1 = s * x + c * y;
                double y2 = ct * y1 - st * z, z2 = st * y1 + ct * z;
                xyz[i] = x1 + shift[0];
                xyz[i + 1] = y2 + shift[1];
                xyz[i + 2] = z2 + shift[2];
            }
        }

        @Override
        public boolean similarity() {
            return Math.abs(scale[0]) == Math.abs(scale[1]) && Math.abs(scale[1]) == Math.abs(scale[2]);
        }

        static Affine shift(double x, double y, double z) {
            return new Affine(0, 0, new double[] {1, 1, 1}, new double[] {x, y, z});
        }
    }

    static List<BezierPatch> placed(List<BezierPatch> model, Placement placement) {
        List<BezierPatch> out = new ArrayList<>();
        for (BezierPatch p : model) {
            double[] net = p.copyNet();
            placement.mapPoints(net, 0, net.length / 3);
            out.add(p.withNet(net));
        }
        return out;
    }

    static Scene scene(List<BezierPatch> model, Placement... uses) {
        Scene.Builder b = Scene.builder();
        for (Placement u : uses) {
            b.addInstance(model, placed(model, u), u, 0);
        }
        return b.build();
    }

    private static SubPatchTable table(Scene scene) {
        return SubPatchTable.build(scene.patches(), SplitOptions.defaults(), scene.instances());
    }

    @Test
    void aModelUsedThreeTimesIsSplitOnceAndANonUniformScaleSplitsItsOwn() {
        List<BezierPatch> teapot = Models.teapot().patches();
        Scene three = scene(teapot, Affine.shift(0, 0, 0), Affine.shift(10, 0, 0),
                new Affine(30, 20, new double[] {2, 2, -2}, new double[] {0, 10, 0}));
        assertEquals(3, three.instances().size());
        assertEquals(32, table(three).splitPatches, "one split of the model for three uses");

        Scene stretched = scene(teapot, Affine.shift(0, 0, 0), new Affine(0, 0, new double[] {1, 3, 1}, new double[3]));
        assertEquals(64, table(stretched).splitPatches, "the model once, and the stretched use's 32 patches themselves");

        Scene flat = Scene.builder().patches(three.patches()).build();
        assertEquals(96, table(flat).splitPatches, "no instances: every patch split");
    }

    @Test
    void aTranslatedUseGetsTheLeavesOfAFreshSplitUpToRounding() {
        List<BezierPatch> teapot = Models.teapot().patches();
        Scene scene = scene(teapot, Affine.shift(0, 0, 0), Affine.shift(64, -32, 16));
        SubPatchTable shared = table(scene);
        SubPatchTable fresh = table(Scene.builder().patches(scene.patches()).build());
        assertEquals(fresh.count, shared.count, "as many leaves");
        assertArrayEquals(fresh.boxes, shared.boxes, "the same parameter boxes");
        double size = scene.controlBounds().diagonal();
        for (int s = 0; s < fresh.count; s++) {
            int len = 3 * (fresh.degreeU[s] + 1) * (fresh.degreeV[s] + 1);
            for (int i = 0; i < len; i++) {
                assertEquals(fresh.nets[fresh.netOffset[s] + i], shared.nets[shared.netOffset[s] + i], 1e-12 * size,
                        "leaf " + s + " point coordinate " + i);
            }
        }
    }

    @Test
    void everyLeafOfARotatedScaledUseHoldsItsPiecesOfTheSurface() {
        List<BezierPatch> teapot = Models.teapot().patches();
        Affine turn = new Affine(37, -61, new double[] {0.75, -0.75, 0.75}, new double[] {3, -4, 5});
        Scene scene = scene(teapot, Affine.shift(0, 0, 0), turn);
        SubPatchTable t = table(scene);
        double size = scene.controlBounds().diagonal();
        double[] box = new double[6], point = new double[3], scratch = new double[64 * 3];
        int checked = 0;
        for (int s = t.firstOf[32]; s < t.count; s++) {
            BezierPatch patch = scene.patches().get(t.parent[s]);
            double[] net = patch.copyNet();
            int n = patch.degreeU(), m = patch.degreeV();
            Bounds.ofPoints(t.nets, t.netOffset[s], (t.degreeU[s] + 1) * (t.degreeV[s] + 1), box);
            for (int i = 0; i <= 4; i++) {
                for (int j = 0; j <= 4; j++) {
                    double u = t.boxes[4 * s] + (t.boxes[4 * s + 1] - t.boxes[4 * s]) * i / 4;
                    double v = t.boxes[4 * s + 2] + (t.boxes[4 * s + 3] - t.boxes[4 * s + 2]) * j / 4;
                    DeCasteljau.evaluate(net, 0, n, m, 3, u, v, point, 0, scratch);
                    for (int a = 0; a < 3; a++) {
                        assertTrue(point[a] >= box[a] - 1e-12 * size && point[a] <= box[3 + a] + 1e-12 * size,
                                "leaf " + s + " at (" + u + ", " + v + ") axis " + a + ": " + point[a] + " outside "
                                        + Arrays.toString(box));
                    }
                    checked++;
                }
            }
        }
        assertTrue(checked > 1000, "the rotated use has leaves: " + checked);
    }

    @Test
    void anEditDropsTheInstanceOfTheEditedPatchOnly() {
        List<BezierPatch> teapot = Models.teapot().patches();
        Scene scene = scene(teapot, Affine.shift(0, 0, 0), Affine.shift(10, 0, 0), Affine.shift(20, 0, 0));
        Scene edited = scene.withPatch(40, scene.patches().get(40).withNet(scene.patches().get(41).copyNet()));
        assertEquals(List.of(0, 64), edited.instances().stream().map(in -> in.first()).toList());
        assertEquals(32 + 32, table(edited).splitPatches, "the model once, and the edited use's patches themselves");
        assertEquals(List.of(), Scene.builder().patches(scene.patches()).build().instances(),
                "a builder given a patch list has no instances");
    }
}
