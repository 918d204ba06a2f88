package org.beziertracer.app;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Which control points coincide: points of a scene closer than {@link #RELATIVE_TOLERANCE} times
 * the scene's size (the diagonal of its control box) form one <i>handle</i>, so that dragging a
 * point two patches share moves both copies and the border stays shared. Built off the UI thread
 * in O(points): every point is bucketed by its coordinates quantised to cells of
 * {@value #CELL_PER_TOLERANCE} tolerances ({@link CellTable}), compared with the points of its own
 * cell and — only when it lies within a tolerance of a cell face — of the neighbouring cells, and
 * coincident points are joined with union–find (so a chain of points each within the tolerance of
 * the next is one handle).
 *
 * <h2>Layout</h2>
 * Points are numbered globally, patch after patch: point {@code k = j(n+1) + i} of patch {@code p}
 * is {@code g = patchStart[p] + k}. {@code next[g]} is the next copy of the same handle, in a ring
 * ({@code next[g] == g} for a point that coincides with no other). Memory: one {@code int} a point,
 * and while building about six more (union–find parents, the cell table and its chains).
 *
 * <p>Immutable and thread-safe. An index built for an older scene of the same model is still
 * safe to use: {@link #copies} checks each copy against the scene it is asked about.
 */
public final class WeldIndex {

    /** Points closer than this times the scene's size are one handle. */
    public static final double RELATIVE_TOLERANCE = 1e-9;
    /** Side of a hash cell, in tolerances: a point needs a neighbour cell only within a tolerance of a face. */
    static final int CELL_PER_TOLERANCE = 16;

    /** No point coincides with another (a scene without patches). */
    public static final WeldIndex NONE = new WeldIndex(new int[] {0}, new int[0], 0, 0);

    private final int[] patchStart;
    private final int[] next;
    private final double tolerance;
    private final int weldedPoints;

    private WeldIndex(int[] patchStart, int[] next, double tolerance, int weldedPoints) {
        this.patchStart = patchStart;
        this.next = next;
        this.tolerance = tolerance;
        this.weldedPoints = weldedPoints;
    }

    /** Patches between two questions whether a build was cancelled. */
    static final int CANCEL_STEP = 1024;

    /** The coincidence tolerance of {@code scene}: {@link #RELATIVE_TOLERANCE} of its size. */
    public static double tolerance(Scene scene) {
        double size = scene.patchCount() == 0 ? 0 : scene.controlBounds().diagonal();
        return RELATIVE_TOLERANCE * size;
    }

    /** Finds the coincident points of {@code scene} (off the UI thread: it reads every point). */
    public static WeldIndex build(Scene scene) {
        return build(scene, () -> false);
    }

    /**
     * As {@link #build(Scene)}, asking {@code cancelled} every {@value #CANCEL_STEP} patches and
     * stopping with a {@link java.util.concurrent.CancellationException} once it says so.
     */
    public static WeldIndex build(Scene scene, java.util.function.BooleanSupplier cancelled) {
        int patches = scene.patchCount();
        int[] start = new int[patches + 1];
        for (int p = 0; p < patches; p++) {
            start[p + 1] = start[p] + scene.patches().get(p).pointCount();
        }
        int n = start[patches];
        double tol = tolerance(scene);
        int[] parent = new int[n];
        Arrays.setAll(parent, g -> g);
        CellTable cells = new CellTable(n, tol > 0 ? CELL_PER_TOLERANCE * tol : 1);
        double[] q = new double[3];
        for (int p = 0, g = 0; p < patches; p++) {
            if (p % CANCEL_STEP == 0) {
                ContinuityAnalysis.stopIf(cancelled);
            }
            BezierPatch patch = scene.patches().get(p);
            int n1 = patch.degreeU() + 1;
            for (int k = 0; k < patch.pointCount(); k++, g++) {
                double x = patch.get(k % n1, k / n1, 0), y = patch.get(k % n1, k / n1, 1), z = patch.get(k % n1, k / n1, 2);
                boolean duplicate = false;
                for (int c = cells.firstNear(x, y, z, tol); c != CellTable.END; c = cells.nextNear()) {
                    for (int h = cells.head(c); h >= 0; h = cells.chain(h)) {
                        position(scene, start, h, q);
                        double dx = q[0] - x, dy = q[1] - y, dz = q[2] - z;
                        double d2 = dx * dx + dy * dy + dz * dz;
                        if (d2 <= tol * tol) {
                            union(parent, g, h);
                            duplicate |= d2 == 0;
                        }
                    }
                }
                if (!duplicate) {
                    cells.add(x, y, z, g); // an exact duplicate need not be compared again
                }
            }
        }
        return rings(start, parent, tol);
    }

    /** Turns the union–find forest into rings of copies. */
    private static WeldIndex rings(int[] start, int[] parent, double tol) {
        int n = parent.length;
        int[] next = new int[n];
        Arrays.setAll(next, g -> g);
        int welded = 0;
        for (int g = 0; g < n; g++) {
            int r = find(parent, g);
            if (r != g) {
                if (next[r] == r) {
                    welded++; // the root's first companion: the root is welded too
                }
                next[g] = next[r];
                next[r] = g;
                welded++;
            }
        }
        return new WeldIndex(start, next, tol, welded);
    }

    private static int find(int[] parent, int g) {
        int r = g;
        while (parent[r] != r) {
            r = parent[r];
        }
        while (parent[g] != r) {
            int up = parent[g];
            parent[g] = r;
            g = up;
        }
        return r;
    }

    private static void union(int[] parent, int a, int b) {
        int ra = find(parent, a), rb = find(parent, b);
        if (ra != rb) {
            parent[Math.max(ra, rb)] = Math.min(ra, rb); // the lowest index is the root
        }
    }

    private static void position(Scene scene, int[] start, int g, double[] out) {
        int p = patchOf(start, g);
        BezierPatch patch = scene.patches().get(p);
        int k = g - start[p], n1 = patch.degreeU() + 1;
        for (int c = 0; c < 3; c++) {
            out[c] = patch.get(k % n1, k / n1, c);
        }
    }

    private static int patchOf(int[] start, int g) {
        int lo = 0, hi = start.length - 2;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (start[mid] <= g) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    /** Points that share their handle with at least one other point. */
    public int weldedPointCount() { return weldedPoints; }

    /** The coincidence tolerance this index was built with, in scene units. */
    public double tolerance() { return tolerance; }

    /** Number of points indexed. */
    public int pointCount() { return next.length; }

    /** The global number of {@code ref} (see the class comment), or -1 when this index has no such point. */
    int global(PointRef ref, Scene scene) {
        int p = ref.patch();
        if (p < 0 || p >= patchStart.length - 1 || p >= scene.patchCount() || ref.i() < 0 || ref.j() < 0) {
            return -1;
        }
        BezierPatch patch = scene.patches().get(p);
        boolean same = patchStart[p + 1] - patchStart[p] == patch.pointCount();
        return same && ref.i() <= patch.degreeU() && ref.j() <= patch.degreeV()
                ? patchStart[p] + ref.j() * (patch.degreeU() + 1) + ref.i() : -1;
    }

    /** The point numbered {@code g} in {@code scene}, or null when the scene has no such point (an index of another model). */
    PointRef ref(int g, Scene scene) {
        if (g < 0 || g >= next.length) {
            return null;
        }
        int p = patchOf(patchStart, g);
        if (!fits(g, scene)) {
            return null;
        }
        int n1 = scene.patches().get(p).degreeU() + 1;
        int k = g - patchStart[p];
        return new PointRef(p, k % n1, k / n1);
    }

    /**
     * Every copy of the handle {@code ref} belongs to in {@code scene}, {@code ref} first: the
     * points this index found coincident with it that still are (within the tolerance) in
     * {@code scene}. Costs the size of the handle.
     */
    public List<PointRef> copies(PointRef ref, Scene scene) {
        List<PointRef> out = new ArrayList<>();
        out.add(ref);
        int g = global(ref, scene);
        if (g < 0) {
            return out;
        }
        double[] at = new double[3], q = new double[3];
        position(scene, patchStart, g, at);
        for (int h = next[g]; h != g; h = next[h]) {
            if (fits(h, scene)) {
                position(scene, patchStart, h, q);
                double dx = q[0] - at[0], dy = q[1] - at[1], dz = q[2] - at[2];
                if (dx * dx + dy * dy + dz * dz <= sq(tolerance)) {
                    out.add(ref(h, scene));
                }
            }
        }
        return out;
    }

    /** True when point {@code g}'s patch exists in {@code scene} with the point count it had here. */
    private boolean fits(int g, Scene scene) {
        int p = patchOf(patchStart, g);
        return p < scene.patchCount() && patchStart[p + 1] - patchStart[p] == scene.patches().get(p).pointCount();
    }

    private static double sq(double v) { return v * v; }

    /** The node of point {@code g}: the lowest number among its copies (g itself when it has none). */
    int node(int g) {
        int min = g;
        for (int h = next[g]; h != g; h = next[h]) {
            min = Math.min(min, h);
        }
        return min;
    }

    /** The next copy in {@code g}'s ring (g itself when it has none). */
    int nextCopy(int g) { return next[g]; }

    /** Global number of patch {@code p}'s first point. */
    int patchStart(int p) { return patchStart[p]; }
}
