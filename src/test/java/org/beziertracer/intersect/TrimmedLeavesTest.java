package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.Tolerances.ROOT_UV;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * {@link TrimmedLeaves}: a snapshot of a trimmed scene edited into another trimmed scene still
 * tests its trims; on a curved trimmed patch every ray gets the nearest reference root that lies
 * in the material (the leaves wholly inside, partly inside and the retries beyond a rejected root).
 * The second was red before: Newton accepts a root in a leaf's overlapped domain, so a leaf wholly
 * inside the trim region returned roots beyond the outer trim curve untested.
 */
class TrimmedLeavesTest {

    private static BezierPatch lifted(BezierPatch p, double dz) {
        double[] net = p.copyNet();
        for (int k = 2; k < net.length; k += 3) {
            net[k] += dz;
        }
        return new BezierPatch(p.degreeU(), p.degreeV(), net, null, p.domain(), null);
    }

    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "NEWTON"})
    void anEditedTrimmedSnapshotStillTestsItsTrims(Method method) {
        BezierPatch plate = TrimmedIntersectionTest.plate(true);
        SceneIntersector before = SceneIntersector.build(new Scene(List.of(plate)), IntersectOptions.defaults().withMethod(method));
        SceneIntersector si = before.withPatch(0, lifted(plate, 1)); // the plate moved up to z = 1
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(1995);
        int hits = 0, holes = 0;
        for (int r = 0; r < 800; r++) {
            double x = rnd.nextDouble(), y = rnd.nextDouble();
            if (Math.abs(Math.hypot(x - 0.5, y - 0.5) - 0.2) < 1e-3 || Math.min(Math.abs(x - 0.1), Math.abs(y - 0.1)) < 1e-3) {
                continue; // too near a trim curve to judge here
            }
            boolean found = si.closestHit(ctx, x, y, 3, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit);
            String where = method + " at (" + x + ", " + y + ")";
            if (!TrimmedIntersectionTest.material(x, y)) {
                assertFalse(found, "through a hole: " + where);
                holes++;
                continue;
            }
            assertTrue(found, "material: " + where);
            assertEquals(2, hit.t, ROOT_T, where);
            assertEquals(x, hit.u, ROOT_UV, where);
            assertEquals(y, hit.v, ROOT_UV, where);
            hits++;
        }
        assertTrue(hits > 300 && holes > 150, hits + " hits, " + holes + " through holes");
    }

    /** A bumpy bicubic height field over [0,1]² trimmed to [0.1,0.9]² minus a disc. */
    private static BezierPatch trimmedBump(Random rnd) {
        BezierPatch bump = RandomPatches.heightField(rnd, 3, 3, 1, 0.8);
        double[] net = bump.copyNet();
        for (int j = 0; j <= 3; j++) {
            for (int i = 0; i <= 3; i++) { // x = u, y = v exactly, so (u,v) of a hit is its (x,y)
                net[3 * (4 * j + i)] = i / 3.0;
                net[3 * (4 * j + i) + 1] = j / 3.0;
            }
        }
        TrimRegion region = new TrimRegion(List.of(TrimmedIntersectionTest.polygon(0.1, 0.1, 0.9, 0.1, 0.9, 0.9, 0.1, 0.9)),
                List.of(TrimmedIntersectionTest.circle(0.55, 0.45, 0.15, true)));
        return new BezierPatch(3, 3, net, null, new PatchDomain(0, 1, 0, 1, region), null);
    }

    private static boolean inMaterial(double u, double v) {
        return u > 0.1 && u < 0.9 && v > 0.1 && v < 0.9 && Math.hypot(u - 0.55, v - 0.45) > 0.15;
    }

    private static boolean nearTrim(double u, double v) {
        return Math.min(Math.min(Math.abs(u - 0.1), Math.abs(u - 0.9)), Math.min(Math.abs(v - 0.1), Math.abs(v - 0.9))) < 1e-4
                || Math.abs(Math.hypot(u - 0.55, v - 0.45) - 0.15) < 1e-4;
    }

    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "NEWTON"})
    void raysAtATrimmedBumpGetTheNearestRootInTheMaterial(Method method) {
        Random rnd = new Random(1996);
        int hits = 0, misses = 0;
        for (int trial = 0; trial < 20; trial++) {
            BezierPatch patch = trimmedBump(rnd);
            SceneIntersector si = SceneIntersector.build(new Scene(List.of(patch)), IntersectOptions.defaults().withMethod(method));
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            rays:
            for (int r = 0; r < 60; r++) {
                // from above at every slant, some grazing the bumps
                double tx = 1.2 * rnd.nextDouble() - 0.1, ty = 1.2 * rnd.nextDouble() - 0.1;
                double ox = tx + 2 * rnd.nextGaussian(), oy = ty + 2 * rnd.nextGaussian(), oz = 0.2 + rnd.nextDouble();
                double dx = tx - ox, dy = ty - oy, dz = -oz;
                double[] want = null;
                double from = 0;
                for (int k = 0; k < 6; k++) { // the nearest reference root in the material
                    double[] root = ReferenceIntersector.nearest(patch, ox, oy, oz, dx, dy, dz, from, Double.POSITIVE_INFINITY, 32);
                    if (root == null) {
                        break;
                    }
                    if (nearTrim(root[1], root[2])) {
                        continue rays;
                    }
                    if (inMaterial(root[1], root[2])) {
                        want = root;
                        break;
                    }
                    from = root[0] + 1e-9;
                }
                boolean found = si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit);
                String where = method + " trial " + trial + " ray " + r;
                assertEquals(want != null, found, where + " hit " + hit.t + " (" + hit.u + ", " + hit.v + ") ref from " + from + " o " + ox + "," + oy + "," + oz + " d " + dx + "," + dy + "," + dz);
                if (want == null) {
                    misses++;
                    continue;
                }
                hits++;
                assertEquals(want[0], hit.t, ROOT_T, where);
                assertEquals(want[1], hit.u, ROOT_UV, where);
                assertEquals(want[2], hit.v, ROOT_UV, where);
            }
        }
        assertTrue(hits > 300 && misses > 100, hits + " hits, " + misses + " misses");
    }
}
