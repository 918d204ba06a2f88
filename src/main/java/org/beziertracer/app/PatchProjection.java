package org.beziertracer.app;

import org.beziertracer.model.BezierPatch;

/**
 * Projects one patch's control net onto the picture into reusable scratch arrays (no allocation
 * per patch): {@link #xy} holds {@code 2·(n+1)(m+1)} pixel coordinates in the net's order (u
 * fastest), {@link #depth} the view depth of each point. A patch with a point at or behind the eye
 * plane is not visible. Not thread-safe (one per build).
 */
final class PatchProjection {

    private static final int MAX_POINTS = (BezierPatch.MAX_DEGREE + 1) * (BezierPatch.MAX_DEGREE + 1);

    final double[] xy = new double[2 * MAX_POINTS];
    /**
     * For a rational patch, its projected homogeneous net: {@code w·x, w·y, w} per point (the
     * weights carried over to the picture, as the iso-curves of the projected net use them).
     */
    final double[] xyw = new double[3 * MAX_POINTS];
    /** True when the last projected patch is rational ({@link #xyw} filled). */
    boolean rational;
    final double[] depth = new double[MAX_POINTS];
    private final double[] net = new double[3 * MAX_POINTS];
    private final double[] out = new double[3];
    private final ScreenProjector projector;
    private double minX, minY, maxX, maxY, nearest;

    PatchProjection(ScreenProjector projector) {
        this.projector = projector;
    }

    /** Projects {@code patch}; false when a point lies at or behind the eye plane. */
    boolean project(BezierPatch patch) {
        patch.copyNetInto(net, 0);
        minX = minY = Double.POSITIVE_INFINITY;
        maxX = maxY = Double.NEGATIVE_INFINITY;
        nearest = Double.POSITIVE_INFINITY;
        for (int k = 0, count = patch.pointCount(); k < count; k++) {
            if (!projector.project(net[3 * k], net[3 * k + 1], net[3 * k + 2], out)) {
                return false;
            }
            xy[2 * k] = out[0];
            xy[2 * k + 1] = out[1];
            depth[k] = out[2];
            nearest = Math.min(nearest, out[2]);
            minX = Math.min(minX, out[0]);
            maxX = Math.max(maxX, out[0]);
            minY = Math.min(minY, out[1]);
            maxY = Math.max(maxY, out[1]);
        }
        rational = patch.isRational();
        if (rational) {
            double[] w = patch.weights();
            for (int k = 0; k < w.length; k++) {
                xyw[3 * k] = w[k] * xy[2 * k];
                xyw[3 * k + 1] = w[k] * xy[2 * k + 1];
                xyw[3 * k + 2] = w[k];
            }
        }
        return true;
    }

    /** True when pixel {@code (x, y)} lies in the last projected net's pixel box (its convex hull holds the patch). */
    boolean covers(double x, double y) {
        return x >= minX && x <= maxX && y >= minY && y <= maxY;
    }

    /** Writes the last projected net's pixel box and nearest depth to {@code out[o..o+5)}: minX, minY, maxX, maxY, depth. */
    void box(float[] out, int o) {
        out[o] = (float) minX;
        out[o + 1] = (float) minY;
        out[o + 2] = (float) maxX;
        out[o + 3] = (float) maxY;
        out[o + 4] = (float) nearest;
    }

    /** The depth of the last projected net's point nearest the eye. */
    double nearestDepth() { return nearest; }

    /**
     * The larger side of the last projected net's pixel box, or −1 when that box lies wholly
     * more than {@code margin} pixels outside the picture.
     */
    double extent(double margin) {
        if (maxX < -margin || maxY < -margin || minX > projector.width() + margin || minY > projector.height() + margin) {
            return -1;
        }
        return Math.max(maxX - minX, maxY - minY);
    }
}
