package org.beziertracer.accel;

import java.util.Arrays;

/**
 * Top-down binned surface-area-heuristic builder for {@link Bvh}.
 *
 * <p>Method: I. Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", IEEE
 * Symposium on Interactive Ray Tracing, 2007. Each node's primitive centroids are binned into
 * {@code binCount} equal intervals per axis of the centroid bounds (one pass for all three axes);
 * a left and a right sweep evaluate the SAH at every bin border; the cheapest border wins. Node
 * layout and in-place partition of one index array follow tinybvh by J. Bikker.
 *
 * <p>Rules: a node with one primitive is a leaf; a node with at most {@code maxLeafSize}
 * primitives becomes a leaf when that is no dearer than the best split. A larger node is always
 * split: by the SAH when the centroids are spread out, otherwise (all centroids equal, e.g.
 * identical boxes) at the middle of its index range, so the build always terminates with leaves
 * of at most {@code maxLeafSize}. The build is iterative (explicit work stack), so even a
 * degenerate, list-like tree cannot overflow the Java stack.
 *
 * <p>Not thread-safe; one instance per build (use {@link Bvh#build}).
 */
final class BinnedSahBuilder {

    /** SAH cost of visiting a node (one box test), relative to {@link #PRIMITIVE_COST}. */
    static final double TRAVERSAL_COST = 1.0;
    /** SAH cost of one leaf callback: a sub-patch test is several times dearer than a box test. */
    static final double PRIMITIVE_COST = 4.0;

    private final double[] primBounds;
    private final int primCount;
    private final int maxLeafSize;
    private final int binCount;

    /** Twice the centre of each primitive box ({@code min + max}), 3 per primitive. */
    private final double[] centroids;
    private final int[] prims;
    private final double[] nodeBounds;
    private final int[] leftFirst;
    private final int[] count;
    private int nodeCount;
    private int depth;

    // Per-node scratch
    private final double[] centroidMin = new double[3];
    private final double[] binScale = new double[3];
    private final int[] binPrims;
    private final double[] binBoxes;
    private final double[] rightArea;
    private final int[] rightPrims;
    private final double[] sweepBox = new double[6];
    private int bestAxis;
    private int bestPlane;
    private double bestCost;

    private BinnedSahBuilder(double[] primBounds, int primCount, BvhOptions opts) {
        this.primBounds = primBounds;
        this.primCount = primCount;
        this.maxLeafSize = opts.maxLeafSize();
        this.binCount = opts.binCount();
        int capacity = Math.max(1, 2 * primCount - 1);
        centroids = new double[3 * primCount];
        prims = new int[primCount];
        nodeBounds = new double[6 * capacity];
        leftFirst = new int[capacity];
        count = new int[capacity];
        binPrims = new int[3 * binCount];
        binBoxes = new double[3 * binCount * 6];
        rightArea = new double[binCount];
        rightPrims = new int[binCount];
    }

    static Bvh build(double[] primBounds, int primCount, BvhOptions opts) {
        long start = System.nanoTime();
        Bvh.checkBounds(primBounds, primCount);
        BinnedSahBuilder b = new BinnedSahBuilder(primBounds, primCount, opts);
        b.run();
        double millis = (System.nanoTime() - start) * 1e-6;
        return new Bvh(Arrays.copyOf(b.nodeBounds, 6 * b.nodeCount),
                Arrays.copyOf(b.leftFirst, b.nodeCount), Arrays.copyOf(b.count, b.nodeCount),
                b.prims, b.depth, millis);
    }

    private void run() {
        for (int p = 0; p < primCount; p++) {
            prims[p] = p;
            for (int a = 0; a < 3; a++) {
                centroids[3 * p + a] = primBounds[6 * p + a] + primBounds[6 * p + 3 + a];
            }
        }
        nodeCount = 1;
        leftFirst[0] = 0;
        count[0] = primCount;
        if (primCount == 0) {
            System.arraycopy(new double[] {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                    Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
                    Double.NEGATIVE_INFINITY}, 0, nodeBounds, 0, 6);
            depth = 1;
            return;
        }
        // Work stack of (node, level) pairs; pending nodes never exceed primCount.
        int[] work = new int[2 * Math.max(2, primCount)];
        int sp = 0;
        work[sp++] = 0;
        work[sp++] = 1;
        while (sp > 0) {
            int level = work[--sp];
            int node = work[--sp];
            depth = Math.max(depth, level);
            int first = leftFirst[node], n = count[node];
            double area = computeBounds(node, first, n);
            if (n <= 1) {
                continue;
            }
            boolean found = findSplit(first, n, area);
            if (n <= maxLeafSize && (!found || PRIMITIVE_COST * n * area <= bestCost)) {
                continue;
            }
            int mid = found ? partition(first, n) : first + n / 2;
            if (mid == first || mid == first + n) {
                mid = first + n / 2; // cannot happen with a valid split; guard against rounding
            }
            int left = nodeCount;
            nodeCount += 2;
            leftFirst[left] = first;
            count[left] = mid - first;
            leftFirst[left + 1] = mid;
            count[left + 1] = first + n - mid;
            leftFirst[node] = left;
            count[node] = 0;
            work[sp++] = left + 1;
            work[sp++] = level + 1;
            work[sp++] = left;
            work[sp++] = level + 1;
        }
    }

    /**
     * Writes the node box, records the centroid bounds for binning and returns the node's half
     * surface area.
     */
    private double computeBounds(int node, int first, int n) {
        double minX = Double.POSITIVE_INFINITY, minY = minX, minZ = minX;
        double maxX = Double.NEGATIVE_INFINITY, maxY = maxX, maxZ = maxX;
        double cMinX = minX, cMinY = minX, cMinZ = minX, cMaxX = maxX, cMaxY = maxX, cMaxZ = maxX;
        for (int i = first; i < first + n; i++) {
            int p = prims[i], o = 6 * p, c = 3 * p;
            minX = Math.min(minX, primBounds[o]);
            minY = Math.min(minY, primBounds[o + 1]);
            minZ = Math.min(minZ, primBounds[o + 2]);
            maxX = Math.max(maxX, primBounds[o + 3]);
            maxY = Math.max(maxY, primBounds[o + 4]);
            maxZ = Math.max(maxZ, primBounds[o + 5]);
            cMinX = Math.min(cMinX, centroids[c]);
            cMinY = Math.min(cMinY, centroids[c + 1]);
            cMinZ = Math.min(cMinZ, centroids[c + 2]);
            cMaxX = Math.max(cMaxX, centroids[c]);
            cMaxY = Math.max(cMaxY, centroids[c + 1]);
            cMaxZ = Math.max(cMaxZ, centroids[c + 2]);
        }
        int o = 6 * node;
        nodeBounds[o] = minX;
        nodeBounds[o + 1] = minY;
        nodeBounds[o + 2] = minZ;
        nodeBounds[o + 3] = maxX;
        nodeBounds[o + 4] = maxY;
        nodeBounds[o + 5] = maxZ;
        setBinning(0, cMinX, cMaxX);
        setBinning(1, cMinY, cMaxY);
        setBinning(2, cMinZ, cMaxZ);
        return halfArea(nodeBounds, o);
    }

    /** Bin scale for an axis, or 0 when its centroid extent cannot be binned. */
    private void setBinning(int axis, double cMin, double cMax) {
        double scale = binCount / (cMax - cMin);
        centroidMin[axis] = cMin;
        binScale[axis] = cMax > cMin && Double.isFinite(scale) ? scale : 0;
    }

    private int binOf(int prim, int axis) {
        int b = (int) ((centroids[3 * prim + axis] - centroidMin[axis]) * binScale[axis]);
        return b < 0 ? 0 : b >= binCount ? binCount - 1 : b;
    }

    /**
     * Bins the node's centroids and finds the cheapest bin border; sets {@link #bestAxis},
     * {@link #bestPlane} (first bin of the right side) and {@link #bestCost} (SAH cost times the
     * node area, so flat nodes need no division). False when no axis can be split.
     */
    private boolean findSplit(int first, int n, double area) {
        int bins = binCount;
        Arrays.fill(binPrims, 0);
        for (int k = 0; k < binBoxes.length; k += 6) {
            setEmpty(binBoxes, k);
        }
        for (int i = first; i < first + n; i++) {
            int p = prims[i];
            for (int a = 0; a < 3; a++) {
                if (binScale[a] > 0) {
                    int bin = a * bins + binOf(p, a);
                    binPrims[bin]++;
                    grow(binBoxes, 6 * bin, primBounds, 6 * p);
                }
            }
        }
        bestCost = Double.POSITIVE_INFINITY;
        bestAxis = -1;
        double[] box = sweepBox;
        for (int a = 0; a < 3; a++) {
            if (binScale[a] == 0) {
                continue;
            }
            // Right sweep: rightArea[b] and rightPrims[b] describe bins b..bins-1.
            setEmpty(box, 0);
            int sum = 0;
            for (int b = bins - 1; b > 0; b--) {
                int bin = a * bins + b;
                grow(box, 0, binBoxes, 6 * bin);
                sum += binPrims[bin];
                rightPrims[b] = sum;
                rightArea[b] = sum > 0 ? halfArea(box, 0) : 0;
            }
            // Left sweep: plane b puts bins 0..b-1 on the left.
            setEmpty(box, 0);
            sum = 0;
            for (int b = 1; b < bins; b++) {
                int bin = a * bins + b - 1;
                grow(box, 0, binBoxes, 6 * bin);
                sum += binPrims[bin];
                if (sum == 0 || rightPrims[b] == 0) {
                    continue;
                }
                double cost = TRAVERSAL_COST * area
                        + PRIMITIVE_COST * (halfArea(box, 0) * sum + rightArea[b] * rightPrims[b]);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = a;
                    bestPlane = b;
                }
            }
        }
        return bestAxis >= 0;
    }

    /** Partitions the node's indices: bins below {@link #bestPlane} first; returns the border. */
    private int partition(int first, int n) {
        int i = first, j = first + n - 1;
        while (i <= j) {
            if (binOf(prims[i], bestAxis) < bestPlane) {
                i++;
            } else {
                int t = prims[i];
                prims[i] = prims[j];
                prims[j--] = t;
            }
        }
        return i;
    }

    static double halfArea(double[] b, int o) {
        double dx = b[o + 3] - b[o], dy = b[o + 4] - b[o + 1], dz = b[o + 5] - b[o + 2];
        return dx * dy + dy * dz + dz * dx;
    }

    static void setEmpty(double[] b, int o) {
        b[o] = b[o + 1] = b[o + 2] = Double.POSITIVE_INFINITY;
        b[o + 3] = b[o + 4] = b[o + 5] = Double.NEGATIVE_INFINITY;
    }

    /** Grows box {@code dst[d..d+5]} to contain box {@code src[s..s+5]}. */
    static void grow(double[] dst, int d, double[] src, int s) {
        for (int k = 0; k < 3; k++) {
            dst[d + k] = Math.min(dst[d + k], src[s + k]);
            dst[d + 3 + k] = Math.max(dst[d + 3 + k], src[s + 3 + k]);
        }
    }
}
