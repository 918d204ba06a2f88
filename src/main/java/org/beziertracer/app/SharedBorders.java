package org.beziertracer.app;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.beziertracer.geometry.BernsteinPoly;
import org.beziertracer.geometry.BorderStrip;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The borders of a model: pairs of patch sides whose corner points are welded as the editor welds
 * them ({@link WeldIndex}, the same tolerance), in the same order or reversed, whatever the sides
 * (u or v, first or last) and degrees. A side whose two corners are one handle (a collapsed edge,
 * a pole) bounds nothing and is left out. Only the corners decide: the inner points may differ,
 * which is what the continuity analysis measures as a gap. But two sides whose curves are farther
 * apart at their middle ({@code t = ½}) than {@value #ARC_FRACTION} of their chord are two arcs of
 * one loop — the half-circles that close the teapot's handle and spout tubes — not one border, and
 * are only counted ({@link Found#arcPairs}). Where more than two sides share corners (a
 * non-manifold border) every other pair is a border.
 *
 * <p>Sides are numbered as in {@code geometry.BorderStrip}: 0 {@code u=0}, 1 {@code u=1},
 * 2 {@code v=0}, 3 {@code v=1}. O(patches) after the weld index. Stateless.
 */
public final class SharedBorders {

    /** Sides farther apart at their middle than this fraction of their chord are arcs of one loop, not a border. */
    public static final double ARC_FRACTION = 0.5;

    private SharedBorders() {}

    /**
     * What {@link #find} found.
     *
     * @param borders  the borders, in patch and side order of their first side
     * @param arcPairs pairs of sides with welded corners left out as arcs of one loop
     */
    public record Found(List<Border> borders, int arcPairs) {}

    /**
     * A border: side {@code sideA} of patch {@code a} (0-based) and side {@code sideB} of patch
     * {@code b}, {@code a < b} or {@code a == b} with {@code sideA < sideB}.
     *
     * @param reversed B's side runs from A's last corner to its first
     */
    public record Border(int a, int sideA, int b, int sideB, boolean reversed) {}

    /** The borders of {@code scene}. */
    public static Found find(Scene scene, WeldIndex welds) {
        return find(scene, welds, () -> false);
    }

    /**
     * As {@link #find(Scene, WeldIndex)}, asking {@code cancelled} every
     * {@value WeldIndex#CANCEL_STEP} patches and stopping with a
     * {@link java.util.concurrent.CancellationException} once it says so.
     */
    public static Found find(Scene scene, WeldIndex welds, java.util.function.BooleanSupplier cancelled) {
        Map<Long, List<int[]>> byCorners = new LinkedHashMap<>();
        for (int p = 0; p < scene.patchCount(); p++) {
            if (p % WeldIndex.CANCEL_STEP == 0) {
                ContinuityAnalysis.stopIf(cancelled);
            }
            BezierPatch patch = scene.patches().get(p);
            for (int side = 0; side < 4; side++) {
                int[] ends = corners(patch, welds.patchStart(p), side);
                int first = welds.node(ends[0]), last = welds.node(ends[1]);
                if (first == last) {
                    continue; // a collapsed side
                }
                long key = ((long) Math.min(first, last) << 32) | Math.max(first, last);
                byCorners.computeIfAbsent(key, k -> new ArrayList<>()).add(new int[] {p, side, first});
            }
        }
        List<Border> out = new ArrayList<>();
        int arcs = 0;
        for (List<int[]> group : byCorners.values()) {
            for (int x = 0; x < group.size(); x++) {
                for (int y = x + 1; y < group.size(); y++) {
                    int[] e = group.get(x), f = group.get(y);
                    Border b = new Border(e[0], e[1], f[0], f[1], e[2] != f[2]);
                    if (arcsOfALoop(scene, b)) {
                        arcs++;
                    } else {
                        out.add(b);
                    }
                }
            }
        }
        out.sort((x, y) -> x.a() != y.a() ? Integer.compare(x.a(), y.a())
                : x.sideA() != y.sideA() ? Integer.compare(x.sideA(), y.sideA())
                : x.b() != y.b() ? Integer.compare(x.b(), y.b()) : Integer.compare(x.sideB(), y.sideB()));
        return new Found(List.copyOf(out), arcs);
    }

    /** True when the two sides' curves are farther apart at {@code t = ½} than {@link #ARC_FRACTION} of A's chord. */
    static boolean arcsOfALoop(Scene scene, Border b) {
        BernsteinPoly ca = BorderStrip.of(scene.patches().get(b.a()), b.sideA(), false, false).x();
        BernsteinPoly cb = BorderStrip.of(scene.patches().get(b.b()), b.sideB(), b.reversed(), false).x();
        double[] p0 = euclidean(ca.value(0)), p1 = euclidean(ca.value(1));
        double[] ma = euclidean(ca.value(0.5)), mb = euclidean(cb.value(0.5));
        return distance(ma, mb) > ARC_FRACTION * distance(p0, p1);
    }

    private static double[] euclidean(double[] h) {
        return new double[] {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
    }

    private static double distance(double[] p, double[] q) {
        return Math.sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    }

    /** Global numbers of the first and last corner of {@code side} (in its own parameter's order). */
    private static int[] corners(BezierPatch patch, int start, int side) {
        int n = patch.degreeU(), m = patch.degreeV();
        int i0, j0, i1, j1;
        switch (side) {
            case 0 -> { i0 = 0; j0 = 0; i1 = 0; j1 = m; }
            case 1 -> { i0 = n; j0 = 0; i1 = n; j1 = m; }
            case 2 -> { i0 = 0; j0 = 0; i1 = n; j1 = 0; }
            default -> { i0 = 0; j0 = m; i1 = n; j1 = m; }
        }
        return new int[] {start + j0 * (n + 1) + i0, start + j1 * (n + 1) + i1};
    }
}
