package org.beziertracer.app;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The control points whose projections fall in a rectangle of the picture (a rubber band, or the
 * whole model for Select All), as handles: coincident copies together ({@link WeldIndex}). Reads
 * every point: runs off the UI thread. At most {@link Selection#MAX_POINTS} points. Stateless.
 */
final class PointsInRectangle {
    private PointsInRectangle() {}

    /**
     * The handles of {@code scene} inside {@code [x0, x1] × [y0, y1]} as {@code projector} draws
     * them (points behind the eye are left out); with {@code projector} null, every point.
     */
    static List<List<PointRef>> find(Scene scene, ScreenProjector projector, double x0, double y0, double x1,
                                     double y1, Topology topology) {
        WeldIndex welds = topology.welds();
        Map<Integer, List<PointRef>> byNode = new LinkedHashMap<>();
        PatchProjection projection = projector == null ? null : new PatchProjection(projector);
        int count = 0;
        for (int p = 0; p < scene.patchCount() && count < Selection.MAX_POINTS; p++) {
            BezierPatch patch = scene.patches().get(p);
            if (projection != null && !projection.project(patch)) {
                continue;
            }
            int n1 = patch.degreeU() + 1;
            for (int k = 0; k < patch.pointCount() && count < Selection.MAX_POINTS; k++) {
                if (projection != null) {
                    double x = projection.xy[2 * k], y = projection.xy[2 * k + 1];
                    if (x < x0 || x > x1 || y < y0 || y > y1) {
                        continue;
                    }
                }
                PointRef r = new PointRef(p, k % n1, k / n1);
                int g = welds.global(r, scene);
                int node = g < 0 ? -1 - count : welds.node(g);
                byNode.computeIfAbsent(node, key -> new ArrayList<>()).add(r);
                count++;
            }
        }
        return new ArrayList<>(byNode.values());
    }
}
