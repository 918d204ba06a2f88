package org.beziertracer.app;

import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.beziertracer.model.Scene;

/**
 * "Keep tangent continuity": after the user moved some points, the points across the borders
 * follow so that every join ({@link SmoothJoins}) that was tangent-continuous stays so, each
 * with the ratio {@code |C − B| / |A − B|} it had:
 * <ul>
 *   <li>a moved border point {@code B} carries its inner neighbours {@code A} and {@code C} with
 *       it (as a smooth node of a curve carries its handles);</li>
 *   <li>a moved inner neighbour {@code A} turns the row about {@code B}: the mirrored neighbour
 *       goes to {@code C' = B' − λ (A' − B')}, where {@code λ} is the old ratio.</li>
 * </ul>
 * A point that moved that way is itself moved for the joins it takes part in, so a change spreads
 * until every join touched is satisfied; carrying is done before turning, and each point moves at
 * most once. Every copy of a moved node moves. Where joins around a corner cannot all be kept
 * (patches that were not tangent-continuous in a compatible way) the first one reached wins.
 *
 * <p>"Keep curvature continuity" (the {@code curvature} flag; it implies tangent continuity) also
 * keeps every join that is C2 in the base scene ({@link CurvatureJoins}) so, on its five-point row
 * {@code (A2, A, B, C, C2)}, with the same ratio:
 * <ul>
 *   <li>a border point {@code B} that carries {@code A} and {@code C} carries {@code A2} and
 *       {@code C2} too (the whole row translates);</li>
 *   <li>otherwise the second-row point on the side that gives way is solved from the other four
 *       ({@link CurvatureJoins#solveOuter}). As for G1, the side the change came from holds: when
 *       only one second-row point is still free it gives way; when both are, the side whose point
 *       moved first (the user's side, before the side that was turned) holds and the other's second
 *       row follows.</li>
 * </ul>
 * Second rows are solved after every carry and turn already due, so that a point reached along two
 * paths (the corner of four patches) is placed by the tangent rules first, and a join that then
 * already holds is left alone. Solved points spread further like turned ones (at degree 3 a second
 * row is the first row of the opposite border). Each point still moves at most once; a join whose
 * second-row points were both pinned by other joins (or by the user) is left as it comes out.
 * Runs off the UI thread, in time proportional to the points it moves. Stateless.
 */
final class SmoothMove {
    private SmoothMove() {}

    /** A kept join whose relative residual is at most this after the moves needs no second-row move (rounding). */
    static final double SNUG = 1e-12;

    /**
     * Adds to {@code change} the moves that keep the joins of {@code topology} that hold in the
     * change's base scene, given that the nodes {@code moved} (global numbers of the index) have
     * just moved by {@code d}.
     */
    static void follow(NetChange change, Topology topology, List<Integer> moved, double[] d) {
        follow(change, topology, moved, d, false);
    }

    /**
     * As {@link #follow(NetChange, Topology, List, double[])}, and with {@code curvature} the joins
     * that are curvature-continuous in the base scene stay so too.
     */
    static void follow(NetChange change, Topology topology, List<Integer> moved, double[] d, boolean curvature) {
        SmoothJoins joins = topology.joins();
        WeldIndex welds = topology.welds();
        if (joins == null || joins.count() == 0 || moved.isEmpty()) {
            return;
        }
        Spread s = new Spread(change.base(), welds, joins, curvature);
        for (int node : moved) {
            s.userMoved.add(node);
            s.assign(node, d, true);
        }
        s.run();
        s.applyTo(change);
    }

    /** The propagation of one move. */
    private static final class Spread {
        final Scene base;
        final WeldIndex welds;
        final SmoothJoins joins;
        final boolean curvature;
        final double tol, size;
        final Map<Integer, double[]> delta = new HashMap<>();
        /** When each moved node moved (0, 1, 2, … in order), for deciding which side leads. */
        final Map<Integer, Integer> order = new HashMap<>();
        final Map<Integer, double[]> positions = new HashMap<>();
        final ArrayDeque<Integer> carried = new ArrayDeque<>(), turned = new ArrayDeque<>();
        /** Joins whose second rows are to be checked once no carry or turn is due (each queued once at a time). */
        final ArrayDeque<Integer> curving = new ArrayDeque<>();
        final Set<Integer> curvingQueued = new HashSet<>();
        /** Per join: 1 when curvature-continuous in the base scene, −1 when not, absent until asked. */
        final Map<Integer, Integer> curvedInBase = new HashMap<>();

        Spread(Scene base, WeldIndex welds, SmoothJoins joins, boolean curvature) {
            this.base = base;
            this.welds = welds;
            this.joins = joins;
            this.curvature = curvature;
            this.tol = welds.tolerance();
            this.size = curvature ? CurvatureJoins.size(base) : 1;
        }

        void assign(int node, double[] d, boolean carry) {
            delta.put(node, d);
            order.put(node, order.size());
            (carry ? carried : turned).add(node);
        }

        void run() {
            while (true) {
                if (!carried.isEmpty() || !turned.isEmpty()) {
                    int node = carried.isEmpty() ? turned.poll() : carried.poll();
                    for (int t : joins.joinsOf(node)) {
                        follow(t, node);
                        if (curvature && joins.hasOuter(t) && curvingQueued.add(t)) {
                            curving.add(t);
                        }
                    }
                } else if (!curving.isEmpty()) {
                    int t = curving.poll();
                    curvingQueued.remove(t);
                    curve(t);
                } else {
                    return;
                }
            }
        }

        /** Keeps join {@code t} after its node {@code moved} moved. */
        private void follow(int t, int moved) {
            int a = joins.node(t, 0), b = joins.node(t, 1), c = joins.node(t, 2);
            double[] pa = at(a), pb = at(b), pc = at(c);
            if (pa == null || pb == null || pc == null || !SmoothJoins.holds(pa, pb, pc, tol)) {
                return; // not tangent-continuous before the move (or no longer in the scene): nothing to keep
            }
            boolean ma = delta.containsKey(a), mb = delta.containsKey(b), mc = delta.containsKey(c);
            if (moved == b && !ma && !mc) {
                assign(a, delta.get(b), true);
                assign(c, delta.get(b), true);
                if (curvature && curvedInBase(t)) {
                    for (int side = 0; side < 2; side++) {
                        if (!delta.containsKey(joins.outer(t, side))) {
                            assign(joins.outer(t, side), delta.get(b), true);
                        }
                    }
                }
            } else if (ma != mc) {
                // One neighbour moved (maybe with B): turn the other about B, keeping the ratio
                int x = ma ? a : c, y = ma ? c : a;
                double[] px = ma ? pa : pc, py = ma ? pc : pa;
                double lambda = dist(py, pb) / dist(px, pb);
                double[] dx = delta.get(x), db = mb ? delta.get(b) : new double[3];
                double[] d = new double[3];
                for (int k = 0; k < 3; k++) {
                    double bNew = pb[k] + db[k];
                    d[k] = bNew - lambda * (px[k] + dx[k] - bNew) - py[k];
                }
                assign(y, d, false);
            }
        }

        /** Keeps the second rows of join {@code t} (which has them) C2, when it was so in the base scene. */
        private void curve(int t) {
            if (!curvedInBase(t)) {
                return;
            }
            int a2 = joins.outer(t, 0), a = joins.node(t, 0), b = joins.node(t, 1), c = joins.node(t, 2), c2 = joins.outer(t, 1);
            int n = joins.degree(t, 0), m = joins.degree(t, 1);
            double[] qa2 = now(a2), qa = now(a), qb = now(b), qc = now(c), qc2 = now(c2);
            if (CurvatureJoins.residual(qa2, qa, qb, qc, qc2, n, m) <= SNUG * size) {
                return; // already C2 (moved whole, or placed along another path)
            }
            boolean ma2 = delta.containsKey(a2), mc2 = delta.containsKey(c2);
            if (ma2 && mc2) {
                return; // both second rows pinned: cannot keep
            }
            boolean cGivesWay = ma2 != mc2 ? ma2 : lead(a2, a) <= lead(c, c2);
            double lambda = CurvatureJoins.ratio(at(a), at(b), at(c));
            double[] solved = new double[3];
            int give;
            if (cGivesWay) {
                give = c2;
                CurvatureJoins.solveOuter(qa2, qa, qb, qc, lambda, n, m, solved);
            } else {
                give = a2;
                CurvatureJoins.solveOuter(qc2, qc, qb, qa, 1 / lambda, m, n, solved);
            }
            double[] was = at(give), d = new double[3];
            for (int k = 0; k < 3; k++) {
                d[k] = solved[k] - was[k];
            }
            assign(give, d, false);
        }

        /** Whether join {@code t} is curvature-continuous in the base scene (decided once per join). */
        private boolean curvedInBase(int t) {
            return curvedInBase.computeIfAbsent(t, k -> {
                int[] nodes = {joins.outer(k, 0), joins.node(k, 0), joins.node(k, 1), joins.node(k, 2), joins.outer(k, 1)};
                double[][] p = new double[5][];
                for (int r = 0; r < 5; r++) {
                    p[r] = nodes[r] < 0 ? null : at(nodes[r]);
                    if (p[r] == null) {
                        return -1;
                    }
                }
                boolean held = SmoothJoins.holds(p[1], p[2], p[3], tol) && CurvatureJoins.residual(p[0], p[1], p[2], p[3], p[4],
                        joins.degree(k, 0), joins.degree(k, 1)) <= CurvatureJoins.HOLDS * size;
                return held ? 1 : -1;
            }) > 0;
        }

        /** The earlier move of the two nodes of one side (Integer.MAX_VALUE when neither moved). */
        private int lead(int g, int h) {
            return Math.min(order.getOrDefault(g, Integer.MAX_VALUE), order.getOrDefault(h, Integer.MAX_VALUE));
        }

        /** Where node {@code g} is with the moves so far. */
        private double[] now(int g) {
            double[] p = at(g), d = delta.get(g);
            return d == null ? p : new double[] {p[0] + d[0], p[1] + d[1], p[2] + d[2]};
        }

        /** Where node {@code g} is in the base scene, or null when the scene has no such point. */
        private double[] at(int g) {
            return positions.computeIfAbsent(g, k -> {
                PointRef r = welds.ref(k, base);
                if (r == null) {
                    return null;
                }
                double[] p = new double[3];
                for (int c = 0; c < 3; c++) {
                    p[c] = base.patches().get(r.patch()).get(r.i(), r.j(), c);
                }
                return p;
            });
        }

        private static double dist(double[] p, double[] q) {
            double x = p[0] - q[0], y = p[1] - q[1], z = p[2] - q[2];
            return Math.sqrt(x * x + y * y + z * z);
        }

        /** Moves every copy of every node that followed (the user's own points are already in the change). */
        void applyTo(NetChange change) {
            for (Map.Entry<Integer, double[]> e : delta.entrySet()) {
                if (!isUserMoved(e.getKey())) {
                    double[] d = e.getValue();
                    for (PointRef r : welds.copies(welds.ref(e.getKey(), base), base)) {
                        change.moveBy(r, d[0], d[1], d[2]);
                    }
                }
            }
        }

        final Set<Integer> userMoved = new HashSet<>();

        boolean isUserMoved(int node) { return userMoved.contains(node); }
    }
}
