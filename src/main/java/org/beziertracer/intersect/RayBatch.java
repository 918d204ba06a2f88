package org.beziertracer.intersect;

/**
 * A batch of rays in struct-of-arrays form, traced together through one traversal and solved
 * together at the leaves they share ({@link SceneIntersector#closestHits}): per lane the ray, its
 * ray-space frame, its interval and its result slots (the best hit so far and the solver's
 * evaluation there).
 *
 * <h2>Layout</h2>
 * Lane {@code i}:
 * <ul>
 *   <li>{@code traversal[6i .. 6i+6)}: origin, reciprocal direction (what the hierarchy reads);</li>
 *   <li>{@code frame[FRAME·i ..)}: direction, the unit normals {@code n1, n2, n3} of the ray's
 *       planes and {@code 1/|d|} ({@link TraceContext}'s ray space), the latter made when a leaf
 *       first needs them ({@code frameSet[i]});</li>
 *   <li>{@code tMax[i]}, {@code found[i]}, {@code best[i]}; {@code hitEval[9i .. 9i+9)} with
 *       {@code hitEvalPatch[i]}, {@code hitEvalU[i]}, {@code hitEvalV[i]}: the evaluation at the
 *       best hit, kept for its surface point.</li>
 * </ul>
 * A leaf solves a lane with the thread's {@link TraceContext} as its scratch: {@link #load} puts the
 * lane's ray and results there, {@link #store} takes the results back. The solvers' stages that run
 * across lanes at once ({@link NewtonLanes}) read the lanes here directly.
 *
 * <p>Per-thread scratch: mutable, not thread-safe; grows (rarely) to the largest batch, and
 * allocates nothing per ray after that.
 */
public final class RayBatch {

    static final int FRAME = 13;

    int capacity, count;
    double tMin;
    double[] traversal = new double[0], frame = new double[0], tMax = new double[0];
    boolean[] found = new boolean[0], frameSet = new boolean[0];
    Hit[] best = new Hit[0];
    double[] hitEval = new double[0], hitEvalU = new double[0], hitEvalV = new double[0];
    int[] hitEvalPatch = new int[0];
    /** Scratch for the traversal's lane lists. */
    int[] live = new int[0], reached = new int[0];

    /** Lanes in the batch. */
    public int count() { return count; }

    /** Room for {@code n} lanes. */
    void ensure(int n) {
        if (capacity >= n) {
            return;
        }
        int c = Math.max(n, 2 * capacity);
        traversal = new double[6 * c];
        frame = new double[FRAME * c];
        tMax = new double[c];
        found = new boolean[c];
        frameSet = new boolean[c];
        Hit[] b = new Hit[c];
        for (int i = 0; i < c; i++) {
            b[i] = i < best.length ? best[i] : new Hit();
        }
        best = b;
        hitEval = new double[9 * c];
        hitEvalU = new double[c];
        hitEvalV = new double[c];
        hitEvalPatch = new int[c];
        live = new int[c];
        reached = new int[c];
        capacity = c;
    }

    /**
     * Makes the batch the {@code n} rays at {@code rays[6i .. 6i+6)} (origin, direction), each on
     * {@code (tMin, tMax)}, no hit yet.
     */
    void set(TraceContext ctx, double[] rays, int n, double tMin, double tMax) {
        ensure(n);
        count = n;
        this.tMin = tMin;
        for (int i = 0; i < n; i++) {
            int o = 6 * i, f = FRAME * i;
            double dx = rays[o + 3], dy = rays[o + 4], dz = rays[o + 5];
            // as TraceContext.setTraversal: the frame waits until a leaf needs it (load)
            traversal[o] = rays[o]; traversal[o + 1] = rays[o + 1]; traversal[o + 2] = rays[o + 2];
            traversal[o + 3] = 1.0 / dx; traversal[o + 4] = 1.0 / dy; traversal[o + 5] = 1.0 / dz;
            frame[f] = dx; frame[f + 1] = dy; frame[f + 2] = dz;
            frameSet[i] = false;
            this.tMax[i] = tMax;
            found[i] = false;
            hitEvalPatch[i] = -1;
        }
    }

    /**
     * Makes lane {@code i}'s ray, frame and results the context's current closest-hit query (the
     * frame made on the lane's first load, by the context, as for a ray alone).
     */
    void load(TraceContext ctx, int i) {
        load(ctx, i, true);
    }

    /** {@link #load}; without {@code withFrame} a frame not made yet is left to the context's {@code ensurePlanes}. */
    void load(TraceContext ctx, int i, boolean withFrame) {
        int o = 6 * i, f = FRAME * i;
        double[] t = traversal, fr = frame;
        ctx.ox = t[o]; ctx.oy = t[o + 1]; ctx.oz = t[o + 2];
        ctx.invDx = t[o + 3]; ctx.invDy = t[o + 4]; ctx.invDz = t[o + 5];
        ctx.dx = fr[f]; ctx.dy = fr[f + 1]; ctx.dz = fr[f + 2];
        if (frameSet[i]) {
            ctx.n1x = fr[f + 3]; ctx.n1y = fr[f + 4]; ctx.n1z = fr[f + 5];
            ctx.n2x = fr[f + 6]; ctx.n2y = fr[f + 7]; ctx.n2z = fr[f + 8];
            ctx.n3x = fr[f + 9]; ctx.n3y = fr[f + 10]; ctx.n3z = fr[f + 11];
            ctx.invLength = fr[f + 12];
            ctx.planesSet = true;
        } else if (!withFrame) {
            ctx.planesSet = false;
        } else {
            ctx.planesSet = false;
            ctx.ensurePlanes();
            fr[f + 3] = ctx.n1x; fr[f + 4] = ctx.n1y; fr[f + 5] = ctx.n1z;
            fr[f + 6] = ctx.n2x; fr[f + 7] = ctx.n2y; fr[f + 8] = ctx.n2z;
            fr[f + 9] = ctx.n3x; fr[f + 10] = ctx.n3y; fr[f + 11] = ctx.n3z;
            fr[f + 12] = ctx.invLength;
            frameSet[i] = true;
        }
        ctx.tMin = tMin;
        ctx.anyHit = false;
        ctx.found = found[i];
        if (found[i]) {
            ctx.best.set(best[i]);
        }
        int k = hitEvalPatch[i];
        ctx.hitEvalPatch = k;
        if (k >= 0) {
            ctx.hitEvalU = hitEvalU[i];
            ctx.hitEvalV = hitEvalV[i];
            System.arraycopy(hitEval, 9 * i, ctx.hitEval, 0, 9);
        }
    }

    /** Takes the context's results back into lane {@code i} (after {@link #load} and a leaf's solve). */
    void store(TraceContext ctx, int i) {
        found[i] = ctx.found;
        if (ctx.found) {
            best[i].set(ctx.best);
        }
        int k = ctx.hitEvalPatch;
        hitEvalPatch[i] = k;
        if (k >= 0) {
            hitEvalU[i] = ctx.hitEvalU;
            hitEvalV[i] = ctx.hitEvalV;
            System.arraycopy(ctx.hitEval, 0, hitEval, 9 * i, 9);
        }
    }
}
