package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link OriginRoot}: when it clears a shadow ray's own leaf, the leaf does hold a root behind the
 * ray's origin and none ahead of it (the clipping search, without the shortcut, on a context that
 * knows nothing of the origin), and the shadow ray's answer is the plain query's. Seeded random
 * patches of degree 1..15, domes with bumps kept whole, and the teapot; a third of the shadow rays
 * graze their surface.
 */
class OriginRootTest {

    /** What one scene's rays saw. */
    /**
     * {@code quarters}: quarters of own leaves cleared so ({@link LeafQuarters}), in the renderer's
     * queries; {@code checkedQuarters}: those the test cleared itself and searched on their own.
     */
    record Tally(int rays, int cleared, int aheadOnOwnLeaf, long quarters, int checkedQuarters) {}

    /** Shadow rays of {@link #check}: trial {@code trial}'s, or null when its camera ray missed. */
    interface Source {
        ShadowRays.ShadowRay ray(SceneIntersector si, TraceContext ctx, Random rnd, int trial, SurfacePoint sp);
    }

    static Tally check(Scene scene, IntersectOptions options, Random rnd, int trials, String in) {
        // A direction on the normal's side: random, a third of them grazing (5° or less)
        return check(scene, options, rnd, trials, in,
                (si, ctx, r, trial, sp) -> ShadowRays.atRandomHit(si, ctx, r, trial % 3 == 0, 1e-4, sp));
    }

    static Tally check(Scene scene, IntersectOptions options, Random rnd, int trials, String in, Source source) {
        SceneIntersector si = SceneIntersector.build(scene, options);
        PatchLeaves leaves = (PatchLeaves) si.leaves;
        SubPatchTable tab = leaves.table;
        double tolerance = PatchLeaves.RELATIVE_TOLERANCE * scene.controlBounds().diagonal();
        TraceContext ctx = si.newContext();
        Hit from = new Hit();
        SurfacePoint sp = new SurfacePoint();
        int rays = 0, cleared = 0, ahead = 0, checked = 0;
        for (int trial = 0; trial < trials; trial++) {
            ShadowRays.ShadowRay sr = source.ray(si, ctx, rnd, trial, sp);
            if (sr == null) {
                continue;
            }
            from.set(sr.from());
            double nx = sr.nx(), ny = sr.ny(), nz = sr.nz(), ox = sr.ox(), oy = sr.oy(), oz = sr.oz();
            double lx = sr.lx(), ly = sr.ly(), lz = sr.lz(), far = sr.far();
            rays++;
            String ray = in + ", trial " + trial;
            // The answer of the renderer's query is the plain one's
            boolean plain = si.occluded(ctx, ox, oy, oz, lx, ly, lz, 0, far);
            assertEquals(plain, si.occludedLeaving(ctx, from, sp, nx, ny, nz, ox, oy, oz, lx, ly, lz, 0, far), ray);
            // The proof itself, on the ray's own leaf
            TraceContext probe = si.newContext();
            probe.setRay(ox, oy, oz, lx, ly, lz);
            probe.tMin = 0;
            probe.anyHit = true;
            probe.leaving(from.subPatch, from.u, from.v, sp, nx, ny, nz);
            boolean behind = OriginRoot.behind(probe, tab, from.subPatch, 0, tolerance);
            // The reference: clipping without the origin's shortcuts, for the nearest root ahead and
            // for roots behind
            TraceContext plainCtx = si.newContext();
            plainCtx.setRay(ox, oy, oz, lx, ly, lz);
            plainCtx.tMin = 0;
            boolean meets = leaves.solve(plainCtx, from.subPatch, 0, far);
            ahead += meets ? 1 : 0;
            // The same proof on each quarter of the leaf that its record proves single-root (as
            // LeafQuarters asks it): the clipping search on the quarter alone, a patch of its own,
            // finds no root ahead in a quarter it clears
            LeafQuarters quarters = LeafQuarters.of(tab);
            int k = tab.parent[from.subPatch];
            if (quarters != null && LeafQuarters.has(tab, k)) {
                quarters.ensure(probe, tab, from.subPatch);
                for (int q = 0; q < 4; q++) {
                    int o = LeafQuarters.STRIDE * from.subPatch + NewtonLeafRecords.STRIDE * q;
                    float[] rec = quarters.records;
                    double u0 = rec[o + NewtonLeafRecords.U0], u1 = u0 + rec[o + NewtonLeafRecords.DU];
                    double v0 = rec[o + NewtonLeafRecords.V0], v1 = v0 + rec[o + NewtonLeafRecords.DV];
                    if (NewtonSolver.start(probe, rec, o, 0, far, tolerance) != NewtonSolver.SINGLE_ROOT
                            || !OriginRoot.behindIn(probe, tab, k, u0, u1, v0, v1, 0, tolerance)) {
                        continue;
                    }
                    int n = tab.patchDegreeU[k], m = tab.patchDegreeV[k];
                    double[] net = new double[3 * (n + 1) * (m + 1)];
                    DeCasteljau.subPatch(tab.patchNets, tab.patchNetOffset[k], n, m, 3, u0, u1, v0, v1, net, 0);
                    SceneIntersector alone = SceneIntersector.build(new Scene(List.of(new BezierPatch(n, m, net))),
                            IntersectOptions.defaults().withSplit(SplitOptions.wholePatches()));
                    Hit there = new Hit();
                    int quarter = q;
                    assertFalse(alone.closestHit(alone.newContext(), ox, oy, oz, lx, ly, lz, 0, far, there),
                            () -> ray + ": cleared quarter " + quarter + ", which the ray meets at t = " + there.t);
                    checked++;
                }
            }
            if (behind) {
                cleared++;
                boolean unique = RootUniqueness.atMostOneRoot(plainCtx, tab, from.subPatch);
                assertFalse(unique && meets, () -> ray + ": cleared a single-root leaf the ray meets at t = " + plainCtx.rootT);
                plainCtx.setRay(ox, oy, oz, lx, ly, lz);
                plainCtx.tMin = -far;
                assertTrue(leaves.solve(plainCtx, from.subPatch, -far, 0), () -> ray + ": no root behind the origin");
            }
        }
        return new Tally(rays, cleared, ahead, ctx.originQuarters, checked);
    }

    @Test
    void randomSurfacesOfDegreeOneToFifteen() {
        Random rnd = new Random(91);
        int rays = 0, cleared = 0, ahead = 0;
        long quarters = 0, checked = 0;
        for (int degree = 1; degree <= 15; degree++) {
            int m = 1 + rnd.nextInt(15);
            List<BezierPatch> patches = new ArrayList<>();
            patches.add(switch (degree % 3) {
                case 0 -> RandomPatches.heightField(rnd, degree, m, 4, 0.5 + rnd.nextDouble());
                case 1 -> RandomPatches.wild(rnd, degree, m, 4);
                default -> OriginLeafTest.dome(rnd, degree, m);
            });
            Tally t = check(new Scene(patches), IntersectOptions.defaults(), rnd, 400, "degree " + degree + "x" + m);
            rays += t.rays();
            cleared += t.cleared();
            ahead += t.aheadOnOwnLeaf();
            quarters += t.quarters();
            checked += t.checkedQuarters();
        }
        // The proof holds for most rays, and rays that meet their own leaf again occur
        assertTrue(cleared > rays / 2, "cleared " + cleared + " of " + rays);
        assertTrue(ahead > 20, "rays meeting their own leaf ahead: " + ahead);
        assertTrue(quarters > 50, "quarters of own leaves cleared: " + quarters);
        assertTrue(checked > 500, "cleared quarters searched on their own: " + checked);
    }

    @Test
    void bumpyCapsKeptWholeWhereShadowRaysMeetTheirOwnLeaf() {
        Random rnd = new Random(92);
        IntersectOptions whole = IntersectOptions.defaults().withSplit(SplitOptions.wholePatches());
        int cleared = 0, ahead = 0;
        long quarters = 0;
        for (int trial = 0; trial < 40; trial++) {
            int n = 4 + rnd.nextInt(6), m = 4 + rnd.nextInt(6);
            Tally t = check(new Scene(List.of(OriginLeafTest.bumpyDome(rnd, n, m))), whole, rnd, 150, "bumpy cap " + trial);
            cleared += t.cleared();
            ahead += t.aheadOnOwnLeaf();
            quarters += t.quarters();
        }
        assertTrue(cleared > 100, "cleared " + cleared);
        assertTrue(quarters > 10, "quarters of own leaves cleared: " + quarters);
        assertTrue(ahead > 30, "rays meeting their own leaf ahead: " + ahead);
    }

    @Test
    void theTeapot() {
        Tally t = check(Models.teapot(), IntersectOptions.defaults(), new Random(93), 1500, "teapot");
        assertTrue(t.rays() > 500, "too few hits: " + t);
        assertTrue(t.cleared() > 0, "never cleared: " + t);
    }

    @Test
    void theTeapotsLeafBorders() {
        // Shadow rays from points on the borders of the teapot's leaves (and so on its patches'
        // borders, where two patches meet): the root's ball must lie in the leaf the hit names
        Scene teapot = Models.teapot();
        SubPatchTable tab = ((PatchLeaves) SceneIntersector.build(teapot, IntersectOptions.defaults()).leaves).table;
        double[] e = new double[9], scratch = new double[org.beziertracer.geometry.DeCasteljau.SCRATCH_LENGTH];
        Tally t = check(teapot, IntersectOptions.defaults(), new Random(96), 3000, "teapot border", (si, ctx, rnd, trial, sp) -> {
            int s = rnd.nextInt(tab.count), k = tab.parent[s], edge = rnd.nextInt(4);
            double along = rnd.nextDouble();
            double u = edge < 2 ? tab.boxes[4 * s + edge] : tab.boxes[4 * s] + along * (tab.boxes[4 * s + 1] - tab.boxes[4 * s]);
            double v = edge >= 2 ? tab.boxes[4 * s + edge] : tab.boxes[4 * s + 2] + along * (tab.boxes[4 * s + 3] - tab.boxes[4 * s + 2]);
            org.beziertracer.geometry.DeCasteljau.evaluateWithDerivatives(tab.patchNets, tab.patchNetOffset[k],
                    tab.patchDegreeU[k], tab.patchDegreeV[k], u, v, e, scratch);
            return ShadowRays.atHit(si, ctx, rnd, e[0], e[1], e[2], rnd.nextGaussian(), rnd.nextGaussian(),
                    rnd.nextGaussian(), trial % 3 == 0, 1e-4, sp);
        });
        assertTrue(t.rays() > 1500, "too few hits: " + t);
        assertTrue(t.cleared() > t.rays() / 4, "rarely cleared: " + t);
    }

    @Test
    void raysGrazingADomeAreClearedOnlyWhereTheLineMeetsTheDomeBehindTheOrigin() {
        // Leaving the top of a dome at an angle θ above its tangent plane, from h0 above it: the
        // line meets the dome behind the origin only when θ² ≥ 2κ·h0 (κ the curvature); below that
        // it passes over the dome altogether, and nothing may be claimed behind
        Random rnd = new Random(95);
        IntersectOptions whole = IntersectOptions.defaults().withSplit(SplitOptions.wholePatches());
        double[] e = new double[9], scratch = new double[org.beziertracer.geometry.DeCasteljau.SCRATCH_LENGTH];
        int cleared = 0, refused = 0;
        for (int trial = 0; trial < 600; trial++) {
            int n = 2 + rnd.nextInt(6), m = 2 + rnd.nextInt(6);
            BezierPatch dome = OriginLeafTest.dome(rnd, n, m);
            SceneIntersector si = SceneIntersector.build(new Scene(List.of(dome)), whole);
            PatchLeaves leaves = (PatchLeaves) si.leaves;
            double u = 0.2 + 0.6 * rnd.nextDouble(), v = 0.2 + 0.6 * rnd.nextDouble();
            org.beziertracer.geometry.DeCasteljau.evaluateWithDerivatives(dome.copyNet(), 0, n, m, u, v, e, scratch);
            double nx = e[4] * e[8] - e[5] * e[7], ny = e[5] * e[6] - e[3] * e[8], nz = e[3] * e[7] - e[4] * e[6];
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz) * Math.signum(nz);
            nx /= len;
            ny /= len;
            nz /= len;
            // a unit tangent, and the direction θ above it
            double ax = e[3] - (e[3] * nx + e[4] * ny + e[5] * nz) * nx, ay = e[4] - (e[3] * nx + e[4] * ny + e[5] * nz) * ny;
            double az = e[5] - (e[3] * nx + e[4] * ny + e[5] * nz) * nz, al = Math.sqrt(ax * ax + ay * ay + az * az);
            double theta = Math.pow(10, -5 + 4 * rnd.nextDouble()), c = Math.cos(theta) / al, sn = Math.sin(theta);
            double h0 = 1e-6 * 8;
            TraceContext ctx = si.newContext();
            ctx.setRay(e[0] + h0 * nx, e[1] + h0 * ny, e[2] + h0 * nz, c * ax + sn * nx, c * ay + sn * ny, c * az + sn * nz);
            ctx.tMin = 0;
            ctx.anyHit = true;
            SurfacePoint sp = new SurfacePoint();
            sp.px = e[0]; sp.py = e[1]; sp.pz = e[2];
            sp.dpdux = e[3]; sp.dpduy = e[4]; sp.dpduz = e[5];
            sp.dpdvx = e[6]; sp.dpdvy = e[7]; sp.dpdvz = e[8];
            ctx.leaving(0, u, v, sp, nx, ny, nz);
            if (!OriginRoot.behind(ctx, leaves.table, 0, 0, 1e-12 * 8)) {
                refused++;
                continue;
            }
            cleared++;
            TraceContext plain = si.newContext();
            plain.setRay(ctx.ox, ctx.oy, ctx.oz, ctx.dx, ctx.dy, ctx.dz);
            plain.tMin = -100;
            String ray = "dome " + trial + ", θ = " + theta;
            assertTrue(leaves.solve(plain, 0, -100, 0), () -> ray + ": cleared, but no root behind the origin");
            assertFalse(leaves.solve(plain, 0, 0, 100), () -> ray + ": cleared, but a root ahead at t = " + plain.rootT);
        }
        assertTrue(cleared > 200 && refused > 50, "cleared " + cleared + ", refused " + refused);
    }

    @Test
    void aRayThatLeavesNoKeptPointOrAnotherLeafIsNotCleared() {
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(OriginLeafTest.dome(new Random(94), 3, 3))),
                IntersectOptions.defaults().withSplit(SplitOptions.wholePatches()));
        SubPatchTable tab = ((PatchLeaves) si.leaves).table;
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        assertTrue(si.closestHit(ctx, 0.1, 0.2, 5, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit));
        si.surfacePoint(ctx, hit, sp);
        double ox = sp.px + 1e-6 * sp.nx, oy = sp.py + 1e-6 * sp.ny, oz = sp.pz + 1e-6 * sp.nz;
        ctx.setRay(ox, oy, oz, sp.nx + 0.3, sp.ny, sp.nz);
        ctx.leaving(hit.subPatch, hit.u, hit.v, sp, sp.nx, sp.ny, sp.nz);
        assertTrue(OriginRoot.behind(ctx, tab, hit.subPatch, 0, 1e-12), "the plain case");
        ctx.leaving(hit.subPatch, hit.u, hit.v, sp.px, sp.py, sp.pz, sp.nx, sp.ny, sp.nz);
        assertFalse(OriginRoot.behind(ctx, tab, hit.subPatch, 0, 1e-12), "no kept derivatives");
        ctx.leaving(-1, hit.u, hit.v, sp, sp.nx, sp.ny, sp.nz);
        assertFalse(OriginRoot.behind(ctx, tab, hit.subPatch, 0, 1e-12), "a ray that leaves no leaf");
        ctx.leaving(hit.subPatch, hit.u, hit.v, sp, sp.nx, sp.ny, sp.nz);
        assertFalse(OriginRoot.behind(ctx, tab, hit.subPatch, -1, 1e-12), "a query that starts behind the root");
        ctx.setRay(ox, oy, oz, -sp.nx + 0.3, -sp.ny, -sp.nz);
        ctx.leaving(hit.subPatch, hit.u, hit.v, sp, sp.nx, sp.ny, sp.nz);
        assertFalse(OriginRoot.behind(ctx, tab, hit.subPatch, 0, 1e-12), "a ray into the surface: its root is ahead");
        ctx.setRay(ox, oy, oz, 1, 0, 1e-9 - sp.nx / sp.nz);
        ctx.leaving(hit.subPatch, hit.u, hit.v, sp, sp.nx, sp.ny, sp.nz);
        assertFalse(OriginRoot.behind(ctx, tab, hit.subPatch, 0, 1e-12), "a ray along the tangent plane");
    }
}
