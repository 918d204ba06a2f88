package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Scene;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Rays at trimmed surfaces: through holes they miss (or hit what lies behind), through the
 * material they hit, near a trim curve they decide as the exact curve does, and the loops'
 * orientation does not matter.
 */
class TrimmedIntersectionTest {

    private static final double H = Math.sqrt(0.5);

    static TrimLoop circle(double cx, double cy, double r, boolean ccw) {
        return TrimLoop.circle(cx, cy, r, ccw);
    }

    /** A polygon, one straight Bézier curve per edge. */
    static TrimLoop polygon(double... uv) {
        List<TrimPiece> pieces = new ArrayList<>();
        int n = uv.length / 2;
        for (int k = 0; k < n; k++) {
            int a = 2 * k, b = 2 * ((k + 1) % n);
            pieces.add(new TrimPiece(new TrimCurve(SplineBasis.BEZIER, 1, new double[] {0, 1},
                    new double[] {uv[a], uv[a + 1], uv[b], uv[b + 1]}, null), 0, 1));
        }
        return new TrimLoop(pieces);
    }

    /** The flat plate x = u, y = v, z = 0 over [0,1]², trimmed to [0.1,0.9]² minus a circle and a triangle. */
    static BezierPatch plate(boolean ccw) {
        TrimLoop outer = ccw ? polygon(0.1, 0.1, 0.9, 0.1, 0.9, 0.9, 0.1, 0.9) : polygon(0.1, 0.1, 0.1, 0.9, 0.9, 0.9, 0.9, 0.1);
        TrimLoop triangle = ccw ? polygon(0.15, 0.15, 0.3, 0.15, 0.15, 0.3) : polygon(0.15, 0.15, 0.15, 0.3, 0.3, 0.15);
        TrimRegion region = new TrimRegion(List.of(outer), List.of(circle(0.5, 0.5, 0.2, ccw), triangle));
        return new BezierPatch(1, 1, new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, null,
                new PatchDomain(0, 1, 0, 1, region), null);
    }

    static boolean material(double x, double y) {
        boolean square = x > 0.1 && x < 0.9 && y > 0.1 && y < 0.9;
        return square && Math.hypot(x - 0.5, y - 0.5) > 0.2 && !(x > 0.15 && y > 0.15 && x + y < 0.45);
    }

    private static boolean down(SceneIntersector si, TraceContext ctx, Hit hit, double x, double y) {
        return si.closestHit(ctx, x, y, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit);
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void raysThroughHolesMissAndRaysThroughTheMaterialHit(Method method) {
        for (IntersectOptions options : List.of(IntersectOptions.defaults().withMethod(method),
                IntersectOptions.defaults().withMethod(method).withBvh(false),
                IntersectOptions.defaults().withTessellate(4))) {
            SceneIntersector si = SceneIntersector.build(new Scene(List.of(plate(true))), options);
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            Random rnd = new Random(81);
            int hits = 0;
            for (int r = 0; r < 3000; r++) {
                double x = rnd.nextDouble(), y = rnd.nextDouble();
                boolean want = material(x, y);
                String where = options + " at (" + x + ", " + y + ")";
                assertEquals(want, down(si, ctx, hit, x, y), where);
                assertEquals(want, si.occluded(ctx, x, y, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY), "occluded " + where);
                if (want) {
                    hits++;
                    assertEquals(1, hit.t, 1e-12, where);
                    assertEquals(x, hit.u, 1e-9, where);
                    assertEquals(y, hit.v, 1e-9, where);
                }
            }
            assertTrue(hits > 1000, options + ": " + hits);
        }
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void aSnapshotEditedIntoATrimmedPatchTestsItsTrimsLikeAFreshOne(Method method) {
        // The app keeps its snapshot when only patches change: opening the trimmed plate after the
        // default patch (one patch each) went through withPatches, which once kept untrimmed leaves
        // (holes showed as the dropped sub-patches' squares)
        BezierPatch plain = new BezierPatch(1, 1, new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.01});
        IntersectOptions options = IntersectOptions.defaults().withMethod(method);
        SceneIntersector plainSnapshot = SceneIntersector.build(new Scene(List.of(plain)), options);
        for (SceneIntersector si : List.of(plainSnapshot.withPatches(new Scene(List.of(plate(true))), new int[] {0}),
                plainSnapshot.withPatch(0, plate(true)))) {
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            Random rnd = new Random(84);
            for (int r = 0; r < 2000; r++) {
                double x = rnd.nextDouble(), y = rnd.nextDouble();
                assertEquals(material(x, y), down(si, ctx, hit, x, y), method + " at (" + x + ", " + y + ")");
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void raysWithin1e9OfATrimCurveDecideAsTheExactCurve(Method method) {
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(plate(true))),
                IntersectOptions.defaults().withMethod(method));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(82);
        for (int r = 0; r < 2000; r++) {
            double angle = 2 * Math.PI * rnd.nextDouble();
            double offset = (rnd.nextBoolean() ? 1 : -1) * (2e-10 + 8e-10 * rnd.nextDouble());
            double x = 0.5 + (0.2 + offset) * Math.cos(angle), y = 0.5 + (0.2 + offset) * Math.sin(angle);
            assertEquals(Math.hypot(x - 0.5, y - 0.5) > 0.2, down(si, ctx, hit, x, y),
                    method + " at angle " + angle + ", offset " + offset);
        }
        for (int r = 0; r < 500; r++) {
            double y = 0.12 + 0.76 * rnd.nextDouble(), offset = 2e-10 + 8e-10 * rnd.nextDouble();
            assertTrue(down(si, ctx, hit, 0.9 - offset, y) || !material(0.9 - offset, y), "inside the right edge");
            assertFalse(down(si, ctx, hit, 0.9 + offset, y), "outside the right edge at " + y);
        }
    }

    @Test
    void clockwiseAndCounterClockwiseLoopsGiveTheSamePicture() {
        SceneIntersector ccw = SceneIntersector.build(new Scene(List.of(plate(true))), IntersectOptions.defaults());
        SceneIntersector cw = SceneIntersector.build(new Scene(List.of(plate(false))), IntersectOptions.defaults());
        TraceContext a = ccw.newContext(), b = cw.newContext();
        Hit ha = new Hit(), hb = new Hit();
        for (int j = 0; j < 120; j++) {
            for (int i = 0; i < 120; i++) {
                double x = (i + 0.5) / 120, y = (j + 0.5) / 120;
                boolean fa = down(ccw, a, ha, x, y), fb = down(cw, b, hb, x, y);
                assertEquals(fa, fb, "pixel " + i + "," + j);
                if (fa) {
                    assertEquals(ha.t, hb.t, 0);
                }
            }
        }
    }

    @Test
    void aRayThroughAHoleHitsWhatLiesBehindIt() {
        BezierPatch below = new BezierPatch(1, 1, new double[] {0, 0, -1, 1, 0, -1, 0, 1, -1, 1, 1, -1});
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(plate(true), below)), IntersectOptions.defaults());
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        assertTrue(down(si, ctx, hit, 0.5, 0.5));
        assertEquals(1, hit.index);
        assertEquals(2, hit.t, 1e-12);
        assertTrue(down(si, ctx, hit, 0.5, 0.8));
        assertEquals(0, hit.index);
    }

    /**
     * A trough {@code z = x²} (u across, v along) with a hole in its near wall: a level ray through
     * the hole meets the far wall of the same patch, also when the whole patch is one leaf. (Not
     * for subdivision on the whole patch: it chooses its split direction by the ray-space chords of
     * the net, which are 0 across this trough along the ray, and misses the untrimmed trough too.)
     */
    @ParameterizedTest
    @EnumSource(Method.class)
    void aRayThroughAHoleFindsTheFartherRootOfTheSameLeaf(Method method) {
        double[] net = {-1, 0, 1, 0, 0, -1, 1, 0, 1, -1, 1, 1, 0, 1, -1, 1, 1, 1};
        double hu = (1 - H) / 2; // u of x = -√½, where z = ½
        TrimRegion hole = new TrimRegion(List.of(), List.of(circle(hu, 0.5, 0.1, true)));
        BezierPatch trough = new BezierPatch(2, 1, net, null, new PatchDomain(0, 1, 0, 1, hole), null);
        for (boolean bvh : method == Method.SUBDIVISION ? new boolean[] {true} : new boolean[] {true, false}) {
            SceneIntersector si = SceneIntersector.build(new Scene(List.of(trough)),
                    IntersectOptions.defaults().withMethod(method).withBvh(bvh));
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            assertTrue(si.closestHit(ctx, -2, 0.5, 0.5, 1, 0, 0, 0, Double.POSITIVE_INFINITY, hit), method + " bvh " + bvh);
            assertEquals(2 + H, hit.t, method == Method.SUBDIVISION ? 1e-3 : 1e-9, method + " bvh " + bvh);
            assertTrue(si.closestHit(ctx, -2, 0.8, 0.5, 1, 0, 0, 0, Double.POSITIVE_INFINITY, hit));
            assertEquals(2 - H, hit.t, method == Method.SUBDIVISION ? 1e-3 : 1e-9, "beside the hole");
        }
    }
}
