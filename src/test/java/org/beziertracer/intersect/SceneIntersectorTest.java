package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.Tolerances.ROUNDING;
import static org.beziertracer.Tolerances.SAME_ROOT_UV;
import static org.beziertracer.Tolerances.SUBDIVISION_T;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Plane;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.junit.jupiter.api.Test;

/** Whole-scene queries: BVH against brute force, occluded against closestHit, solvers against a reference. */
class SceneIntersectorTest {

    /** Size of {@link #wildScene}s: patches of size 2 placed in [0,6]³, about 10 across. */
    static final double SCENE_SIZE = 10;

    static Scene wildScene(Random rnd, int patches, int maxDegree) {
        List<BezierPatch> list = new ArrayList<>();
        for (int k = 0; k < patches; k++) {
            BezierPatch p = RandomPatches.wild(rnd, 1 + rnd.nextInt(maxDegree), 1 + rnd.nextInt(maxDegree), 2);
            double ox = 6 * rnd.nextDouble(), oy = 6 * rnd.nextDouble(), oz = 6 * rnd.nextDouble();
            double[] net = p.copyNet();
            for (int i = 0; i < net.length; i += 3) {
                net[i] += ox; net[i + 1] += oy; net[i + 2] += oz;
            }
            list.add(new BezierPatch(p.degreeU(), p.degreeV(), net));
        }
        return new Scene(list);
    }

    /** Random ray from outside the [0,8]³ region toward a random point inside it. */
    static double[] randomRay(Random rnd) {
        double[] o = {-4 + 16 * rnd.nextDouble(), -4 + 16 * rnd.nextDouble(), -4 + 16 * rnd.nextDouble()};
        double[] target = {8 * rnd.nextDouble(), 8 * rnd.nextDouble(), 8 * rnd.nextDouble()};
        return new double[] {o[0], o[1], o[2], target[0] - o[0], target[1] - o[1], target[2] - o[2]};
    }

    @Test
    void bvhClosestHitEqualsBruteForceOverWholePatches() {
        Random rnd = new Random(7);
        Scene scene = wildScene(rnd, 40, 6);
        SceneIntersector withBvh = SceneIntersector.build(scene, IntersectOptions.defaults());
        SceneIntersector flat = SceneIntersector.build(scene, IntersectOptions.defaults().withBvh(false));
        assertTrue(withBvh.subPatchCount() > scene.patchCount(), "patches were pre-split");
        assertEquals(scene.patchCount(), flat.subPatchCount());
        TraceContext c1 = withBvh.newContext(), c2 = flat.newContext();
        Hit h1 = new Hit(), h2 = new Hit();
        int hits = 0;
        for (int r = 0; r < 3000; r++) {
            double[] ray = randomRay(rnd);
            boolean a = withBvh.closestHit(c1, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, h1);
            boolean b = flat.closestHit(c2, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, h2);
            String where = "ray " + r + " " + java.util.Arrays.toString(ray);
            assertEquals(b, a, "hit/miss differs: " + where);
            if (a) {
                hits++;
                assertEquals(h2.t, h1.t, ROOT_T * SCENE_SIZE, "t differs: " + where);
                assertEquals(h2.index, h1.index, "patch differs: " + where);
            }
        }
        assertTrue(hits > 300, "test rays should hit often, hit " + hits);
    }

    @Test
    void occludedAgreesWithClosestHit() {
        Random rnd = new Random(11);
        Scene scene = wildScene(rnd, 25, 5);
        for (Method method : Method.values()) {
            SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(method));
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            for (int r = 0; r < 1500; r++) {
                double[] ray = randomRay(rnd);
                double tMax = rnd.nextDouble() * 1.5;
                boolean closest = si.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax, hit);
                boolean occluded = si.occluded(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax);
                assertEquals(closest, occluded, method + " ray " + java.util.Arrays.toString(ray) + " tMax " + tMax);
            }
        }
    }

    @Test
    void clippingAndNewtonAgreeWithTheSlowReference() {
        Random rnd = new Random(5);
        int compared = 0, newtonAgrees = 0;
        for (int trial = 0; trial < 60; trial++) {
            int n = 1 + rnd.nextInt(9), m = 1 + rnd.nextInt(9);
            BezierPatch patch = RandomPatches.heightField(rnd, n, m, 4, 0.8);
            Scene scene = new Scene(List.of(patch));
            SceneIntersector clip = SceneIntersector.build(scene, IntersectOptions.defaults());
            SceneIntersector newton = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(Method.NEWTON));
            TraceContext cc = clip.newContext(), cn = newton.newContext();
            Hit hc = new Hit(), hn = new Hit();
            for (int r = 0; r < 10; r++) {
                double ox = 6 * (rnd.nextDouble() - 0.5), oy = 6 * (rnd.nextDouble() - 0.5), oz = 3 + 3 * rnd.nextDouble();
                double tx = 3 * (rnd.nextDouble() - 0.5), ty = 3 * (rnd.nextDouble() - 0.5);
                double dx = tx - ox, dy = ty - oy, dz = -oz;
                double[] ref = ReferenceIntersector.nearest(patch, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, 48);
                boolean a = clip.closestHit(cc, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hc);
                boolean b = newton.closestHit(cn, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hn);
                String where = "degree " + n + "x" + m + " o=(" + ox + "," + oy + "," + oz + ") d=(" + dx + "," + dy + "," + dz + ")";
                assertEquals(ref != null, a, "clipping hit/miss differs from the reference: " + where);
                if (ref != null) {
                    compared++;
                    assertEquals(ref[0], hc.t, ROOT_T, "clipping t: " + where); // stricter than ROOT_T × size 4
                    assertEquals(ref[1], hc.u, SAME_ROOT_UV, "clipping u: " + where);
                    assertEquals(ref[2], hc.v, SAME_ROOT_UV, "clipping v: " + where);
                    if (b && Math.abs(hn.t - ref[0]) < ROOT_T) {
                        newtonAgrees++;
                    }
                }
            }
        }
        assertTrue(compared > 200, "compared " + compared);
        assertTrue(newtonAgrees > 0.95 * compared, "Newton agreed on " + newtonAgrees + " of " + compared);
    }

    @Test
    void subdivisionApproximatesTheExactHit() {
        Random rnd = new Random(3);
        BezierPatch patch = RandomPatches.heightField(rnd, 3, 3, 4, 0.5);
        Scene scene = new Scene(List.of(patch));
        SceneIntersector exact = SceneIntersector.build(scene, IntersectOptions.defaults());
        SceneIntersector sub = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(Method.SUBDIVISION));
        TraceContext ce = exact.newContext(), cs = sub.newContext();
        Hit he = new Hit(), hs = new Hit();
        int both = 0;
        for (int r = 0; r < 400; r++) {
            double ox = 1.5 * (rnd.nextDouble() - 0.5), oy = 1.5 * (rnd.nextDouble() - 0.5);
            boolean a = exact.closestHit(ce, ox, oy, 10, 0.1 * (rnd.nextDouble() - 0.5), 0.1 * (rnd.nextDouble() - 0.5), -1, 0, 100, he);
            boolean b = sub.closestHit(cs, ox, oy, 10, ce.dx, ce.dy, ce.dz, 0, 100, hs);
            assertEquals(a, b, "ray " + r);
            if (a) {
                both++;
                assertEquals(he.t, hs.t, SUBDIVISION_T * 4, "subdivision t close to exact, ray " + r);
            }
        }
        assertTrue(both > 300);
    }

    @Test
    void planesAndSpheresAreHitThroughTheSameQuery() {
        Scene scene = new Scene(List.of(), List.of(new Plane(new Vec3(0, 0, 0), new Vec3(0, 0, 1))),
                List.of(new Sphere(new Vec3(0, 0, 2), 1)));
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        assertTrue(si.closestHit(ctx, 0, 0, 10, 0, 0, -2, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Hit.SPHERE, hit.kind);
        assertEquals(3.5, hit.t, ROUNDING);
        assertTrue(si.closestHit(ctx, 5, 0, 10, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Hit.PLANE, hit.kind);
        assertEquals(10, hit.t, ROUNDING);
        // from inside the sphere, the far side
        assertTrue(si.closestHit(ctx, 0, 0, 2, 0, 0, 1, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(1, hit.t, ROUNDING);
        assertFalse(si.occluded(ctx, 5, 0, 10, 0, 0, -1, 0, 9.9));
        assertTrue(si.occluded(ctx, 5, 0, 10, 0, 0, -1, 0, 10.1));
        SurfacePoint sp = new SurfacePoint();
        si.closestHit(ctx, 0, 0, 10, 0, 0, -2, 0, Double.POSITIVE_INFINITY, hit);
        si.surfacePoint(ctx, hit, sp);
        assertEquals(3, sp.pz, ROUNDING);
        assertEquals(1, sp.nz, ROUNDING);
    }

    @Test
    void aRayLeavingAHitPointDoesNotFindThatPointAgain() {
        Random rnd = new Random(99);
        Scene scene = wildScene(rnd, 20, 4);
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        TraceContext ctx = si.newContext();
        Hit hit = new Hit(), again = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double eps = 1e-7 * si.sceneSize();
        int tested = 0;
        for (int r = 0; r < 2000; r++) {
            double[] ray = randomRay(rnd);
            if (!si.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, hit)) {
                continue;
            }
            si.surfacePoint(ctx, hit, sp);
            // leave toward the side the ray came from, along a random direction in that hemisphere
            double side = sp.nx * ray[3] + sp.ny * ray[4] + sp.nz * ray[5] < 0 ? 1 : -1;
            double lx = rnd.nextGaussian(), ly = rnd.nextGaussian(), lz = rnd.nextGaussian();
            double dn = (lx * sp.nx + ly * sp.ny + lz * sp.nz) * side;
            if (dn < 0.05) {
                continue;
            }
            tested++;
            if (si.closestHit(ctx, sp.px, sp.py, sp.pz, lx, ly, lz, eps, Double.POSITIVE_INFINITY, again)) {
                double gx = again.t * lx, gy = again.t * ly, gz = again.t * lz;
                double dist = Math.sqrt(gx * gx + gy * gy + gz * gz);
                assertTrue(dist > 1e-6 * si.sceneSize(), "ray from hit point " + r + " hit itself at distance " + dist);
            }
        }
        assertTrue(tested > 100, "tested " + tested);
    }

    @Test
    void editingOnePatchGivesTheSameAnswersAsARebuild() {
        Random rnd = new Random(17);
        Scene scene = wildScene(rnd, 12, 4);
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        BezierPatch moved = scene.patches().get(3).withPoint(1, 1, 4, 4, 4);
        SceneIntersector edited = si.withPatch(3, moved);
        SceneIntersector rebuilt = SceneIntersector.build(scene.withPatch(3, moved), IntersectOptions.defaults());
        assertNotNull(edited.scene());
        assertEquals(moved, edited.scene().patches().get(3));
        assertEquals(scene.patches().get(3), si.scene().patches().get(3), "old snapshot unchanged");
        sameAnswers(edited, rebuilt, rnd);
    }

    /** 1000 random rays meet {@code edited} and {@code rebuilt} alike; returns how many hit. */
    private static int sameAnswers(SceneIntersector edited, SceneIntersector rebuilt, Random rnd) {
        TraceContext c1 = edited.newContext(), c2 = rebuilt.newContext();
        Hit h1 = new Hit(), h2 = new Hit();
        int hits = 0;
        for (int r = 0; r < 1000; r++) {
            double[] ray = randomRay(rnd);
            boolean a = edited.closestHit(c1, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, h1);
            boolean b = rebuilt.closestHit(c2, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, h2);
            assertEquals(b, a, "ray " + r);
            if (a) {
                hits++;
                assertEquals(h2.t, h1.t, ROOT_T, "ray " + r);
                assertEquals(h2.index, h1.index, "ray " + r);
            }
        }
        return hits;
    }

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(ints = {0, 6})
    void editingSeveralPatchesAtOnceGivesTheSameAnswersAsARebuild(int tessellate) {
        Random rnd = new Random(23);
        Scene scene = wildScene(rnd, 12, 4);
        IntersectOptions io = IntersectOptions.defaults().withTessellate(tessellate);
        SceneIntersector si = SceneIntersector.build(scene, io);
        java.util.List<BezierPatch> patches = new java.util.ArrayList<>(scene.patches());
        int[] changed = {2, 5, 9};
        for (int k : changed) {
            patches.set(k, patches.get(k).withPoint(0, 0, 3, -2, 5));
        }
        Scene after = scene.toBuilder().patches(patches).build();
        SceneIntersector edited = si.withPatches(after, changed);
        SceneIntersector rebuilt = SceneIntersector.build(after, io);
        assertSame(after, edited.scene(), "the edited scene itself, not a copy");
        // Triangles are remade as a rebuild makes them; sub-patches keep their old halvings where
        // they still fit, so the count is the kept split's
        int expected = tessellate > 0 ? rebuilt.primitiveCount()
                : ((PatchLeaves) si.leaves).table.withPatches(changed, java.util.List.of(patches.get(2), patches.get(5),
                        patches.get(9)), true).count;
        assertEquals(expected, edited.primitiveCount());
        int hits = sameAnswers(edited, rebuilt, rnd);
        assertTrue(hits > 100, "hits " + hits);
    }

    /** With one leaf a patch the leaf count cannot change: the edit refits the BVH (partial refit). */
    @Test
    void anEditThatKeepsTheLeafCountRefitsAndAnswersLikeARebuild() {
        Random rnd = new Random(18);
        Scene scene = wildScene(rnd, 40, 4);
        IntersectOptions whole = IntersectOptions.defaults().withSplit(org.beziertracer.geometry.SplitOptions.wholePatches());
        SceneIntersector si = SceneIntersector.build(scene, whole);
        for (int edit = 0; edit < 5; edit++) {
            int index = rnd.nextInt(scene.patchCount());
            BezierPatch moved = si.scene().patches().get(index).withPoint(1, 1, 6 * rnd.nextGaussian(),
                    6 * rnd.nextGaussian(), 6 * rnd.nextGaussian());
            SceneIntersector edited = si.withPatch(index, moved);
            assertEquals(si.subPatchCount(), edited.subPatchCount());
            assertEquals(si.nodeCount(), edited.nodeCount(), "refitted, not rebuilt");
            SceneIntersector rebuilt = SceneIntersector.build(edited.scene(), whole);
            TraceContext c1 = edited.newContext(), c2 = rebuilt.newContext();
            Hit h1 = new Hit(), h2 = new Hit();
            for (int r = 0; r < 500; r++) {
                double[] ray = randomRay(rnd);
                boolean a = edited.closestHit(c1, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, h1);
                boolean b = rebuilt.closestHit(c2, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, h2);
                assertEquals(b, a, "edit " + edit + " ray " + r);
                if (a) {
                    assertEquals(h2.t, h1.t, 0, "edit " + edit + " ray " + r);
                    assertEquals(h2.index, h1.index, "edit " + edit + " ray " + r);
                }
            }
            si = edited;
        }
    }

    /**
     * A drag keeps the patch's old halvings (the leaf count, and a refit) for
     * {@link SceneIntersector#KEPT_EDITS} edits in a row; the next edit splits afresh and rebuilds.
     * The wavy degree-5 patch flattens step by step: its kept leaves stay, a fresh split makes fewer.
     */
    @Test
    void aLongDragKeepsTheSplitForAWhileThenSplitsAfresh() {
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(wavy(6, 1))), IntersectOptions.defaults());
        int leaves = si.subPatchCount();
        for (int edit = 1; edit <= SceneIntersector.KEPT_EDITS; edit++) {
            si = si.withPatch(0, wavy(6, 1 - 0.03 * edit));
            assertEquals(leaves, si.subPatchCount(), "edit " + edit + " keeps the leaves");
            assertEquals(edit, si.keptEdits);
        }
        Scene flatter = si.scene().withPatch(0, wavy(6, 0.02));
        SceneIntersector fresh = SceneIntersector.build(flatter, IntersectOptions.defaults());
        assertTrue(fresh.subPatchCount() < leaves, fresh.subPatchCount() + " of " + leaves);
        si = si.withPatches(flatter, new int[] {0});
        assertEquals(0, si.keptEdits, "split afresh");
        assertEquals(fresh.subPatchCount(), si.subPatchCount());
        assertEquals(fresh.nodeCount(), si.nodeCount(), "the BVH rebuilt");
        Random rnd = new Random(61);
        sameAnswers(si, fresh, rnd);
        assertEquals(1, si.withPatch(0, wavy(6, 0.5)).keptEdits, "and the count starts again");
    }

    /**
     * An edit that makes the first rational (or trimmed) patch splits every patch afresh (the table's storage
     * changes), also a patch whose old halvings a drag kept: the solver's data and the BVH are then
     * made for every patch, not copied or refitted from the patches the edit did not touch.
     */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(booleans = {false, true})
    void anEditThatSplitsEveryPatchAfreshAfterAKeptDragAnswersLikeARebuild(boolean trimmed) {
        Random rnd = new Random(404);
        List<BezierPatch> patches = new ArrayList<>(wildScene(rnd, 8, 4).patches());
        patches.set(0, shifted(wavy(6, 1), 4));
        SceneIntersector si = SceneIntersector.build(new Scene(patches), IntersectOptions.defaults());
        si = si.withPatch(0, shifted(wavy(6, 0.01), 4)); // flattened: its leaves are kept
        int kept = si.subPatchCount();
        assertTrue(kept > SceneIntersector.build(si.scene(), IntersectOptions.defaults()).subPatchCount(), "kept leaves");
        BezierPatch p = si.scene().patches().get(3);
        double[] weights = new double[p.pointCount()];
        java.util.Arrays.fill(weights, 1);
        weights[0] = 2;
        var region = new org.beziertracer.model.TrimRegion(List.of(TrimmedIntersectionTest.circle(0.5, 0.5, 0.4, true)),
                List.of());
        BezierPatch first = trimmed
                ? new BezierPatch(p.degreeU(), p.degreeV(), p.copyNet(), null, new org.beziertracer.model.PatchDomain(0, 1, 0, 1, region), null)
                : new BezierPatch(p.degreeU(), p.degreeV(), p.copyNet(), weights, null, null);
        SceneIntersector edited = si.withPatch(3, first);
        SceneIntersector rebuilt = SceneIntersector.build(edited.scene(), IntersectOptions.defaults());
        assertEquals(rebuilt.subPatchCount(), edited.subPatchCount(), "every patch split afresh");
        assertTrue(sameAnswers(edited, rebuilt, rnd) > 100);
    }

    /** {@code p} moved by {@code d} along x, y and z. */
    private static BezierPatch shifted(BezierPatch p, double d) {
        double[] net = p.copyNet();
        for (int i = 0; i < net.length; i++) {
            net[i] += d;
        }
        return p.withNet(net);
    }

    /**
     * The BVH of a long drag: refitted (its leaf order kept) for {@link SceneIntersector#KEPT_EDITS}
     * edits, then rebuilt as a fresh build makes it, even though the leaf count never changes (a
     * flat patch carried across a row of others).
     */
    @Test
    void aLongDragRebuildsTheBvhAfterItsKeptEdits() {
        List<BezierPatch> row = new ArrayList<>();
        for (int k = 0; k < 12; k++) {
            row.add(new BezierPatch(1, 1, new double[] {k, 0, 0, k + 0.8, 0, 0, k, 0.8, 0, k + 0.8, 0.8, 0}));
        }
        SceneIntersector si = SceneIntersector.build(new Scene(row), IntersectOptions.defaults());
        int[] order = ((org.beziertracer.accel.Bvh) si.accel).primIndices().clone();
        BezierPatch moving = row.get(0);
        for (int edit = 1; edit <= SceneIntersector.KEPT_EDITS + 1; edit++) {
            double x = 11.0 * edit / (SceneIntersector.KEPT_EDITS + 1);
            double[] net = moving.copyNet();
            for (int i = 0; i < net.length; i += 3) {
                net[i] += x;
                net[i + 2] = 0.5;
            }
            SceneIntersector next = si.withPatch(0, moving.withNet(net));
            int[] now = ((org.beziertracer.accel.Bvh) next.accel).primIndices();
            assertEquals(12, next.subPatchCount());
            if (edit <= SceneIntersector.KEPT_EDITS) {
                assertArrayEquals(order, now, "edit " + edit + " refits");
            } else {
                SceneIntersector fresh = SceneIntersector.build(next.scene(), IntersectOptions.defaults());
                assertArrayEquals(((org.beziertracer.accel.Bvh) fresh.accel).primIndices(), now, "rebuilt");
                assertTrue(!java.util.Arrays.equals(order, now), "the patch moved across: another order");
            }
            si = next;
        }
    }

    /** The wavy height field of issue [1 of 5] on the toolbox's {@code points}² grid, heights times {@code amplitude}. */
    static BezierPatch wavy(int points, double amplitude) {
        double[] net = org.beziertracer.model.io.Models.flatGrid(points, points).copyNet();
        for (int k = 0; k < net.length; k += 3) {
            double x = net[k], y = net[k + 1];
            net[k + 2] = amplitude * (0.5 * Math.sin(2.6 * x + 1.2 * y) * Math.cos(1.7 * y - 0.9 * x)
                    + 0.25 * Math.sin(2.0 * x * y));
        }
        return new BezierPatch(points - 1, points - 1, net);
    }

    @Test
    void tinyAndHugeDirectionsGiveTheSameHitScaled() {
        Scene scene = org.beziertracer.model.io.Models.teapot();
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        assertTrue(si.closestHit(ctx, 0, 0, 220, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit));
        double t = hit.t;
        for (double scale : new double[] {1e-200, 1e-100, 1e100, 1e200}) {
            assertTrue(si.closestHit(ctx, 0, 0, 220, 0, 0, -scale, 0, Double.POSITIVE_INFINITY, hit), "scale " + scale);
            assertEquals(t, hit.t * scale, ROOT_T * t, "t scales with 1/|d|, scale " + scale);
            assertTrue(si.closestHit(ctx, 0, 0, 220, scale * 1e-3, scale * 2e-3, -scale, 0, Double.POSITIVE_INFINITY, hit),
                    "oblique, scale " + scale);
            assertTrue(Double.isFinite(hit.u) && Double.isFinite(hit.v), "finite (u,v) at scale " + scale);
        }
    }
    /** Plane and sphere hits carry their texture coordinates; their surface points are the shapes'. */
    @Test
    void planeAndSphereHitsHaveTheirTextureCoordinatesAndSurfacePoints() {
        Plane plane = new Plane(new Vec3(1, 2, -1), new Vec3(0, 0, 1), 0, 2);
        Sphere sphere = new Sphere(new Vec3(3, -1, 4), 1.5);
        Scene scene = new Scene(List.of(), List.of(plane), List.of(sphere));
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        AnalyticShapes shapes = new AnalyticShapes(List.of(plane), List.of(sphere));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit(), expected = new Hit();
        SurfacePoint sp = new SurfacePoint();
        // a plane hit at (-2, 5.5, -1): t = 2
        assertTrue(si.closestHit(ctx, 0, 4.5, 3, -1, 0.5, -2, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Hit.PLANE, hit.kind);
        assertEquals(2, hit.t, ROUNDING);
        assertEquals(-1, hit.subPatch);
        shapes.planeUv(0, -2, 5.5, -1, expected);
        assertEquals(expected.u, hit.u, ROUNDING);
        assertEquals(expected.v, hit.v, ROUNDING);
        assertEquals(Math.hypot(3, 3.5) / 2, Math.hypot(hit.u, hit.v), ROUNDING, "distance from the plane's point / uvScale");
        si.surfacePoint(ctx, hit, sp);
        assertEquals(Hit.PLANE, sp.kind);
        assertEquals(hit.u, sp.u, 0);
        assertEquals(-2, sp.px, ROUNDING);
        assertEquals(5.5, sp.py, ROUNDING);
        assertEquals(-1, sp.pz, ROUNDING);
        assertEquals(1, sp.nz, 0);
        assertEquals(0, sp.dpduz, ROUNDING, "dp/du lies in the plane");
        assertEquals(1, Math.hypot(sp.dpdux, sp.dpduy), ROUNDING);
        // a sphere hit at colatitude 60° and longitude 60°: u = 1/6, v = 1/3
        double[] n = {Math.sqrt(3) / 4, 0.75, 0.5};
        double[] o = {3 + 3.5 * n[0], -1 + 3.5 * n[1], 4 + 3.5 * n[2]};
        assertTrue(si.closestHit(ctx, o[0], o[1], o[2], -n[0], -n[1], -n[2], 0, 100, hit));
        assertEquals(Hit.SPHERE, hit.kind);
        assertEquals(0, hit.index);
        assertEquals(2, hit.t, 1e-12);
        assertEquals(1.0 / 6, hit.u, 1e-12);
        assertEquals(1.0 / 3, hit.v, 1e-12);
        si.surfacePoint(ctx, hit, sp);
        assertEquals(4 + 1.5 * n[2], sp.pz, 1e-12);
        assertEquals(n[0], sp.nx, 1e-12);
        // nothing in front: a miss leaves the answer false
        assertFalse(si.closestHit(ctx, 0, 0, 10, 0, 0, 1, 0, Double.POSITIVE_INFINITY, hit));
    }

    /** The interval is open at both ends, for planes in both queries and for spheres. */
    @Test
    void shapesExactlyAtTMinOrTMaxDoNotCount() {
        Scene scene = new Scene(List.of(), List.of(new Plane(new Vec3(0, 0, 0), new Vec3(0, 0, 1))),
                List.of(new Sphere(new Vec3(10, 0, 0), 1)));
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        assertFalse(si.closestHit(ctx, 0, 0, 10, 0, 0, -1, 0, 10, hit), "plane at tMax");
        assertFalse(si.closestHit(ctx, 0, 0, 10, 0, 0, -1, 10, 20, hit), "plane at tMin");
        assertTrue(si.closestHit(ctx, 0, 0, 10, 0, 0, -1, Math.nextDown(10.0), 20, hit));
        assertFalse(si.occluded(ctx, 0, 0, 10, 0, 0, -1, 0, 10), "plane at tMax");
        assertFalse(si.occluded(ctx, 0, 0, 10, 0, 0, -1, 10, 20), "plane at tMin");
        assertTrue(si.occluded(ctx, 0, 0, 10, 0, 0, -1, Math.nextDown(10.0), Math.nextUp(10.0)));
        // the sphere occludes, and only inside the interval
        assertTrue(si.occluded(ctx, 5, 0, 0.5, 1, 0, 0, 0, 10));
        assertFalse(si.occluded(ctx, 5, 0, 0.5, 1, 0, 0, 0, 4));
        assertFalse(si.occluded(ctx, 5, 0, 0.5, -1, 0, 0, 0, 100), "behind the origin");
        assertTrue(si.closestHit(ctx, 5, 0, 0.5, 1, 0, 0, 0, 100, hit));
        assertEquals(Hit.SPHERE, hit.kind);
    }

    /** An occlusion query on its own (no closest-hit query first with the same ray) in both modes. */
    @Test
    void occlusionAloneAnswersLikeClosestHit() {
        Random rnd = new Random(29);
        Scene scene = wildScene(rnd, 15, 3);
        for (int tessellate : new int[] {0, 5}) {
            SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults().withTessellate(tessellate));
            TraceContext a = si.newContext(), b = si.newContext();
            Hit hit = new Hit();
            int blocked = 0;
            for (int r = 0; r < 800; r++) {
                double[] ray = randomRay(rnd);
                boolean occluded = si.occluded(a, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, 1);
                boolean closest = si.closestHit(b, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, 1, hit);
                assertEquals(closest, occluded, "K = " + tessellate + " ray " + r);
                blocked += occluded ? 1 : 0;
            }
            assertTrue(blocked > 50 && blocked < 750, "K = " + tessellate + ": " + blocked + " blocked");
        }
    }

    @Test
    void theSceneSizeIsTheControlBoxDiagonalOrOne() {
        BezierPatch unit = new BezierPatch(1, 1, new double[] {0, 0, 0, 3, 0, 0, 0, 4, 0, 3, 4, 12});
        assertEquals(13, SceneIntersector.build(new Scene(List.of(unit)), IntersectOptions.defaults()).sceneSize(), ROUNDING);
        BezierPatch point = new BezierPatch(1, 1, new double[] {2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2});
        assertEquals(1, SceneIntersector.build(new Scene(List.of(point)), IntersectOptions.defaults()).sceneSize(), 0);
        Scene shapesOnly = new Scene(List.of(), List.of(), List.of(new Sphere(new Vec3(0, 0, 0), 50)));
        assertEquals(1, SceneIntersector.build(shapesOnly, IntersectOptions.defaults()).sceneSize(), 0);
        // the edit measures the edited scene
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(unit)), IntersectOptions.defaults());
        assertEquals(26, si.withPatch(0, unit.withPoint(1, 1, 6, 8, 24)).sceneSize(), ROUNDING);
    }

    @Test
    void theStatisticsDescribeTheBuild() {
        Scene teapot = org.beziertracer.model.io.Models.teapot();
        for (IntersectOptions io : List.of(IntersectOptions.defaults(), IntersectOptions.defaults().withTessellate(3))) {
            long before = System.nanoTime();
            SceneIntersector si = SceneIntersector.build(teapot, io);
            double wallMillis = (System.nanoTime() - before) / 1e6;
            assertSame(io, si.options());
            assertTrue(si.buildMillis() > 0 && si.buildMillis() <= wallMillis, si.buildMillis() + " of " + wallMillis);
            assertTrue(si.nodeCount() >= 2 * si.primitiveCount() / io.bvhOptions().maxLeafSize() - 1, "nodes " + si.nodeCount());
            assertTrue(si.depth() > 1 && si.depth() < si.nodeCount(), "depth " + si.depth());
            assertTrue(si.accelBytes() >= 32L * si.nodeCount(), "accel bytes " + si.accelBytes());
            assertEquals(si.leaves.bytes(), si.leafBytes());
            assertTrue(si.leafBytes() > 8L * 3 * si.primitiveCount(), "leaf bytes " + si.leafBytes());
            before = System.nanoTime();
            SceneIntersector edited = si.withPatch(0, teapot.patches().get(0).withPoint(1, 1, 0, 0, 50));
            wallMillis = (System.nanoTime() - before) / 1e6;
            assertTrue(edited.buildMillis() > 0 && edited.buildMillis() <= wallMillis, edited.buildMillis() + " of " + wallMillis);
        }
    }

    @Test
    void aSceneThatWouldNotFitInTheHeapIsRefusedBeforeItIsBuilt() {
        Scene teapot = org.beziertracer.model.io.Models.teapot();
        String message = org.beziertracer.UserMessages.of(IllegalArgumentException.class,
                () -> SceneIntersector.build(teapot, IntersectOptions.defaults().withTessellate(1024)));
        assertTrue(message.startsWith("32 patches tessellated 1024x1024"), message);
    }

    /**
     * A context grows its traversal stack to the BVH it is given: one whose stack is smaller than
     * the teapot's BVH needs (as if it had served only shallower trees; a real BVH that deep
     * would need more than 2^128 leaves or a degenerate build) answers both queries.
     */
    @Test
    void aContextWithATooSmallStackGrowsItForTheBvh() {
        SceneIntersector si = SceneIntersector.build(org.beziertracer.model.io.Models.teapot(), IntersectOptions.defaults());
        Hit hit = new Hit(), expected = new Hit();
        assertTrue(si.closestHit(si.newContext(), 0, 0, 220, 0.01, 0.02, -1, 0, Double.POSITIVE_INFINITY, expected));
        TraceContext ctx = si.newContext();
        ctx.stack = new int[1];
        assertTrue(si.closestHit(ctx, 0, 0, 220, 0.01, 0.02, -1, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(expected.t, hit.t, 0);
        assertTrue(ctx.stack.length >= 2 * si.depth());
        ctx.stack = new int[1];
        assertTrue(si.occluded(ctx, 0, 0, 220, 0.01, 0.02, -1, 0, Double.POSITIVE_INFINITY));
        assertTrue(ctx.stack.length >= 2 * si.depth());
    }

    /** Edits that change the number of leaves rebuild the BVH; with the BVH off the list is rebuilt. */
    @Test
    void editsThatChangeTheLeafCountOrHaveNoBvhAnswerLikeARebuild() {
        Random rnd = new Random(31);
        Scene scene = wildScene(rnd, 10, 3);
        for (IntersectOptions io : List.of(IntersectOptions.defaults(), IntersectOptions.defaults().withBvh(false))) {
            SceneIntersector si = SceneIntersector.build(scene, io);
            // a flat bilinear patch needs one leaf; the wild patch it replaces needed several
            int index = 0;
            while (io.bvh() && si.leaves.leafCount(index) == 1) {
                index++;
            }
            BezierPatch flat = new BezierPatch(1, 1, new double[] {0, 0, 3, 8, 0, 3, 0, 8, 3, 8, 8, 3});
            SceneIntersector edited = si.withPatch(index, flat);
            SceneIntersector rebuilt = SceneIntersector.build(scene.withPatch(index, flat), io);
            assertEquals(rebuilt.primitiveCount(), edited.primitiveCount());
            if (io.bvh()) {
                assertTrue(edited.primitiveCount() < si.primitiveCount(), "fewer leaves");
            }
            assertTrue(sameAnswers(edited, rebuilt, rnd) > 100);
        }
    }
}
