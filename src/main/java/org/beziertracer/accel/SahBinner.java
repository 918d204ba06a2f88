package org.beziertracer.accel;

import static org.beziertracer.accel.BinnedSahBuilder.PRIMITIVE_COST;
import static org.beziertracer.accel.BinnedSahBuilder.TRAVERSAL_COST;
import static org.beziertracer.accel.BvhBuild.grow;
import static org.beziertracer.accel.BvhBuild.growPoint;
import static org.beziertracer.accel.BvhBuild.halfArea;
import static org.beziertracer.accel.BvhBuild.setEmpty;

import java.util.Arrays;

/**
 * One node's split for {@link BinnedSahBuilder}: bins the centroids along all three axes (Wald
 * 2007), or in big builds ({@link BinnedSahBuilder#ALL_AXES_PRIMS}) along the axis of their widest
 * extent only (a third of the binning for trees about 1–2 % dearer in SAH cost), sweeps the bins for the cheapest SAH border, partitions the node's primitive indices and
 * writes the children's boxes. Scratch of one build task; not thread-safe.
 */
final class SahBinner {

    private final BinnedSahBuilder b;
    private final int[] counts;
    private final float[] binBoxes;
    private final int[] rightCounts;
    private final float[] rightBoxes;
    private final float[] box = new float[6];
    private final float[] bestLeft = new float[6];
    private final float[] bestRight = new float[6];
    private final float[] cmin = new float[3];
    private final float[] scale = new float[3];
    /** Centroid bounds of the children of the last split. */
    final float[] leftCentroids = new float[6];
    final float[] rightCentroids = new float[6];
    private int bins;
    private int bestAxis;
    private int bestPlane;

    SahBinner(BinnedSahBuilder b) {
        this.b = b;
        int max = b.binCount;
        counts = new int[3 * max];
        binBoxes = new float[3 * max * 6];
        rightCounts = new int[max];
        rightBoxes = new float[6 * max];
    }

    /**
     * Splits node {@code slot} (its box already written) over {@code prims[first .. first+n-1]}
     * with centroid bounds {@code cbox}: -1 when it stays a leaf; else partitions the indices,
     * writes the children's boxes at slots {@code desc} and {@code desc+1}, their centroid bounds
     * to {@link #leftCentroids} and {@link #rightCentroids}, and returns the border.
     */
    int split(int slot, int desc, int first, int n, float[] cbox) {
        if (n == 1) {
            return -1;
        }
        bins = Math.min(b.binCount, Math.max(2, n));
        boolean any = false;
        int widest = 0;
        for (int a = 1; a < 3; a++) {
            if (cbox[3 + a] - cbox[a] > cbox[3 + widest] - cbox[widest]) {
                widest = a;
            }
        }
        for (int a = 0; a < 3; a++) {
            float extent = cbox[3 + a] - cbox[a];
            float s = bins / extent;
            cmin[a] = cbox[a];
            scale[a] = (b.allAxes || a == widest) && extent > 0 && Float.isFinite(s) ? s : 0;
            any |= scale[a] > 0;
        }
        if (!any) {
            return n <= b.maxLeafSize ? -1 : middle(desc, first, n);
        }
        double area = halfArea(b.nodeBounds, 6 * slot);
        bin(first, n);
        double bestCost = sweep(area);
        if (n <= b.maxLeafSize && PRIMITIVE_COST * n * area <= bestCost) {
            return -1;
        }
        if (bestAxis < 0) {
            return middle(desc, first, n); // cannot happen: a binned axis has its extremes in its end bins
        }
        int mid = partition(first, n);
        if (mid == first || mid == first + n) {
            return middle(desc, first, n); // cannot happen with a valid split; guard against rounding
        }
        System.arraycopy(bestLeft, 0, b.nodeBounds, 6 * desc, 6);
        System.arraycopy(bestRight, 0, b.nodeBounds, 6 * desc + 6, 6);
        return mid;
    }

    /** Splits at the middle of the index range; the children's boxes from a pass over each half. */
    private int middle(int desc, int first, int n) {
        int mid = first + n / 2;
        b.unionOf(first, mid - first, b.nodeBounds, 6 * desc, leftCentroids);
        b.unionOf(mid, first + n - mid, b.nodeBounds, 6 * desc + 6, rightCentroids);
        return mid;
    }

    private int binOf(float c, int axis) {
        int k = (int) ((c - cmin[axis]) * scale[axis]);
        return k < 0 ? 0 : k >= bins ? bins - 1 : k;
    }

    /** Counts and boxes of the bins on the binned axis. */
    private void bin(int first, int n) {
        int[] cnt = counts;
        float[] bb = binBoxes, pb = b.boxes, c = b.centroids;
        Arrays.fill(cnt, 0, 3 * bins, 0);
        for (int k = 0; k < 3 * bins; k++) {
            setEmpty(bb, 6 * k);
        }
        for (int i = first; i < first + n; i++) {
            for (int a = 0; a < 3; a++) {
                if (scale[a] > 0) {
                    int bin = a * bins + binOf(c[3 * i + a], a);
                    cnt[bin]++;
                    grow(bb, 6 * bin, pb, 6 * i);
                }
            }
        }
    }

    /**
     * The cheapest bin border over the binned axes: sets the best axis, plane (first bin of the
     * right side) and both sides' boxes; returns its SAH cost times the node area (so flat nodes
     * need no division), +Infinity when no border has primitives on both sides.
     */
    private double sweep(double area) {
        double bestCost = Double.POSITIVE_INFINITY;
        bestAxis = -1;
        for (int a = 0; a < 3; a++) {
            if (scale[a] == 0) {
                continue;
            }
            // Right sweep: rightBoxes[6k..] and rightCounts[k] describe bins k..bins-1
            setEmpty(box, 0);
            int sum = 0;
            for (int k = bins - 1; k > 0; k--) {
                int bin = a * bins + k;
                grow(box, 0, binBoxes, 6 * bin);
                sum += counts[bin];
                rightCounts[k] = sum;
                System.arraycopy(box, 0, rightBoxes, 6 * k, 6);
            }
            // Left sweep: plane k puts bins 0..k-1 on the left
            setEmpty(box, 0);
            sum = 0;
            for (int k = 1; k < bins; k++) {
                int bin = a * bins + k - 1;
                grow(box, 0, binBoxes, 6 * bin);
                sum += counts[bin];
                if (sum == 0 || rightCounts[k] == 0) {
                    continue;
                }
                double cost = TRAVERSAL_COST * area
                        + PRIMITIVE_COST * (halfArea(box, 0) * sum + halfArea(rightBoxes, 6 * k) * rightCounts[k]);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = a;
                    bestPlane = k;
                    System.arraycopy(box, 0, bestLeft, 0, 6);
                    System.arraycopy(rightBoxes, 6 * k, bestRight, 0, 6);
                }
            }
        }
        return bestCost;
    }

    /**
     * Partitions the node's indices: bins below the best plane first; gathers each side's
     * centroid bounds; returns the border.
     */
    private int partition(int first, int n) {
        float[] c = b.centroids;
        int axis = bestAxis, plane = bestPlane;
        setEmpty(leftCentroids, 0);
        setEmpty(rightCentroids, 0);
        int i = first, j = first + n - 1;
        while (i <= j) {
            if (binOf(c[3 * i + axis], axis) < plane) {
                growPoint(leftCentroids, c, 3 * i);
                i++;
            } else {
                growPoint(rightCentroids, c, 3 * i);
                b.swap(i, j--);
            }
        }
        return i;
    }
}
