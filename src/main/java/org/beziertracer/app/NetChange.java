package org.beziertracer.app;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Control-point moves gathered into one edit: each touched patch's net is copied once, every move
 * lands in those copies, and {@link #apply} builds <b>one</b> new scene — the patch list is
 * copied once however many points and patches moved (a welded point shared by four patches is
 * four moves, one scene). Not thread-safe (one per edit, off the UI thread).
 */
final class NetChange {

    private final Scene base;
    private final Map<Integer, double[]> nets = new LinkedHashMap<>();

    NetChange(Scene base) {
        this.base = base;
    }

    /** The scene the moves apply to. */
    Scene base() { return base; }

    /** Moves point {@code ref} by {@code (dx, dy, dz)} (moves of one point add up). */
    void moveBy(PointRef ref, double dx, double dy, double dz) {
        double[] net = net(ref.patch());
        int k = index(ref);
        net[k] += dx;
        net[k + 1] += dy;
        net[k + 2] += dz;
    }

    private int index(PointRef ref) {
        return base.patches().get(ref.patch()).index(ref.i(), ref.j(), 0);
    }

    private double[] net(int patch) {
        return nets.computeIfAbsent(patch, p -> base.patches().get(p).copyNet());
    }

    /** The scene with every move applied (the base itself when nothing moved); untouched patches are shared. */
    Scene apply() {
        if (nets.isEmpty()) {
            return base;
        }
        List<BezierPatch> patches = new ArrayList<>(base.patches());
        for (Map.Entry<Integer, double[]> e : nets.entrySet()) {
            patches.set(e.getKey(), withNet(base.patches().get(e.getKey()), e.getValue()));
        }
        return base.toBuilder().patches(patches).build();
    }

    /**
     * {@code p} with another net of the same size, everything else kept. The one place an edit
     * makes a patch from a net: a rational patch keeps its weights, a trimmed one its trim
     * region and domain ({@link BezierPatch#withNet}).
     */
    static BezierPatch withNet(BezierPatch p, double[] net) {
        return p.withNet(net);
    }
}
