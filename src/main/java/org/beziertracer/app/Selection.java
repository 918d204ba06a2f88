package org.beziertracer.app;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The selected control points: an immutable, ordered list of <i>handles</i>, each the copies of
 * one point that coincide ({@link WeldIndex}) — or a single copy picked with Alt. The first copy of
 * the first handle is the <i>primary</i> point (the one a drag grabbed). Moving the selection
 * moves every selected copy by the same offset ({@link SelectionMove}). At most
 * {@value #MAX_POINTS} points are selected (a rubber band over a huge model stops there).
 */
public final class Selection {

    /** Most points a selection holds. */
    public static final int MAX_POINTS = 100_000;

    public static final Selection EMPTY = new Selection(List.of(), new LinkedHashSet<>());

    private final List<List<PointRef>> handles;
    private final LinkedHashSet<PointRef> points;

    private Selection(List<List<PointRef>> handles, LinkedHashSet<PointRef> points) {
        this.handles = handles;
        this.points = points;
    }

    /** Each point a handle of its own. */
    public static Selection of(PointRef... refs) {
        return of(List.of(refs));
    }

    /** Each point a handle of its own. */
    public static Selection of(Collection<PointRef> refs) {
        List<List<PointRef>> hs = new ArrayList<>();
        for (PointRef r : refs) {
            hs.add(List.of(r));
        }
        return ofHandles(hs);
    }

    /** The given handles (each the copies of one point, its picked copy first), in order. */
    public static Selection ofHandles(List<List<PointRef>> handles) {
        return EMPTY.withAll(handles);
    }

    public boolean isEmpty() { return points.isEmpty(); }

    /** Selected points, every copy counted. */
    public int size() { return points.size(); }

    /** Selected handles (coincident copies count once). */
    public int handleCount() { return handles.size(); }

    public boolean contains(PointRef p) { return points.contains(p); }

    /** The first selected point, or null when empty. */
    public PointRef primary() { return handles.isEmpty() ? null : handles.get(0).get(0); }

    /** Every selected point, every copy, in selection order (unmodifiable). */
    public List<PointRef> points() { return List.copyOf(points); }

    /** The handles in selection order, each its copies (unmodifiable). */
    public List<List<PointRef>> handles() { return handles; }

    /** This selection plus the handle {@code copies} (Shift-click); unchanged when it is already selected. */
    public Selection with(List<PointRef> copies) {
        return withAll(List.of(copies));
    }

    /** This selection plus {@code more} handles, up to {@link #MAX_POINTS} points. */
    public Selection withAll(List<List<PointRef>> more) {
        List<List<PointRef>> hs = new ArrayList<>(handles);
        LinkedHashSet<PointRef> ps = new LinkedHashSet<>(points);
        for (List<PointRef> h : more) {
            List<PointRef> fresh = new ArrayList<>();
            for (PointRef r : h) {
                if (!ps.contains(r)) {
                    fresh.add(r);
                }
            }
            if (fresh.isEmpty() || ps.size() + fresh.size() > MAX_POINTS) {
                continue;
            }
            ps.addAll(fresh);
            hs.add(List.copyOf(fresh));
        }
        return hs.isEmpty() ? EMPTY : new Selection(List.copyOf(hs), ps);
    }

    /**
     * This selection with the handle {@code copies} removed when its first copy is selected, else
     * added (Ctrl-click).
     */
    public Selection toggled(List<PointRef> copies) {
        return contains(copies.get(0)) ? without(copies) : with(copies);
    }

    /** This selection without the points {@code refs} (handles left empty go). */
    public Selection without(Collection<PointRef> refs) {
        java.util.Set<PointRef> drop = new java.util.HashSet<>(refs);
        List<List<PointRef>> hs = new ArrayList<>();
        LinkedHashSet<PointRef> ps = new LinkedHashSet<>();
        for (List<PointRef> h : handles) {
            List<PointRef> kept = h.stream().filter(r -> !drop.contains(r)).toList();
            if (!kept.isEmpty()) {
                hs.add(kept);
                ps.addAll(kept);
            }
        }
        return hs.isEmpty() ? EMPTY : new Selection(List.copyOf(hs), ps);
    }

    /** The handles of {@code band} added (Shift) or toggled (Ctrl) handle by handle. */
    public Selection combined(List<List<PointRef>> band, boolean toggle) {
        if (!toggle) {
            return withAll(band);
        }
        Selection s = this;
        for (List<PointRef> h : band) {
            s = s.toggled(h);
        }
        return s;
    }

    /**
     * Where the selected points of {@code scene} are drawn by {@code projector}: the first
     * {@code budget} points, in selection order; points that {@code scene} does not have, or that
     * lie behind the eye, are left out. Costs one projection per point drawn.
     */
    public List<Handle> drawn(Scene scene, ScreenProjector projector, int budget) {
        List<Handle> out = new ArrayList<>();
        double[] xyz = new double[3];
        for (PointRef r : points) {
            if (out.size() >= budget) {
                break;
            }
            if (!r.in(scene)) {
                continue;
            }
            BezierPatch p = scene.patches().get(r.patch());
            if (projector.project(p.get(r.i(), r.j(), 0), p.get(r.i(), r.j(), 1), p.get(r.i(), r.j(), 2), xyz)) {
                out.add(new Handle(r, xyz[0], xyz[1], xyz[2]));
            }
        }
        return out;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Selection s && s.handles.equals(handles);
    }

    @Override
    public int hashCode() { return handles.hashCode(); }

    @Override
    public String toString() { return "Selection" + handles; }
}
