package org.beziertracer.app;

import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

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
 * Runs off the UI thread, in time proportional to the points it moves. Stateless.
 */
final class SmoothMove {
    private SmoothMove() {}

    /**
     * Adds to {@code change} the moves that keep the joins of {@code topology} that hold in the
     * change's base scene, given that the nodes {@code moved} (global numbers of the index) have
     * just moved by {@code d}.
     */
    static void follow(NetChange change, Topology topology, List<Integer> moved, double[] d) {
        SmoothJoins joins = topology.joins();
        WeldIndex welds = topology.welds();
        if (joins == null || joins.count() == 0 || moved.isEmpty()) {
            return;
        }
        Spread s = new Spread(change.base(), welds, joins);
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
        final double tol;
        final Map<Integer, double[]> delta = new HashMap<>();
        final Map<Integer, double[]> positions = new HashMap<>();
        final ArrayDeque<Integer> carried = new ArrayDeque<>(), turned = new ArrayDeque<>();

        Spread(Scene base, WeldIndex welds, SmoothJoins joins) {
            this.base = base;
            this.welds = welds;
            this.joins = joins;
            this.tol = welds.tolerance();
        }

        void assign(int node, double[] d, boolean carry) {
            delta.put(node, d);
            (carry ? carried : turned).add(node);
        }

        void run() {
            while (!carried.isEmpty() || !turned.isEmpty()) {
                int node = carried.isEmpty() ? turned.poll() : carried.poll();
                for (int t : joins.joinsOf(node)) {
                    follow(t, node);
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

        final java.util.Set<Integer> userMoved = new java.util.HashSet<>();

        boolean isUserMoved(int node) { return userMoved.contains(node); }
    }
}
