package org.beziertracer.geometry;

/**
 * An earlier split of a patch, replayed: the parameter boxes of its leaves in the order the
 * depth-first halving of {@link PatchSplitter} made them (a patch's range of
 * {@link SubPatchTable#boxes}). {@link PatchSplitter#resplit} walks the same halvings on the
 * edited net, so that a dragged patch keeps its leaves (and the BVH over them can be refitted
 * rather than rebuilt).
 *
 * <p>The leaves of an untrimmed patch tile its parameter square, and every box is a dyadic
 * rectangle (exact in a float down to 2<sup>-24</sup>), so the halving that made a node is read
 * off the boxes: the node was halved in u exactly when the leaves that follow the cursor and lie in
 * its lower u half cover that half (their areas, exact sums of powers of two, add up to half the
 * node's). Halved in v, that run lies in the node's lower-left quarter and covers at most half of
 * it. Boxes that do not tile (a trimmed patch's, or a table's of another patch) make the guide
 * {@link #failed()} rather than guess.
 */
final class SplitGuide {
    private final float[] boxes;
    private final int end;
    private int cursor;
    private boolean failed;

    /** The leaves {@code from .. to-1} of {@code boxes} (4 floats a leaf: u0, u1, v0, v1). */
    SplitGuide(float[] boxes, int from, int to) {
        this.boxes = boxes;
        this.cursor = from;
        this.end = to;
    }

    /** True when the next leaf of the old split is the node {@code [u0,u1]×[v0,v1]}; it is then consumed. */
    boolean takeLeaf(double u0, double u1, double v0, double v1) {
        if (cursor < end && boxes[4 * cursor] == u0 && boxes[4 * cursor + 1] == u1
                && boxes[4 * cursor + 2] == v0 && boxes[4 * cursor + 3] == v1) {
            cursor++;
            return true;
        }
        return false;
    }

    /**
     * True when the old split halved the node {@code [u0,u1]×[v0,v1]} (not a leaf) in u, false
     * when in v; when neither is consistent with the boxes the guide has {@link #failed()}.
     */
    boolean halvedInU(double u0, double u1, double v0, double v1) {
        if (runEnd(u0, 0.5 * (u0 + u1), v0, v1) > cursor) {
            return true;
        }
        if (runEnd(u0, u1, v0, 0.5 * (v0 + v1)) == cursor) {
            failed = true;
        }
        return false;
    }

    /**
     * The end (exclusive) of the run of leaves from the cursor that tile {@code [u0,u1]×[v0,v1]}
     * (the node's first half after {@link #halvedInU}); the cursor's index when they do not.
     */
    int runEnd(double u0, double u1, double v0, double v1) {
        double area = 0, whole = (u1 - u0) * (v1 - v0);
        int s = cursor;
        for (; s < end && area < whole; s++) {
            double a0 = boxes[4 * s], a1 = boxes[4 * s + 1], b0 = boxes[4 * s + 2], b1 = boxes[4 * s + 3];
            if (a0 < u0 || a1 > u1 || b0 < v0 || b1 > v1) {
                break;
            }
            area += (a1 - a0) * (b1 - b0);
        }
        return area == whole ? s : cursor;
    }

    /** Marks the replay void (the boxes ask for a halving the split would not make). */
    void fail() { failed = true; }

    /** The guide's boxes did not tile the patch the way a halving does: the replay is void. */
    boolean failed() { return failed; }

    /** True when every leaf of the old split was replayed. */
    boolean finished() { return cursor == end; }
}
