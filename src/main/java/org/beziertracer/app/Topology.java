package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.Scene;

/**
 * How a model's control points hang together: which coincide ({@link WeldIndex}) and, when
 * "Keep tangent continuity" or "Keep curvature continuity" asks for them, the cross-border rows
 * ({@link SmoothJoins}). Built off
 * the UI thread for one scene; still usable, with care, for later scenes of the same model (its
 * parts check their answers against the scene they are asked about). Immutable.
 *
 * @param scene  the scene it was built for
 * @param welds  coincident points
 * @param joins  cross-border rows, or null when not asked for
 */
record Topology(Scene scene, WeldIndex welds, SmoothJoins joins) {

    /** Nothing known yet: every point is its own handle. */
    static final Topology NONE = new Topology(null, WeldIndex.NONE, null);

    /** Finds the welds (and the joins when {@code withJoins}) of {@code scene}; O(points). */
    static Topology of(Scene scene, boolean withJoins) {
        WeldIndex welds = WeldIndex.build(scene);
        return new Topology(scene, welds, withJoins ? SmoothJoins.find(scene, welds) : null);
    }

    /** The handle of {@code ref} in {@code scene}: every copy, {@code ref} first. */
    List<PointRef> handle(PointRef ref, Scene scene) {
        return welds.copies(ref, scene);
    }

    /**
     * The nodes (global numbers) of the handles that {@code selection} moves whole — all their
     * copies selected — which are what tangent continuity follows (a copy dragged alone with Alt
     * is not).
     */
    List<Integer> wholeNodes(Selection selection, Scene scene) {
        List<Integer> out = new ArrayList<>();
        java.util.Set<Integer> seen = new java.util.HashSet<>();
        for (PointRef r : selection.points()) {
            int g = welds.global(r, scene);
            if (g < 0) {
                continue;
            }
            List<PointRef> copies = welds.copies(r, scene);
            int node = g;
            boolean all = true;
            for (PointRef c : copies) {
                all &= selection.contains(c);
                node = Math.min(node, welds.global(c, scene));
            }
            int lowest = welds.node(g);
            if (all && lowest == node && seen.add(node)) {
                out.add(node);
            }
        }
        return out;
    }
}
