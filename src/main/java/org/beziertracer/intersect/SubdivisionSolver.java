package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.math.Bounds;

/**
 * Ray–patch intersection by recursive subdivision (memoir ch. I 3.3.3.1; Whitted 1980, Rubin and
 * Whitted 1980): the leaf's net, projected into ray space, is halved with de Casteljau until a
 * piece is smaller than a tolerance; pieces whose ray-space box misses the ray or lies beyond
 * the best hit are dropped; a small piece's control mesh is intersected as triangles (two per
 * quad), interpolating t and (u,v). The result is an approximation: its error is the distance
 * between the control mesh and the surface, which shrinks quadratically with the piece size.
 * A rational leaf is halved through its homogeneous ray-space net ({@link RationalNets}) and its
 * small pieces' Euclidean control meshes are intersected. Kept for comparison.
 */
final class SubdivisionSolver {
    private SubdivisionSolver() {}

    /** A piece is small enough when its ray-space extent is below this fraction of the leaf. */
    static final double TINY = 1e-3;
    static final int MAX_STEPS = 4000;
    /**
     * Barycentric slack of the final triangle test. Neighbouring patches (and neighbouring pieces)
     * are split at different parameters, so their control meshes' border polylines differ by
     * about the mesh-to-surface distance; growing each triangle slightly closes those cracks.
     */
    static final double EDGE_SLACK = 0.02;

    static boolean intersect(TraceContext ctx, SubPatchTable tab, int s, double tMin, double tMax, double tolerance) {
        int n = tab.degreeU[s], m = tab.degreeV[s];
        int points = (n + 1) * (m + 1), len = 3 * points;
        double[] arena = ctx.arena, boxes = ctx.entryBoxes;
        double leafU0 = tab.boxes[4 * s], leafDu = tab.boxes[4 * s + 1] - leafU0;
        double leafV0 = tab.boxes[4 * s + 2], leafDv = tab.boxes[4 * s + 3] - leafV0;
        double tiny = TINY * BezierClipper.leafSize(tab, s);
        ctx.project(tab.nets, tab.netOffset[s], points, arena, 0);
        boolean rational = RationalNets.rational(tab, s);
        if (rational) {
            RationalNets.weigh(ctx, tab, s, points);
        }
        boxes[0] = 0; boxes[1] = 1; boxes[2] = 0; boxes[3] = 1;
        int sp = 1, steps = 0;
        ctx.pieceBestT = tMax;
        ctx.pieceFound = false;
        double invLength = ctx.invLength;
        while (sp > 0 && ++steps <= MAX_STEPS) {
            int w = sp - 1, base = w * len, b4 = 4 * w;
            // Ray-space bounds of the piece: the ray must pass through it, within (tMin, best)
            double[] rb = ctx.rayBounds;
            if (rational) {
                RationalNets.rayBounds(ctx, w, points, rb);
            } else {
                Bounds.ofPoints(arena, base, points, rb);
            }
            double min1 = rb[0], min2 = rb[1], min3 = rb[2], max1 = rb[3], max2 = rb[4], max3 = rb[5];
            if (min1 > tolerance || max1 < -tolerance || min2 > tolerance || max2 < -tolerance
                    || min3 * invLength >= ctx.pieceBestT || max3 * invLength <= tMin) {
                sp--;
                continue;
            }
            if (Math.max(max1 - min1, max2 - min2) <= tiny || sp == TraceContext.MAX_ENTRIES) {
                if (rational) {
                    RationalNets.toEuclidean(ctx, w, points); // the control mesh of Euclidean points
                }
                intersectControlMesh(ctx, base, n, m, b4, tMin);
                sp--;
                continue;
            }
            // Halve the longer direction (in ray space) and visit the nearer half first
            boolean inU = PatchExtents.rayLengthU(arena, base, n, m) >= PatchExtents.rayLengthV(arena, base, n, m);
            boolean swapped = BezierClipper.split(ctx, arena, base, len, n, m, boxes, b4, inU);
            if (rational) {
                RationalNets.split(ctx, w, n, m, inU, swapped);
            }
            sp++;
        }
        if (ctx.pieceFound) {
            ctx.rootT = ctx.pieceBestT;
            // the triangle test's slack may reach slightly past the patch border
            ctx.rootU = Math.min(1, Math.max(0, leafU0 + leafDu * ctx.pieceBestU));
            ctx.rootV = Math.min(1, Math.max(0, leafV0 + leafDv * ctx.pieceBestV));
        }
        return ctx.pieceFound;
    }

    /**
     * Intersects the control mesh of the piece at {@code ctx.arena[base..]} (parameter box
     * {@code ctx.entryBoxes[b4..]}, local to the leaf) as triangles, two per quad, interpolating
     * t and (u,v); a hit nearer than {@code ctx.pieceBestT} becomes the best.
     */
    private static void intersectControlMesh(TraceContext ctx, int base, int n, int m, int b4, double tMin) {
        double[] arena = ctx.arena, boxes = ctx.entryBoxes;
        double u0 = boxes[b4], u1 = boxes[b4 + 1], v0 = boxes[b4 + 2], v1 = boxes[b4 + 3];
        double invLength = ctx.invLength;
        for (int j = 0; j < m; j++) {
            for (int i = 0; i < n; i++) {
                int p00 = base + 3 * (j * (n + 1) + i), p10 = p00 + 3;
                int p01 = p00 + 3 * (n + 1), p11 = p01 + 3;
                double ua = u0 + (u1 - u0) * i / n, ub = u0 + (u1 - u0) * (i + 1) / n;
                double va = v0 + (v1 - v0) * j / m, vb = v0 + (v1 - v0) * (j + 1) / m;
                for (int tri = 0; tri < 2; tri++) {
                    int pb = tri == 0 ? p10 : p11, pc = tri == 0 ? p11 : p01;
                    double ubb = ub, vbb = tri == 0 ? va : vb;
                    double ucc = tri == 0 ? ub : ua, vcc = vb;
                    if (triangle(arena, p00, pb, pc, ctx.clip)) {
                        double wb = ctx.clip[0], wc = ctx.clip[1], wa = 1 - wb - wc;
                        double t = (wa * arena[p00 + 2] + wb * arena[pb + 2] + wc * arena[pc + 2]) * invLength;
                        if (t > tMin && t < ctx.pieceBestT) {
                            ctx.pieceBestT = t;
                            ctx.pieceBestU = wa * ua + wb * ubb + wc * ucc;
                            ctx.pieceBestV = wa * va + wb * vbb + wc * vcc;
                            ctx.pieceFound = true;
                        }
                    }
                }
            }
        }
    }

    /**
     * 2-D test of the ray (the origin of ray space) against triangle (a, b, c) in the first two
     * coordinates; writes the barycentric weights of b and c into {@code w}.
     */
    static boolean triangle(double[] p, int a, int b, int c, double[] w) {
        double ax = p[a], ay = p[a + 1];
        double e1x = p[b] - ax, e1y = p[b + 1] - ay, e2x = p[c] - ax, e2y = p[c + 1] - ay;
        double det = e1x * e2y - e1y * e2x;
        if (det == 0) {
            return false;
        }
        double inv = 1.0 / det;
        double wb = (-ax * e2y + ay * e2x) * inv;
        double wc = (-ay * e1x + ax * e1y) * inv;
        if (wb < -EDGE_SLACK || wc < -EDGE_SLACK || wb + wc > 1 + EDGE_SLACK) {
            return false;
        }
        w[0] = wb;
        w[1] = wc;
        return true;
    }
}
