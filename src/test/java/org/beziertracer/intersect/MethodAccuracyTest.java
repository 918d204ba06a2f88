package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.Tolerances.SUBDIVISION_T;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Every method against the slow reference ({@link QuadtreeReference}) on seeded random rays, each
 * method on its own default leaves: hit or miss disagree on at most {@value #HIT_MISS_BUDGET} of
 * the rays; the exact methods (clipping, Newton) never return a farther root where the nearest lies
 * more than 1e-6 of the scene size from a silhouette, and their agreeing hits lie within
 * {@code ROOT_T} of the scene size of the reference's; subdivision's within {@code SUBDIVISION_T}.
 * On folded random patches (several roots per ray, grazing rays) hit and miss agree as often, and
 * clipping returns no farther root (Newton: {@link #NEWTON_FOLDED_FARTHER}).
 */
class MethodAccuracyTest {

    /** Issue #10's target: 0.05 % of the rays. */
    static final double HIT_MISS_BUDGET = 0.0005;
    /**
     * Farther roots Newton returns on the folded patches, of 5,400 rays: 1 (a bilinear patch, the
     * nearer root 3e-4 from the patch's border, the ray at cos 0.38 to the normal; trying every
     * quarter start finds it, but costs Newton a third of its teapot speed). Lower it, never raise it.
     */
    static final int NEWTON_FOLDED_FARTHER = 1;
    static final Scene TEAPOT = Models.load("teapot");
    static final double[] TEAPOT_RAYS = MethodAccuracy.randomRays(TEAPOT.controlBounds(), 20_000, 10);
    static final double[][] TEAPOT_REFERENCE = MethodAccuracy.references(TEAPOT, TEAPOT_RAYS);

    @ParameterizedTest
    @EnumSource(Method.class)
    void agreesWithTheReferenceOnRandomTeapotRays(Method method) {
        SceneIntersector si = SceneIntersector.build(TEAPOT, IntersectOptions.defaults().withMethod(method));
        MethodAccuracy a = MethodAccuracy.measure(TEAPOT, si, TEAPOT_RAYS, TEAPOT_REFERENCE);
        assertTrue(a.referenceHits > a.rays / 2, "most rays hit the teapot: " + a);
        check(method, a, si.sceneSize());
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void agreesWithTheReferenceOnHeightFieldsOfDegree1To15(Method method) {
        MethodAccuracy total = new MethodAccuracy();
        double size = 0;
        for (int degree = 1; degree <= 15; degree++) {
            for (int p = 0; p < 3; p++) {
                Random rnd = new Random(100 * degree + p);
                BezierPatch patch = RandomPatches.heightField(rnd, degree, degree, 4, 0.8);
                Scene scene = new Scene(List.of(patch));
                double[] rays = MethodAccuracy.rainRays(rnd, 120);
                SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(method));
                add(total, MethodAccuracy.measure(scene, si, rays, MethodAccuracy.references(scene, rays)));
                size = si.sceneSize();
            }
        }
        check(method, total, size);
    }

    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "NEWTON"})
    void hitOrMissAgreeOnFoldedRandomPatchesOfDegree1To15(Method method) {
        MethodAccuracy total = new MethodAccuracy();
        for (int degree = 1; degree <= 15; degree++) {
            for (int p = 0; p < 3; p++) {
                BezierPatch patch = RandomPatches.wild(new Random(200 * degree + p), degree, degree, 2);
                Scene scene = new Scene(List.of(patch));
                double[] rays = MethodAccuracy.randomRays(scene.controlBounds(), 120, 300 * degree + p);
                SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(method));
                add(total, MethodAccuracy.measure(scene, si, rays, MethodAccuracy.references(scene, rays)));
            }
        }
        assertTrue(total.hitMiss <= HIT_MISS_BUDGET * total.rays, method + ": " + total);
        assertTrue(total.fartherAway <= (method == Method.NEWTON ? NEWTON_FOLDED_FARTHER : 0), method + ": " + total);
    }

    private static void check(Method method, MethodAccuracy a, double size) {
        assertTrue(a.hitMiss <= HIT_MISS_BUDGET * a.rays, method + ": " + a);
        if (method == Method.SUBDIVISION) {
            assertTrue(a.maxBothHitError <= SUBDIVISION_T * size, method + ": " + a);
        } else {
            assertEquals(0, a.fartherAway, method + ": " + a);
            assertTrue(a.maxError <= ROOT_T * size, method + ": " + a);
        }
    }

    private static void add(MethodAccuracy total, MethodAccuracy a) {
        total.rays += a.rays;
        total.referenceHits += a.referenceHits;
        total.hitMiss += a.hitMiss;
        total.hitMissAwayFromSilhouette += a.hitMissAwayFromSilhouette;
        total.fartherAway += a.fartherAway;
        total.fartherNearSilhouette += a.fartherNearSilhouette;
        total.nearer += a.nearer;
        total.agreeing += a.agreeing;
        total.sumError += a.sumError;
        total.maxError = Math.max(total.maxError, a.maxError);
        total.maxBothHitError = Math.max(total.maxBothHitError, a.maxBothHitError);
    }
}
