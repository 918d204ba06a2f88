package org.beziertracer.app;

import org.beziertracer.model.Scene;

/**
 * Moving the selection, as a pure function from scene to scene (run off the UI thread): every
 * selected copy moves by the same offset and, with "Keep tangent continuity", the points across
 * the borders follow ({@link SmoothMove}); all of it lands in <b>one</b> new scene
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
        NetChange change = new NetChange(base);
        for (PointRef r : selection.points()) {
            if (r.in(base)) {
                change.moveBy(r, d[0], d[1], d[2]);
            }
        }
        if (smooth) {
            SmoothMove.follow(change, topology, topology.wholeNodes(selection, base), d);
        }
        return change.apply();
    }
}
