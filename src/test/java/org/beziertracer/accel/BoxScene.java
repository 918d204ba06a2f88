package org.beziertracer.accel;

import java.util.Arrays;
import java.util.Random;

/**
 * Test fixture: seeded random boxes and rays, a leaf callback whose "primitive" is the box itself
 * (hit distance = ray–box entry distance), and the brute-force answer to compare with. The scene
 * is its own per-query state: a callback that receives any other query object fails.
 */
final class BoxScene implements LeafIntersector<BoxScene>, LeafOccluder<BoxScene> {

    final double[] bounds;
    final int primCount;
    /** Current ray: origin, reciprocal direction, tMin. */
    double ox, oy, oz, invDx, invDy, invDz, tMin;
    int[] calls;
    /** Primitives called back since {@link #resetCalls()}, in call order. */
    int[] called;
    int calledCount;
    /** A primitive called back twice since {@link #resetCalls()}, or -1. */
    int calledTwice = -1;
    int closestPrim = -1;

    BoxScene(double[] bounds, int primCount) {
        this.bounds = bounds;
        this.primCount = primCount;
        this.calls = new int[primCount];
        this.called = new int[primCount];
    }

    /**
     * Random boxes in {@code [-10, 10]^3}: sizes spanning three orders of magnitude, about 10 %
     * flat in one axis, 2 % points, 5 % exact duplicates of an earlier box.
     */
    static double[] randomBoxes(Random rnd, int n) {
        double[] b = new double[6 * n];
        for (int p = 0; p < n; p++) {
            int o = 6 * p;
            if (p > 0 && rnd.nextDouble() < 0.05) {
                System.arraycopy(b, 6 * rnd.nextInt(p), b, o, 6);
                continue;
            }
            double size = Math.pow(10, -2 + 3 * rnd.nextDouble());
            double kind = rnd.nextDouble();
            for (int a = 0; a < 3; a++) {
                double c = -10 + 20 * rnd.nextDouble();
                double half = kind < 0.02 ? 0 : 0.5 * size * rnd.nextDouble();
                b[o + a] = c - half;
                b[o + 3 + a] = c + half;
            }
            if (kind >= 0.02 && kind < 0.12) {
                int a = rnd.nextInt(3);
                b[o + a] = b[o + 3 + a];
            }
        }
        return b;
    }

    /** All {@code n} boxes equal to {@code [0,1]^3}. */
    static double[] identicalBoxes(int n) {
        double[] b = new double[6 * n];
        for (int p = 0; p < n; p++) {
            System.arraycopy(new double[] {0, 0, 0, 1, 1, 1}, 0, b, 6 * p, 6);
        }
        return b;
    }

    /**
     * Sets a random ray: origin in {@code [-15, 15]^3}; a third of rays parallel to an axis (with
     * signed zeros in the other components), and half of those start exactly on a plane of some
     * box, where {@code 0 * Infinity} would give NaN.
     */
    void randomRay(Random rnd) {
        double[] o = {-15 + 30 * rnd.nextDouble(), -15 + 30 * rnd.nextDouble(), -15 + 30 * rnd.nextDouble()};
        double[] d = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
        if (primCount > 0 && rnd.nextInt(3) == 0) {
            // Aim at a random point of a random box
            int box = 6 * rnd.nextInt(primCount);
            for (int a = 0; a < 3; a++) {
                double lo = bounds[box + a], hi = bounds[box + 3 + a];
                d[a] = lo + (hi - lo) * rnd.nextDouble() - o[a];
            }
        }
        if (rnd.nextInt(3) == 0) {
            int axis = rnd.nextInt(3);
            for (int a = 0; a < 3; a++) {
                if (a != axis) {
                    d[a] = rnd.nextBoolean() ? 0.0 : -0.0;
                    if (primCount > 0 && rnd.nextBoolean()) {
                        o[a] = bounds[6 * rnd.nextInt(primCount) + a + (rnd.nextBoolean() ? 3 : 0)];
                    }
                }
            }
        }
        setRay(o[0], o[1], o[2], d[0], d[1], d[2], rnd.nextInt(4) == 0 ? 1.0 : 0.0);
    }

    void setRay(double ox, double oy, double oz, double dx, double dy, double dz, double tMin) {
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        this.invDx = 1 / dx;
        this.invDy = 1 / dy;
        this.invDz = 1 / dz;
        this.tMin = tMin;
    }

    String ray() {
        return String.format(java.util.Locale.ROOT, "ray o=(%s, %s, %s) invD=(%s, %s, %s) tMin=%s",
                ox, oy, oz, invDx, invDy, invDz, tMin);
    }

    double entry(int prim, double tMax) {
        return RayBox.entry(bounds, 6 * prim, ox, oy, oz, invDx, invDy, invDz, tMin, tMax);
    }

    @Override
    public double intersect(BoxScene query, int prim, double tMax) {
        checkQuery(query);
        if (calls[prim]++ == 0) {
            called[calledCount++] = prim;
        } else {
            calledTwice = prim;
        }
        double t = entry(prim, tMax);
        if (t < tMax) {
            closestPrim = prim;
            return t;
        }
        return tMax;
    }

    @Override
    public boolean occludes(BoxScene query, int prim, double tMax) {
        checkQuery(query);
        return entry(prim, tMax) < tMax;
    }

    private void checkQuery(BoxScene query) {
        if (query != this) {
            throw new AssertionError("the accelerator passed another query object: " + query);
        }
    }

    /** Brute-force closest hit over every primitive. */
    double bruteForce(double tMax) {
        for (int p = 0; p < primCount; p++) {
            double t = entry(p, tMax);
            if (t < tMax) {
                tMax = t;
            }
        }
        return tMax;
    }

    void resetCalls() {
        for (int k = 0; k < calledCount; k++) {
            calls[called[k]] = 0;
        }
        calledCount = 0;
        calledTwice = -1;
        closestPrim = -1;
    }

    String box(int prim) {
        return Arrays.toString(Arrays.copyOfRange(bounds, 6 * prim, 6 * prim + 6));
    }
}
