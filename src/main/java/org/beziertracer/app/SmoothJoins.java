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
 * <p>Points are the welded <i>nodes</i> of the index, each named by the lowest global number of its
 * copies. Immutable and thread-safe.
 */
final class SmoothJoins {

    /** Joins whose rows bend by less than this angle (its sine) count as tangent-continuous. */
    static final double COLLINEAR = 1e-6;

    /** No joins (a single patch, or patches that share no border). */
    static final SmoothJoins NONE = new SmoothJoins(new int[0], new int[1], new int[0]);

    /** {@code joins[3t..3t+2]} = nodes A, B, C of join {@code t}. */
    private final int[] joins;
    /** Joins of node {@code g}: {@code byNode[first[g]..first[g+1]-1]} (CSR over global numbers). */
    private final int[] first;
    private final int[] byNode;

    private SmoothJoins(int[] joins, int[] first, int[] byNode) {
        this.joins = joins;
        this.first = first;
        this.byNode = byNode;
    }

    /** One edge of one patch: the border points and, beside each, its neighbour one row inward. */
    private record Edge(int[] border, int[] inner) {}

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
        List<int[]> found = new ArrayList<>();
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
            int len = alongV ? m + 1 : n + 1;
            int[] border = new int[len], inner = new int[len];
            for (int k = 0; k < len; k++) {
                int i = alongV ? (side == 0 ? 0 : n) : k, j = alongV ? k : (side == 2 ? 0 : m);
                int ii = alongV ? (side == 0 ? 1 : n - 1) : k, jj = alongV ? k : (side == 2 ? 1 : m - 1);
                border[k] = node[start + j * (n + 1) + i];
                inner[k] = node[start + jj * (n + 1) + ii];
            }
            if (distinct(border)) {
                out.add(new Edge(border, inner));
            }
        }
        return out;
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
    private static void pair(Edge e, Edge f, List<int[]> out) {
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
        for (int k = 0; k < len; k++) {
            int a = e.inner()[k], b = e.border()[k], c = f.inner()[forward ? k : len - 1 - k];
            if (a != b && c != b && a != c) {
                out.add(new int[] {a, b, c});
            }
        }
    }

    private static SmoothJoins index(List<int[]> found, int n) {
        int[] joins = new int[3 * found.size()];
        int[] first = new int[n + 1];
        for (int t = 0; t < found.size(); t++) {
            System.arraycopy(found.get(t), 0, joins, 3 * t, 3);
            for (int r = 0; r < 3; r++) {
                first[found.get(t)[r] + 1]++;
            }
        }
        for (int g = 0; g < n; g++) {
            first[g + 1] += first[g];
        }
        int[] fill = Arrays.copyOf(first, n);
        int[] byNode = new int[joins.length];
        for (int t = 0; t < found.size(); t++) {
            for (int r = 0; r < 3; r++) {
                byNode[fill[joins[3 * t + r]]++] = t;
            }
        }
        return new SmoothJoins(joins, first, byNode);
    }

    /** Number of joins. */
    int count() { return joins.length / 3; }

    /** Node {@code role} (0 = A, 1 = B, 2 = C) of join {@code t}. */
    int node(int t, int role) { return joins[3 * t + role]; }

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
