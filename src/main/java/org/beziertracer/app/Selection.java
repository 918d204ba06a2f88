package org.beziertracer.app;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The selected control points: an immutable, ordered set of {@link PointRef}s (the first is the
 * <i>primary</i> point, the one a drag grabbed). A drag moves every selected point by the same
 * world-space offset ({@link NetEdits#moveBy}).
 */
public final class Selection {

    public static final Selection EMPTY = new Selection(new LinkedHashSet<>());

    private final LinkedHashSet<PointRef> points;

    private Selection(LinkedHashSet<PointRef> points) {
        this.points = points;
    }

    public static Selection of(PointRef... refs) {
        return of(List.of(refs));
    }

    public static Selection of(Collection<PointRef> refs) {
        return refs.isEmpty() ? EMPTY : new Selection(new LinkedHashSet<>(refs));
    }

    public boolean isEmpty() { return points.isEmpty(); }

    public int size() { return points.size(); }

    public boolean contains(PointRef p) { return points.contains(p); }

    /** The first selected point, or null when empty. */
    public PointRef primary() { return points.isEmpty() ? null : points.iterator().next(); }

    /** The points in selection order (unmodifiable). */
    public List<PointRef> points() { return List.copyOf(points); }

    /** This selection plus {@code p} (Shift-click). */
    public Selection with(PointRef p) {
        LinkedHashSet<PointRef> copy = new LinkedHashSet<>(points);
        copy.add(p);
        return new Selection(copy);
    }

    /** This selection with {@code p} added or removed (Ctrl-click). */
    public Selection toggled(PointRef p) {
        LinkedHashSet<PointRef> copy = new LinkedHashSet<>(points);
        if (!copy.remove(p)) {
            copy.add(p);
        }
        return copy.isEmpty() ? EMPTY : new Selection(copy);
    }

    /** Points grouped by patch: for each patch index in first-seen order, its selected points. */
    public Collection<List<PointRef>> byPatch() {
        Map<Integer, List<PointRef>> groups = new LinkedHashMap<>();
        for (PointRef p : points) {
            groups.computeIfAbsent(p.patch(), k -> new ArrayList<>()).add(p);
        }
        return groups.values();
    }

    /**
     * The selected points of {@code scene} as drawn by {@code projector}, in selection order;
     * points that {@code scene} does not have, or that lie behind the eye, are left out. Costs one
     * projection per selected point.
     */
    public List<Handle> handles(Scene scene, ScreenProjector projector) {
        List<Handle> out = new ArrayList<>();
        double[] xyz = new double[3];
        for (PointRef r : points) {
            if (r.patch() >= scene.patchCount()) {
                continue;
            }
            BezierPatch p = scene.patches().get(r.patch());
            if (r.i() <= p.degreeU() && r.j() <= p.degreeV()
                    && projector.project(p.get(r.i(), r.j(), 0), p.get(r.i(), r.j(), 1), p.get(r.i(), r.j(), 2), xyz)) {
                out.add(new Handle(r, xyz[0], xyz[1], xyz[2]));
            }
        }
        return out;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Selection s && List.copyOf(s.points).equals(List.copyOf(points));
    }

    @Override
    public int hashCode() { return points.hashCode(); }

    @Override
    public String toString() { return "Selection" + points; }
}
