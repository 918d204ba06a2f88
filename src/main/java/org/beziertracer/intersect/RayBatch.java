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
 * A leaf solves a lane with the thread's {@link TraceContext} as its scratch: {@link #loadRay} puts
 * the lane's ray there, and a hit goes straight to the lane's slots ({@link #record}); the solvers'
 * stages that run across lanes at once ({@link NewtonLanes}) read the lanes here directly. After
 * the traversal {@link #loadResult} hands each lane's result to the context, as a query alone
 * leaves it.
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
    /**
     * A batch of shadow rays ({@link #setShadows}): per lane the hit each leaves (null: none), its
     * surface point, the unit normal on the ray's side at {@code normal[3i ..]}, and the answer.
     */
    Hit[] from = new Hit[0];
    SurfacePoint[] at = new SurfacePoint[0];
    double[] normal = new double[0];
    boolean[] occluded = new boolean[0];
    /** The lane whose origin the context holds ({@link #loadShadowRay}), or -1. */
    private int originLane = -1;
    /**
     * A batch of shadow rays while its traversal runs: each lane's own leaf (the one its ray leaves)
     * is put off ({@link #putOff}) until every other leaf had its say ({@link #solvePutOff}).
     */
    private boolean puttingOff;
    /** Per lane, the leaves whose own leaf was put off ({@code null}: none) and that leaf. */
    ClippingLeaves[] ownLeaves = new ClippingLeaves[0];
    int[] ownLeaf = new int[0];
    /** A batch of one: a single ray of a gathered packet ({@code SceneIntersector.closestHit} with a packet). */
    final double[] oneRay = new double[6], oneNormal = new double[3];
    final Hit[] oneHit = {new Hit()}, oneFrom = new Hit[1];
    final SurfacePoint[] oneAt = new SurfacePoint[1];
    final boolean[] oneAnswer = new boolean[1];
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
        from = new Hit[c];
        at = new SurfacePoint[c];
        normal = new double[3 * c];
        occluded = new boolean[c];
        ownLeaves = new ClippingLeaves[c];
        ownLeaf = new int[c];
        capacity = c;
    }

    /**
     * Makes the batch the {@code n} rays at {@code rays[6i .. 6i+6)} (origin, direction), each on
     * {@code (tMin, tMax)}, no hit yet.
     */
    void set(TraceContext ctx, double[] rays, int n, double tMin, double tMax) {
        ensure(n);
        count = n;
        originLane = -1;
        puttingOff = false;
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
     * Makes the batch the {@code n} shadow rays at {@code rays[6i .. 6i+6)} on {@code (tMin, tMax)},
     * ray {@code i} leaving the hit {@code hits[i]} (null or not a patch hit: it leaves no leaf) at
     * {@code points[i]}, on the side of the unit normal {@code normals[3i .. 3i+3)}; none blocked yet.
     */
    void setShadows(TraceContext ctx, double[] rays, int n, double tMin, double tMax, Hit[] hits,
                    SurfacePoint[] points, double[] normals) {
        set(ctx, rays, n, tMin, tMax);
        for (int i = 0; i < n; i++) {
            from[i] = hits[i];
            at[i] = points[i];
            normal[3 * i] = normals[3 * i];
            normal[3 * i + 1] = normals[3 * i + 1];
            normal[3 * i + 2] = normals[3 * i + 2];
            occluded[i] = false;
            ownLeaves[i] = null;
        }
        originLane = -1;
        puttingOff = true;
    }

    /**
     * Puts off the search of lane {@code i}'s own leaf {@code s} of {@code leaves} (the leaf its shadow
     * ray leaves, reached by its traversal, not proven behind it) while the batch's traversal runs;
     * false when it must be solved now.
     * That leaf is the nearest on the ray and its search the dearest (the ray starts on it, where a
     * surface curving toward the light may meet the ray again), and a ray that another leaf blocks
     * needs no answer from it: the answer, blocked or not, is the same in any order.
     */
    boolean putOff(int i, ClippingLeaves leaves, int s) {
        if (!puttingOff) {
            return false;
        }
        ownLeaves[i] = leaves;
        ownLeaf[i] = s;
        return true;
    }

    /**
     * After the traversal of a batch of shadow rays: the own leaves {@linkplain #putOff put off},
     * solved now for the lanes no other leaf blocked (as they would have been when reached).
     */
    void solvePutOff(TraceContext ctx) {
        puttingOff = false;
        for (int i = 0; i < count; i++) {
            ClippingLeaves leaves = ownLeaves[i];
            if (leaves != null) {
                ownLeaves[i] = null;
                if (!occluded[i]) {
                    leaves.solveOwn(ctx, ownLeaf[i], i, tMax, occluded);
                }
            }
        }
    }

    /**
     * {@link #loadRay} for a shadow ray of {@link #setShadows}: an any-hit query that leaves its
     * lane's hit, as {@code SceneIntersector.occludedLeaving} sets it for the ray alone.
     */
    void loadShadowRay(TraceContext ctx, int i) {
        loadRay(ctx, i);
        ctx.anyHit = true;
        if (originLane != i) {
            Hit h = from[i];
            if (h != null && h.kind == Hit.PATCH) {
                ctx.leaving(h.subPatch, h.u, h.v, at[i], normal[3 * i], normal[3 * i + 1], normal[3 * i + 2]);
            } else {
                ctx.originLeaf = -1;
            }
            originLane = i;
        }
    }

    /** The context leaves no lane's origin any more (after a batch of shadow rays). */
    void endShadows(TraceContext ctx) {
        ctx.originLeaf = -1;
        originLane = -1;
        puttingOff = false;
    }

    /**
     * Makes lane {@code i}'s ray and frame the context's current closest-hit query, for a leaf to
     * solve it with the context as scratch (the frame made on the lane's first load, by the context,
     * as for a ray alone). The lane's results stay here: a hit goes to {@link #record}.
     */
    void loadRay(TraceContext ctx, int i) {
        int f = FRAME * i;
        double[] fr = frame;
        loadTraversal(ctx, i);
        if (frameSet[i]) {
            ctx.n1x = fr[f + 3]; ctx.n1y = fr[f + 4]; ctx.n1z = fr[f + 5];
            ctx.n2x = fr[f + 6]; ctx.n2y = fr[f + 7]; ctx.n2z = fr[f + 8];
            ctx.n3x = fr[f + 9]; ctx.n3y = fr[f + 10]; ctx.n3z = fr[f + 11];
            ctx.invLength = fr[f + 12];
            ctx.planesSet = true;
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
    }

    /** Lane {@code i}'s origin, direction and reciprocal direction into the context. */
    private void loadTraversal(TraceContext ctx, int i) {
        int o = 6 * i, f = FRAME * i;
        double[] t = traversal, fr = frame;
        ctx.ox = t[o]; ctx.oy = t[o + 1]; ctx.oz = t[o + 2];
        ctx.invDx = t[o + 3]; ctx.invDy = t[o + 4]; ctx.invDz = t[o + 5];
        ctx.dx = fr[f]; ctx.dy = fr[f + 1]; ctx.dz = fr[f + 2];
    }

    /**
     * Records the solver's root ({@code ctx.root*}, its ray the context's since {@link #loadRay}) on
     * leaf {@code s} of patch {@code k} as lane {@code i}'s best hit, with the solver's last
     * evaluation when it stands at that root: what {@code PatchLeaves.recordRoot} does for a ray
     * alone. Returns the hit's t.
     */
    double record(TraceContext ctx, int i, int k, int s) {
        found[i] = true;
        Hit b = best[i];
        b.t = ctx.rootT;
        b.kind = Hit.PATCH;
        b.index = k;
        b.subPatch = s;
        b.u = ctx.rootU;
        b.v = ctx.rootV;
        b.b1 = 0; // only triangles have barycentrics
        b.b2 = 0;
        if (ctx.evalPatch == k && ctx.evalU == ctx.rootU && ctx.evalV == ctx.rootV) {
            System.arraycopy(ctx.eval, 0, hitEval, 9 * i, 9);
            hitEvalPatch[i] = k;
            hitEvalU[i] = ctx.evalU;
            hitEvalV[i] = ctx.evalV;
        }
        return ctx.rootT;
    }

    /**
     * Keeps the context's best hit ({@code ctx.best}, recorded by a leaf of another kind than
     * patches, after {@link #loadRay}) as lane {@code i}'s.
     */
    void recordBest(TraceContext ctx, int i) {
        found[i] = true;
        best[i].set(ctx.best);
    }

    /**
     * Makes lane {@code i}'s ray (without its frame) and results the context's, as a closest-hit
     * query alone leaves them after its traversal: for the planes and spheres, the hit and its
     * surface point.
     */
    void loadResult(TraceContext ctx, int i) {
        loadTraversal(ctx, i);
        ctx.planesSet = false;
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
}
