package org.beziertracer.app;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The cross-border control rows of a model: where two patches share a border (the points of an
 * edge of one are welded, in order or reversed, to the points of an edge of the other), each
 * border point {@code B} with its inner neighbour {@code A} in one patch and {@code C} in the other
 * is a <i>join</i> {@code (A, B, C)}. Where the three are collinear with {@code B} between, the
 * surface is tangent-continuous (G1) across the border there, and "Keep tangent continuity"
 * ({@link SmoothMove}) keeps it so. Found off the UI thread in O(points) from a
 * {@link WeldIndex}; whether a join holds is decided from the positions of the scene being edited.
 *
 * <p>Where both patches have degree at least {@link #CURVATURE_DEGREE} across the border, a join also
 * has its <i>second rows</i>: {@code A2} beside {@code A} and {@code C2} beside {@code C}, one more
 * row inward, making the five-point row {@code (A2, A, B, C, C2)} on which "Keep curvature
 * continuity" ({@link CurvatureJoins}) keeps the C2 condition. At degree 2 the second row would be
 * the opposite border of the patch (moving it would drag that border and its welded neighbours),
 * so such borders are counted ({@link #shortBorderCount}) and their joins keep tangent continuity
 * only. At degree 3 a second row is the first row of the opposite border, so keeping both borders
 * of a patch couples them; {@link SmoothMove} spreads the change along such chains.
 *
 * <p>Points are the welded <i>nodes</i> of the index, each named by the lowest global number of its
 * copies. Immutable and thread-safe.
 */
final class SmoothJoins {

    /** Joins whose rows bend by less than this angle (its sine) count as tangent-continuous. */
    static final double COLLINEAR = 1e-6;

    /** The least degree across a border, on both sides, for which joins get their second rows. */
    static final int CURVATURE_DEGREE = 3;

    /** No joins (a single patch, or patches that share no border). */
    static final SmoothJoins NONE = new SmoothJoins(new int[0], new int[0], new int[1], new int[0], 0);

    /**
     * {@code joins[5t..5t+4]} = nodes A2, A, B, C, C2 of join {@code t}; A2 and C2 are −1 where the
     * join has no second rows.
     */
    private final int[] joins;
    /** {@code degrees[2t]}, {@code degrees[2t+1]}: the degrees across the border on A's and C's side. */
    private final int[] degrees;
    /** Joins of node {@code g}: {@code byNode[first[g]..first[g+1]-1]} (CSR over global numbers). */
    private final int[] first;
    private final int[] byNode;
    private final int shortBorders;

    private SmoothJoins(int[] joins, int[] degrees, int[] first, int[] byNode, int shortBorders) {
        this.joins = joins;
        this.degrees = degrees;
        this.first = first;
        this.byNode = byNode;
        this.shortBorders = shortBorders;
    }

    /**
     * One edge of one patch: the border points, beside each its neighbour one row inward and two
     * rows inward ({@code inner2}, null below {@link #CURVATURE_DEGREE}), and the patch's degree
     * across the edge.
     */
    private record Edge(int[] border, int[] inner, int[] inner2, int degree) {}

    /** The joins found so far and the borders whose rows were too short for second rows. */
    private static final class Found {
        final List<int[]> rows = new ArrayList<>();
        int shortBorders;
    }

    /** Finds the joins of {@code scene}, whose coincident points {@code welds} found. */
    static SmoothJoins find(Scene scene, WeldIndex welds) {
        int n = welds.pointCount();
        int[] node = nodes(welds);
        Map<Long, List<Edge>> byEnds = new HashMap<>();
        for (int p = 0; p < scene.patchCount(); p++) {
            for (Edge e : edges(scene.patches().get(p), welds.patchStart(p), node)) {
                int a = e.border()[0], b = e.border()[e.border().length - 1];
                long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
                byEnds.computeIfAbsent(key, k -> new ArrayList<>()).add(e);
            }
        }
        Found found = new Found();
        for (List<Edge> group : byEnds.values()) {
            for (int x = 0; x < group.size(); x++) {
                for (int y = x + 1; y < group.size(); y++) {
                    pair(group.get(x), group.get(y), found);
                }
            }
        }
        return index(found, n);
    }

    /** Each point's node: the lowest global number among its copies ({@link WeldIndex#node}). */
    private static int[] nodes(WeldIndex welds) {
        int[] node = new int[welds.pointCount()];
        Arrays.fill(node, -1);
        for (int g = 0; g < node.length; g++) {
            if (node[g] < 0) {
                int min = welds.node(g);
                node[g] = min;
                for (int h = welds.nextCopy(g); h != g; h = welds.nextCopy(h)) {
                    node[h] = min;
                }
            }
        }
        return node;
    }

    /** The four edges of a patch as nodes; an edge collapsed to fewer distinct points is left out. */
    private static List<Edge> edges(BezierPatch patch, int start, int[] node) {
        int n = patch.degreeU(), m = patch.degreeV();
        List<Edge> out = new ArrayList<>(4);
        for (int side = 0; side < 4; side++) {
            boolean alongV = side < 2; // u = 0 or u = n: the edge runs along v
            int len = alongV ? m + 1 : n + 1, across = alongV ? n : m;
            int[] border = new int[len], inner = new int[len];
            int[] inner2 = across >= CURVATURE_DEGREE ? new int[len] : null;
            for (int k = 0; k < len; k++) {
                border[k] = node[start + at(side, k, 0, n, m)];
                inner[k] = node[start + at(side, k, 1, n, m)];
                if (inner2 != null) {
                    inner2[k] = node[start + at(side, k, 2, n, m)];
                }
            }
            if (distinct(border)) {
                out.add(new Edge(border, inner, inner2, across));
            }
        }
        return out;
    }

    /**
     * Index in a net of {@code (n+1) × (m+1)} points of point {@code k} along edge {@code side}
     * (0: u = 0, 1: u = n, 2: v = 0, 3: v = m), {@code row} rows inward from it.
     */
    private static int at(int side, int k, int row, int n, int m) {
        boolean alongV = side < 2;
        int i = alongV ? (side == 0 ? row : n - row) : k, j = alongV ? k : (side == 2 ? row : m - row);
        return j * (n + 1) + i;
    }

    private static boolean distinct(int[] seq) {
        for (int k = 1; k < seq.length; k++) {
            if (seq[k] == seq[k - 1]) {
                return false;
            }
        }
        return true;
    }

    /** The joins across two edges, when they are one border (the same nodes, in order or reversed). */
    private static void pair(Edge e, Edge f, Found out) {
        int len = e.border().length;
        if (f.border().length != len) {
            return;
        }
        boolean forward = true, backward = true;
        for (int k = 0; k < len; k++) {
            forward &= e.border()[k] == f.border()[k];
            backward &= e.border()[k] == f.border()[len - 1 - k];
        }
        if (!forward && !backward) {
            return;
        }
        int before = out.rows.size();
        boolean second = e.inner2() != null && f.inner2() != null;
        for (int k = 0; k < len; k++) {
            int kf = forward ? k : len - 1 - k;
            int a = e.inner()[k], b = e.border()[k], c = f.inner()[kf];
            if (a != b && c != b && a != c) {
                int a2 = second ? e.inner2()[k] : -1, c2 = second ? f.inner2()[kf] : -1;
                if (!allDifferent(a2, a, b, c, c2)) {
                    a2 = c2 = -1;
                }
                out.rows.add(new int[] {a2, a, b, c, c2, e.degree(), f.degree()});
            }
        }
        if (!second && out.rows.size() > before) {
            out.shortBorders++;
        }
    }

    private static boolean allDifferent(int... nodes) {
        for (int x = 0; x < nodes.length; x++) {
            for (int y = x + 1; y < nodes.length; y++) {
                if (nodes[x] == nodes[y]) {
                    return false;
                }
            }
        }
        return true;
    }

    private static SmoothJoins index(Found found, int n) {
        List<int[]> rows = found.rows;
        int[] joins = new int[5 * rows.size()], degrees = new int[2 * rows.size()];
        int[] first = new int[n + 1];
        for (int t = 0; t < rows.size(); t++) {
            System.arraycopy(rows.get(t), 0, joins, 5 * t, 5);
            System.arraycopy(rows.get(t), 5, degrees, 2 * t, 2);
            for (int r = 0; r < 5; r++) {
                if (joins[5 * t + r] >= 0) {
                    first[joins[5 * t + r] + 1]++;
                }
            }
        }
        for (int g = 0; g < n; g++) {
            first[g + 1] += first[g];
        }
        int[] fill = Arrays.copyOf(first, n);
        int[] byNode = new int[first[n]];
        for (int t = 0; t < rows.size(); t++) {
            for (int r = 0; r < 5; r++) {
                if (joins[5 * t + r] >= 0) {
                    byNode[fill[joins[5 * t + r]]++] = t;
                }
            }
        }
        return new SmoothJoins(joins, degrees, first, byNode, found.shortBorders);
    }

    /** Number of joins. */
    int count() { return joins.length / 5; }

    /** Node {@code role} (0 = A, 1 = B, 2 = C) of join {@code t}. */
    int node(int t, int role) { return joins[5 * t + 1 + role]; }

    /** Second-row node of join {@code t} on {@code side} (0: A2 beside A, 1: C2 beside C), or −1 when it has none. */
    int outer(int t, int side) { return joins[5 * t + (side == 0 ? 0 : 4)]; }

    /** True when join {@code t} has its second rows (degree at least {@link #CURVATURE_DEGREE} on both sides). */
    boolean hasOuter(int t) { return joins[5 * t] >= 0; }

    /** The degree across the border of the patch on {@code side} of join {@code t} (0: A's, 1: C's). */
    int degree(int t, int side) { return degrees[2 * t + side]; }

    /**
     * Shared borders whose joins have no second rows because a patch has degree below
     * {@link #CURVATURE_DEGREE} across them: where curvature continuity cannot be kept.
     */
    int shortBorderCount() { return shortBorders; }

    /** The joins node {@code g} takes part in (a fresh array). */
    int[] joinsOf(int g) {
        if (g < 0 || g + 1 >= first.length) {
            return new int[0];
        }
        return Arrays.copyOfRange(byNode, first[g], first[g + 1]);
    }

    /**
     * True when {@code a}, {@code b}, {@code c} form a tangent-continuous row: {@code b} lies between
     * the other two on one line (the sine of the bend at most {@link #COLLINEAR}), neither
     * neighbour within {@code tol} of it.
     */
    static boolean holds(double[] a, double[] b, double[] c, double tol) {
        double ax = a[0] - b[0], ay = a[1] - b[1], az = a[2] - b[2];
        double cx = c[0] - b[0], cy = c[1] - b[1], cz = c[2] - b[2];
        double la = Math.sqrt(ax * ax + ay * ay + az * az), lc = Math.sqrt(cx * cx + cy * cy + cz * cz);
        if (!(la > tol && lc > tol) || ax * cx + ay * cy + az * cz >= 0) {
            return false;
        }
        return sine(a, b, c) <= COLLINEAR;
    }

    /** Sine of the angle between {@code a − b} and {@code b − c}: 0 for a straight row. */
    static double sine(double[] a, double[] b, double[] c) {
        double ax = a[0] - b[0], ay = a[1] - b[1], az = a[2] - b[2];
        double cx = c[0] - b[0], cy = c[1] - b[1], cz = c[2] - b[2];
        double x = ay * cz - az * cy, y = az * cx - ax * cz, z = ax * cy - ay * cx;
        double la = Math.sqrt(ax * ax + ay * ay + az * az), lc = Math.sqrt(cx * cx + cy * cy + cz * cz);
        return Math.sqrt(x * x + y * y + z * z) / (la * lc);
    }
}
