package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link OriginLeaf}: a shadow ray is never told "no hit" on its own leaf when the leaf does meet
 * it, and the proof does skip the leaf on convex surfaces (seeded, against the clipping search).
 */
class OriginLeafTest {

    /** What one scene's trials saw. */
    /**
     * What one scene's trials saw; {@code nearOriginStarts}: any-hit Newton attempts on the ray's own
     * leaf left out because they would start near its origin ({@link OriginLeaf#awayFromOrigin}).
     */
    record Tally(int rays, int proven, int ownLeafHits, int neighboursProven, long nearOriginStarts) {}

    /**
     * Rays at random points of {@code scene} from random directions; at each hit a shadow ray
     * leaves the point (offset along the normal on the arriving side, as the renderer does) in a
     * random direction on that side, a third of them grazing. Asserts: {@link
     * SceneIntersector#occludedLeaving} answers as {@link SceneIntersector#occluded}; whenever
     * {@link OriginLeaf#cannotMeet} holds, the clipping search finds no root of the ray on that
     * leaf beyond the origin.
     */
    static Tally check(Scene scene, Random rnd, int trials, String in) {
        return check(scene, IntersectOptions.defaults(), rnd, trials, in);
    }

    /** As {@link #check(Scene, Random, int, String)}, with these options. */
    static Tally check(Scene scene, IntersectOptions options, Random rnd, int trials, String in) {
        SceneIntersector si = SceneIntersector.build(scene, options);
        PatchLeaves leaves = (PatchLeaves) si.leaves;
        TraceContext ctx = si.newContext();
        SurfacePoint sp = new SurfacePoint();
        int rays = 0, proven = 0, own = 0, neighbours = 0;
        for (int trial = 0; trial < trials; trial++) {
            // From a random hit, a direction on the normal's side: random, a third of them grazing (5° or less)
            ShadowRays.ShadowRay sr = ShadowRays.atRandomHit(si, ctx, rnd, trial % 3 == 0, 1e-3, sp);
            if (sr == null) {
                continue;
            }
            Hit from = sr.from();
            double nx = sr.nx(), ny = sr.ny(), nz = sr.nz(), ox = sr.ox(), oy = sr.oy(), oz = sr.oz();
            double lx = sr.lx(), ly = sr.ly(), lz = sr.lz(), far = sr.far();
            rays++;
            String ray = in + ", trial " + trial;
            boolean plain = si.occluded(ctx, ox, oy, oz, lx, ly, lz, 0, far);
            // Twice, so that a leaf remembered as unprovable is also answered
            assertEquals(plain, si.occludedLeaving(ctx, from, sp, nx, ny, nz, ox, oy, oz, lx, ly, lz, 0, far), ray);
            assertEquals(plain, si.occludedLeaving(ctx, from, sp, nx, ny, nz, ox, oy, oz, lx, ly, lz, 0, far), ray);
            // The test itself, on a fresh memory, and the clipping search on the same leaf
            TraceContext fresh = si.newContext();
            fresh.setRay(ox, oy, oz, lx, ly, lz);
            fresh.tMin = 0;
            fresh.anyHit = false;
            fresh.leaving(from.subPatch, from.u, from.v, sp.px, sp.py, sp.pz, nx, ny, nz);
            boolean skip = OriginLeaf.cannotMeet(fresh, leaves.table, from.subPatch);
            boolean meets = leaves.solve(fresh, from.subPatch, 0, far);
            assertFalse(skip && meets, () -> ray + ": the proof skips a leaf the ray meets at t = " + fresh.rootT);
            proven += skip ? 1 : 0;
            own += meets ? 1 : 0;
            // The other leaves of the same patch: the proof splits them at the point nearest the
            // origin's (u, v); whenever it holds, the search finds no root there either
            int k = leaves.table.parent[from.subPatch];
            for (int s = leaves.table.firstOf[k]; s < leaves.table.firstOf[k + 1]; s++) {
                if (s == from.subPatch) {
                    continue;
                }
                fresh.setRay(ox, oy, oz, lx, ly, lz);
                boolean skipOther = OriginLeaf.cannotMeet(fresh, leaves.table, s);
                if (skipOther) {
                    int leaf = s;
                    assertFalse(leaves.solve(fresh, s, 0, far),
                            () -> ray + ": the proof skips leaf " + leaf + ", which the ray meets at t = " + fresh.rootT);
                    neighbours++;
                }
            }
        }
        return new Tally(rays, proven, own, neighbours, ctx.nearOriginStarts);
    }

    @Test
    void theTeapotsOwnLeavesAreMostlyProvenAndNeverWrongly() {
        Tally t = check(Models.teapot(), new Random(70), 1500, "teapot");
        assertTrue(t.rays() > 500, "too few hits: " + t);
        assertTrue(t.proven() > t.rays() / 2, "the convex teapot should mostly be proven: " + t);
        assertTrue(t.neighboursProven() > t.rays(), "the neighbouring leaves of the same patch too: " + t);
    }

    @Test
    void randomSurfacesOfDegreeOneToFifteenAreNeverWronglySkipped() {
        Random rnd = new Random(71);
        int proven = 0, own = 0;
        long nearOrigin = 0;
        for (int degree = 1; degree <= 15; degree++) {
            int m = 1 + rnd.nextInt(degree);
            BezierPatch patch = switch (degree % 3) {
                case 0 -> RandomPatches.heightField(rnd, degree, m, 4, 1 + rnd.nextDouble());
                case 1 -> RandomPatches.wild(rnd, degree, m, 4);
                default -> dome(rnd, degree, m);
            };
            List<BezierPatch> patches = List.of(patch);
            Tally t = check(new Scene(patches), rnd, 300, "degree " + degree + "x" + m);
            proven += t.proven();
            own += t.ownLeafHits();
            nearOrigin += t.nearOriginStarts();
        }
        // Both kinds of leaf occur: proven ones, and ones the shadow ray does meet again
        assertTrue(proven > 50, "proofs: " + proven);
        assertTrue(own > 20, "shadow rays meeting their own leaf: " + own);
        // ... and answers as the plain query although Newton's attempt near the origin was left out
        assertTrue(nearOrigin > 200, "own leaves searched without that attempt: " + nearOrigin);
    }

    @Test
    void aBumpOnAConvexCapIsNeverSkippedWhicheverPieceOfTheLeafItRisesIn() {
        // Shadow rays graze a convex cap that carries a bump somewhere, kept whole (one leaf):
        // the ray leaves a point below its tangent plane in most directions but meets the bump
        // in one of the four pieces around it, and the leaf must be searched
        Random rnd = new Random(72);
        IntersectOptions whole = IntersectOptions.defaults().withSplit(SplitOptions.wholePatches());
        int own = 0;
        long nearOrigin = 0;
        for (int trial = 0; trial < 40; trial++) {
            int n = 4 + rnd.nextInt(6), m = 4 + rnd.nextInt(6);
            Tally t = check(new Scene(List.of(bumpyDome(rnd, n, m))), whole, rnd, 150, "bumpy cap " + trial);
            own += t.ownLeafHits();
            nearOrigin += t.nearOriginStarts();
        }
        assertTrue(own > 30, "shadow rays meeting their own leaf: " + own);
        assertTrue(nearOrigin > 1000, "own leaves searched without Newton's attempt near the origin: " + nearOrigin);
    }

    @Test
    void aProvenLeafLiesBelowTheOriginsPlaneAtEverySampledPoint() {
        // The claim itself, on one-leaf caps with a bump in a random place: when the test holds,
        // no point of a dense grid on the leaf rises above the plane through the ray's origin
        Random rnd = new Random(73);
        double[] e = new double[9], scratch = new double[org.beziertracer.geometry.DeCasteljau.SCRATCH_LENGTH];
        int proven = 0, refused = 0;
        for (int trial = 0; trial < 400; trial++) {
            int n = 3 + rnd.nextInt(7), m = 3 + rnd.nextInt(7);
            BezierPatch patch = trial % 4 == 0 ? dome(rnd, n, m) : bumpyDome(rnd, n, m);
            org.beziertracer.geometry.SubPatchTable table = org.beziertracer.geometry.SubPatchTable.build(
                    List.of(patch), SplitOptions.wholePatches());
            double[] net = patch.copyNet();
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            org.beziertracer.geometry.DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, e, scratch);
            double nx = e[4] * e[8] - e[5] * e[7], ny = e[5] * e[6] - e[3] * e[8], nz = e[3] * e[7] - e[4] * e[6];
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz) * Math.signum(nz);
            nx /= len;
            ny /= len;
            nz /= len;
            double h0 = 1e-6 * 8;
            TraceContext ctx = new TraceContext();
            double tx = rnd.nextGaussian(), ty = rnd.nextGaussian();
            ctx.setRay(e[0] + h0 * nx, e[1] + h0 * ny, e[2] + h0 * nz, nx + tx, ny + ty, nz + 1e-3);
            ctx.tMin = 0;
            ctx.leaving(0, u, v, e[0], e[1], e[2], nx, ny, nz);
            if (!(nx * ctx.dx + ny * ctx.dy + nz * ctx.dz > 0)) {
                continue;
            }
            if (!OriginLeaf.cannotMeet(ctx, table, 0)) {
                refused++;
                continue;
            }
            proven++;
            for (int i = 0; i <= 40; i++) {
                for (int j = 0; j <= 40; j++) {
                    org.beziertracer.geometry.DeCasteljau.evaluateWithDerivatives(net, 0, n, m, i / 40.0, j / 40.0, e,
                            scratch);
                    double h = nx * (e[0] - ctx.originPx) + ny * (e[1] - ctx.originPy) + nz * (e[2] - ctx.originPz);
                    assertTrue(h <= 0.5 * h0 + 1e-12, "trial " + trial + ": proven, but the point at (" + i / 40.0
                            + ", " + j / 40.0 + ") is " + h + " above the tangent plane");
                }
            }
        }
        assertTrue(proven > 40 && refused > 40, "proven " + proven + ", refused " + refused);
    }

    @Test
    void newtonStartsOnItsOwnLeafAtTheOriginsPoint() {
        // The start maps back to the hit's own (u, v) on its leaf, for plain and re-parametrised patches
        SceneIntersector si = SceneIntersector.build(Models.teapot(), IntersectOptions.defaults());
        org.beziertracer.geometry.SubPatchTable table = ((PatchLeaves) si.leaves).table;
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(75);
        int checked = 0;
        for (int trial = 0; trial < 300; trial++) {
            double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
            if (!si.closestHit(ctx, -300 * dx, -300 * dy, 40 - 300 * dz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit)) {
                continue;
            }
            int s = hit.subPatch;
            ctx.leaving(s, hit.u, hit.v, 0, 0, 0, 0, 0, 1);
            OriginLeaf.startAtOrigin(ctx, table, s);
            float[] box = table.boxes;
            double u = box[4 * s] + ctx.clip[0] * (box[4 * s + 1] - box[4 * s]);
            double v = box[4 * s + 2] + ctx.clip[1] * (box[4 * s + 3] - box[4 * s + 2]);
            double expectU = Math.min(box[4 * s + 1], Math.max(box[4 * s], hit.u));
            double expectV = Math.min(box[4 * s + 3], Math.max(box[4 * s + 2], hit.v));
            assertEquals(expectU, u, 1e-12, "trial " + trial);
            assertEquals(expectV, v, 1e-12, "trial " + trial);
            checked++;
        }
        assertTrue(checked > 100, "hits: " + checked);
    }

    @Test
    void thePiecesTestIsTheLargestCoefficientOfTheFourPiecesAgainstTheLimit() {
        // Against the four pieces made by the generic de Casteljau split (a scalar net as dim 1)
        Random rnd = new Random(74);
        for (int trial = 0; trial < 3000; trial++) {
            int n = 1 + rnd.nextInt(15), m = 1 + rnd.nextInt(15), points = (n + 1) * (m + 1);
            double[] w = new double[OriginLeaf.SCRATCH], net = new double[points];
            for (int k = 0; k < points; k++) {
                net[k] = rnd.nextGaussian();
            }
            double a = trial % 7 == 0 ? rnd.nextInt(2) : rnd.nextDouble(), b = trial % 5 == 0 ? rnd.nextInt(2) : rnd.nextDouble();
            double[] uLo = new double[points], uHi = new double[points], q0 = new double[points], q1 = new double[points];
            org.beziertracer.geometry.DeCasteljau.splitU(net, 0, n, m, 1, a, uLo, 0, uHi, 0);
            double max = Double.NEGATIVE_INFINITY;
            for (double[] half : new double[][] {uLo, uHi}) {
                org.beziertracer.geometry.DeCasteljau.splitV(half, 0, n, m, 1, b, q0, 0, q1, 0);
                for (int k = 0; k < points; k++) {
                    max = Math.max(max, Math.max(q0[k], q1[k]));
                }
            }
            // limits just below and just above the largest coefficient, and a random one
            for (double limit : new double[] {max - 1e-9, max + 1e-9, rnd.nextGaussian()}) {
                System.arraycopy(net, 0, w, 0, points);
                assertEquals(max <= limit, OriginLeaf.piecesBelow(w, n, m, a, b, limit),
                        "trial " + trial + ", degree " + n + "x" + m + ", split at " + a + ", " + b + ", limit " + limit);
            }
        }
    }

    /** {@link #dome} with a narrow bump at a random place. */
    static BezierPatch bumpyDome(Random rnd, int n, int m) {
        double[] net = dome(rnd, n, m).copyNet();
        double bx = 3 * rnd.nextDouble() - 1.5, by = 3 * rnd.nextDouble() - 1.5, height = 1 + 2 * rnd.nextDouble();
        for (int k = 0; k < net.length; k += 3) {
            double dx = net[k] - bx, dy = net[k + 1] - by;
            net[k + 2] += height * Math.exp(-(dx * dx + dy * dy) / 0.3);
        }
        return new BezierPatch(n, m, net);
    }

    /**
     * A cap bulging toward +z: on a regular grid, heights {@code c(1 − x² − y²)} as control
     * points. The surface is {@code c(1 − f(u) − g(v))} with {@code f, g} Bernstein sums of convex
     * data (convex) over a linear map to (x, y): a concave graph, below each of its tangent planes.
     */
    static BezierPatch dome(Random rnd, int n, int m) {
        double[] net = new double[3 * (n + 1) * (m + 1)];
        double bulge = 0.5 + rnd.nextDouble();
        for (int j = 0, k = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++, k += 3) {
                double x = 2.0 * i / n - 1, y = 2.0 * j / m - 1;
                net[k] = 2 * x;
                net[k + 1] = 2 * y;
                net[k + 2] = bulge * (1 - x * x - y * y);
            }
        }
        return new BezierPatch(n, m, net);
    }
}
