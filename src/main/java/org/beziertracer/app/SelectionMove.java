package org.beziertracer.app;

import org.beziertracer.model.Scene;

/**
 * Moving the selection, as a pure function from scene to scene (run off the UI thread): every
 * selected copy moves by the same offset and, with "Keep tangent continuity", the points across
 * the borders follow ({@link SmoothMove}), with "Keep curvature continuity" their second rows too;
 * all of it lands in <b>one</b> new scene
 * ({@link NetChange}). Stateless.
 */
public final class SelectionMove {
    private SelectionMove() {}

    /**
     * {@code base} with the selected points moved by {@code d} (x, y, z in scene units).
     *
     * @param topology the model's welds and joins (maybe of an earlier scene of the same model)
     * @param smooth   keep tangent continuity across the borders where it holds
     */
    public static Scene apply(Scene base, Selection selection, double[] d, Topology topology, boolean smooth) {
        return apply(base, selection, d, topology, smooth, false);
    }

    /**
     * As {@link #apply(Scene, Selection, double[], Topology, boolean)}; with {@code curvature} the
     * cross-border rows that are curvature-continuous (C2, {@link CurvatureJoins}) stay so too, which
     * implies keeping tangent continuity whatever {@code smooth} says.
     */
    public static Scene apply(Scene base, Selection selection, double[] d, Topology topology, boolean smooth,
            boolean curvature) {
        NetChange change = new NetChange(base);
        for (PointRef r : selection.points()) {
            if (r.in(base)) {
                change.moveBy(r, d[0], d[1], d[2]);
            }
        }
        if (smooth || curvature) {
            SmoothMove.follow(change, topology, topology.wholeNodes(selection, base), d, curvature);
        }
        return change.apply();
    }
}
