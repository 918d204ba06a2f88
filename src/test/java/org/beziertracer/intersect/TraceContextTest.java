package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * {@link TraceContext}'s ray space on its own: for directions of any length (1e-200 to 1e200) the
 * frame is orthonormal with {@code n3 = d/|d|}, {@code invLength = 1/|d|}; a point
 * {@code o + t·d + a·n1 + b·n2} maps to {@code (a, b, t·|d|)}, and the corner projection agrees
 * with the full one on the four corners of nets of unequal degrees at any offset. The traversal
 * stack only grows.
 */
class TraceContextTest {

    private static double dot(double ax, double ay, double az, double bx, double by, double bz) {
        return ax * bx + ay * by + az * bz;
    }

    @Test
    void theRayFrameIsOrthonormalAndAlongTheDirectionWhateverItsLength() {
        Random rnd = new Random(61);
        TraceContext c = new TraceContext();
        for (int trial = 0; trial < 3000; trial++) {
            double scale = Math.pow(10, -200 + 400 * rnd.nextDouble());
            double[] d = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            if (trial % 7 == 0) {
                d[trial % 3] = 0; // directions in a coordinate plane, and (below) along an axis
            }
            if (trial % 11 == 0) {
                d[(trial + 1) % 3] = 0;
                d[trial % 3] = 0;
            }
            double len = Math.sqrt(dot(d[0], d[1], d[2], d[0], d[1], d[2]));
            if (len == 0) {
                continue;
            }
            c.setRay(1, 2, 3, d[0] * scale, d[1] * scale, d[2] * scale);
            String where = "trial " + trial + " scale " + scale;
            assertEquals(1, c.invLength * len * scale, ROUNDING, "invLength = 1/|d|, " + where);
            assertEquals(d[0] / len, c.n3x, ROUNDING, where);
            assertEquals(d[1] / len, c.n3y, ROUNDING, where);
            assertEquals(d[2] / len, c.n3z, ROUNDING, where);
            assertEquals(1, dot(c.n1x, c.n1y, c.n1z, c.n1x, c.n1y, c.n1z), ROUNDING, where);
            assertEquals(1, dot(c.n2x, c.n2y, c.n2z, c.n2x, c.n2y, c.n2z), ROUNDING, where);
            assertEquals(0, dot(c.n1x, c.n1y, c.n1z, c.n2x, c.n2y, c.n2z), ROUNDING, where);
            assertEquals(0, dot(c.n1x, c.n1y, c.n1z, c.n3x, c.n3y, c.n3z), ROUNDING, where);
            assertEquals(0, dot(c.n2x, c.n2y, c.n2z, c.n3x, c.n3y, c.n3z), ROUNDING, where);
            // right-handed: n1 × n2 = n3
            assertEquals(c.n3z, c.n1x * c.n2y - c.n1y * c.n2x, ROUNDING, where);
            assertEquals(1 / (d[0] * scale), c.invDx, Math.abs(ROUNDING * c.invDx), where);
            assertEquals(1 / (d[2] * scale), c.invDz, Math.abs(ROUNDING * c.invDz), where);
        }
    }

    /**
     * Directions whose squared length lies just inside and just outside the range where
     * {@code setRay} normalises without scaling first, with one component far below the others
     * (its square underflows): the same frame either side of the switch.
     */
    @Test
    void theFrameIsTheSameEitherSideOfTheUnscaledRange() {
        TraceContext c = new TraceContext();
        for (double squared : new double[] {TraceContext.SQUARES_FROM, TraceContext.SQUARES_TO}) {
            for (double factor : new double[] {0.5, 0.999, 1.001, 2}) {
                double len = Math.sqrt(squared * factor);
                double[] d = {0.6 * len, -0.8 * len, 1e-30 * len};
                c.setRay(0, 0, 0, d[0], d[1], d[2]);
                String where = "|d|² = " + squared * factor;
                assertEquals(1, c.invLength * len, ROUNDING, where);
                assertEquals(0.6, c.n3x, ROUNDING, where);
                assertEquals(-0.8, c.n3y, ROUNDING, where);
                assertEquals(1e-30, c.n3z, 1e-45, where);
                assertEquals(1, dot(c.n1x, c.n1y, c.n1z, c.n1x, c.n1y, c.n1z), ROUNDING, where);
                assertEquals(0, dot(c.n1x, c.n1y, c.n1z, c.n3x, c.n3y, c.n3z), ROUNDING, where);
            }
        }
    }

    @Test
    void aPointMapsToItsDistancesFromTheRaysPlanesAndAlongTheRay() {
        Random rnd = new Random(62);
        TraceContext c = new TraceContext();
        double[] src = new double[3 * 5], dest = new double[3 * 6];
        for (int trial = 0; trial < 500; trial++) {
            double ox = 10 * rnd.nextGaussian(), oy = 10 * rnd.nextGaussian(), oz = 10 * rnd.nextGaussian();
            double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
            c.setRay(ox, oy, oz, dx, dy, dz);
            double len = Math.sqrt(dot(dx, dy, dz, dx, dy, dz));
            double[][] abt = new double[5][];
            for (int k = 0; k < 5; k++) {
                double a = rnd.nextGaussian(), b = rnd.nextGaussian(), t = 3 * rnd.nextGaussian();
                abt[k] = new double[] {a, b, t * len};
                src[3 * k] = ox + t * dx + a * c.n1x + b * c.n2x;
                src[3 * k + 1] = oy + t * dy + a * c.n1y + b * c.n2y;
                src[3 * k + 2] = oz + t * dz + a * c.n1z + b * c.n2z;
            }
            c.project(src, 3, 4, dest, 6);
            for (int k = 1; k < 5; k++) {
                double tol = 64 * ROUNDING * (1 + Math.abs(ox) + Math.abs(oy) + Math.abs(oz));
                for (int i = 0; i < 3; i++) {
                    assertEquals(abt[k][i], dest[6 + 3 * (k - 1) + i], tol, "trial " + trial + " point " + k);
                }
            }
            assertEquals(0, dest[0], 0, "before the destination offset: untouched");
        }
    }

    @Test
    void theCornerProjectionIsTheFullProjectionOfTheFourCorners() {
        Random rnd = new Random(63);
        TraceContext c = new TraceContext();
        double[] full = new double[3], out = new double[8];
        for (int trial = 0; trial < 300; trial++) {
            int n = 1 + rnd.nextInt(5), m = 1 + rnd.nextInt(5), off = 3 * rnd.nextInt(4);
            double[] net = new double[off + 3 * (n + 1) * (m + 1)];
            for (int i = 0; i < net.length; i++) {
                net[i] = 5 * rnd.nextGaussian();
            }
            c.setRay(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(),
                    rnd.nextGaussian(), rnd.nextGaussian());
            c.projectCorners(net, off, n, m, out);
            int[][] corners = {{0, 0}, {n, 0}, {0, m}, {n, m}};
            for (int k = 0; k < 4; k++) {
                c.project(net, off + 3 * (corners[k][1] * (n + 1) + corners[k][0]), 1, full, 0);
                String where = "trial " + trial + " degree " + n + "x" + m + " corner " + k;
                assertEquals(full[0], out[2 * k], ROUNDING * 40, where);
                assertEquals(full[1], out[2 * k + 1], ROUNDING * 40, where);
            }
        }
    }

    @Test
    void theStackGrowsForADeeperTreeAndIsKeptOtherwise() {
        TraceContext c = new TraceContext();
        int[] first = c.stack;
        c.ensureStack(first.length);
        assertSame(first, c.stack, "deep enough: no new array");
        c.ensureStack(1);
        assertSame(first, c.stack);
        c.ensureStack(first.length + 1);
        assertNotSame(first, c.stack);
        assertTrue(c.stack.length >= first.length + 1);
    }

    /**
     * A traversal's ray has no frame until a leaf asks for it, and then the frame {@code setRay}
     * makes, to the bit; the next ray's traversal drops it again. Queries through the scene answer
     * every ray with its own frame (two rays in turn, the second a different direction).
     */
    @Test
    void aTraversalsFrameIsMadeOnDemandAndIsTheRaysOwn() {
        Random rnd = new Random(96);
        TraceContext lazy = new TraceContext(), eager = new TraceContext();
        for (int trial = 0; trial < 200; trial++) {
            double ox = rnd.nextGaussian(), oy = rnd.nextGaussian(), oz = rnd.nextGaussian();
            double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
            lazy.setTraversal(ox, oy, oz, dx, dy, dz);
            assertTrue(!lazy.planesSet, "a traversal starts without a frame");
            assertEquals(1 / dx, lazy.invDx);
            lazy.ensurePlanes();
            eager.setRay(ox, oy, oz, dx, dy, dz);
            assertTrue(lazy.planesSet && eager.planesSet);
            double[] a = {lazy.n1x, lazy.n1y, lazy.n1z, lazy.n2x, lazy.n2y, lazy.n2z, lazy.n3x, lazy.n3y, lazy.n3z,
                    lazy.invLength};
            double[] b = {eager.n1x, eager.n1y, eager.n1z, eager.n2x, eager.n2y, eager.n2z, eager.n3x, eager.n3y,
                    eager.n3z, eager.invLength};
            org.junit.jupiter.api.Assertions.assertArrayEquals(b, a, 0, "trial " + trial);
        }
        // Through the scene: the teapot hit from two sides in turn, each against a fresh context
        SceneIntersector si = SceneIntersector.build(org.beziertracer.model.io.Models.teapot(),
                IntersectOptions.defaults());
        TraceContext shared = si.newContext();
        Hit hit = new Hit();
        double[][] rays = {{0, -300, 40, 0, 1, 0}, {-300, 0, 40, 1, 0, 0}, {0, 0, 300, 0.01, 0.02, -1}};
        for (int round = 0; round < 2; round++) {
            for (double[] r : rays) {
                TraceContext fresh = si.newContext();
                Hit expected = new Hit();
                assertTrue(si.closestHit(fresh, r[0], r[1], r[2], r[3], r[4], r[5], 0, Double.POSITIVE_INFINITY, expected));
                assertTrue(si.closestHit(shared, r[0], r[1], r[2], r[3], r[4], r[5], 0, Double.POSITIVE_INFINITY, hit));
                assertEquals(expected.t, hit.t, 0);
                assertEquals(expected.u, hit.u, 0);
            }
        }
    }
}
