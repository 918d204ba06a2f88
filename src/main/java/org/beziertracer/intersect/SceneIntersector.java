package org.beziertracer.intersect;

import org.beziertracer.accel.Accelerator;
import org.beziertracer.accel.Bvh;
import org.beziertracer.accel.BvhOptions;
import org.beziertracer.accel.FlatList;
import org.beziertracer.accel.RayPacket;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The whole-scene ray queries: {@link #closestHit} and {@link #occluded} over Bézier patches
 * (sub-patch BVH, then the chosen solver at the leaves: {@link Leaves}), triangle meshes and
 * spheres (leaves of the same BVH when the scene holds them: {@link MixedLeaves}) and planes
 * (unbounded: tested apart, after the BVH).
 *
 * <p>Immutable snapshot: build once per scene, share between render threads, each with its own
 * {@link TraceContext}. An edit of one patch makes a new snapshot with {@link #withPatch}, which
 * re-splits only that patch and refits the BVH (or rebuilds it when the number of sub-patches
 * changed).
 *
 * <p>In tessellated mode ({@link IntersectOptions#tessellate()} {@code = K > 0}) the patches are
 * replaced by a uniform triangle mesh ({@link TriangleMesh}) in the same kind of BVH; hits still
 * report the patch index and its (u,v), interpolated over the triangle, and
 * {@link #surfacePoint} returns the point on the triangle with the interpolated analytic normal.
 */
public final class SceneIntersector {

    final Scene scene;
    /** The primitives in the accelerator and their solver, chosen once by {@link Leaves#of}. */
    final Leaves leaves;
    final Accelerator accel;
    final IntersectOptions options;
    /** The planes, and the spheres unless the leaves hold them ({@link #spheresInLeaves}). */
    final AnalyticShapes shapes;
    /** True when the spheres are leaves of the BVH ({@link Leaves#holdsSpheres}). */
    final boolean spheresInLeaves;
    final double sceneSize;
    final double buildMillis;
    /**
     * Edits in a row that kept their patches' old halvings ({@link #withPatches}); 0 after a build
     * or an edit that split afresh. Scene-wide: the edit that splits afresh re-splits its own
     * patches only, so a patch dragged earlier keeps its leaves until it is edited again; each of
     * them is within twice the flatness tolerance (checked at its patch's last edit), it may only be
     * finer than a fresh split's.
     */
    final int keptEdits;

    private SceneIntersector(Scene scene, Leaves leaves, Accelerator accel, IntersectOptions options,
                             double sceneSize, double buildMillis, int keptEdits) {
        this.scene = scene;
        this.leaves = leaves;
        this.accel = accel;
        this.options = options;
        // Spheres in the BVH (a scene of more than one kind, MixedLeaves) are not tested apart;
        // planes are unbounded and always are
        this.spheresInLeaves = leaves.holdsSpheres();
        this.shapes = new AnalyticShapes(scene.planes(), spheresInLeaves ? java.util.List.of() : scene.spheres());
        this.sceneSize = sceneSize;
        this.buildMillis = buildMillis;
        this.keptEdits = keptEdits;
    }

    /**
     * Makes the leaves (splitting the patches, or tessellating them) and builds the acceleration structure.
     *
     * @throws IllegalArgumentException (one line, {@link HeapBudget}) when it would not fit in the heap
     */
    public static SceneIntersector build(Scene scene, IntersectOptions options) {
        HeapBudget.require(null, scene, options);
        long t0 = System.nanoTime();
        double size = sizeOf(scene);
        Leaves leaves = Leaves.of(scene, options, size);
        Accelerator accel = buildAccel(leaves, scene.patches().size(), options);
        return new SceneIntersector(scene, leaves, accel, options, size, (System.nanoTime() - t0) / 1e6, 0);
    }

    /** The scene's size: the diagonal of its patches' control box, 1 when there is none. */
    private static double sizeOf(Scene scene) {
        double size = scene.patches().isEmpty() ? 1 : scene.controlBounds().diagonal();
        return size > 0 ? size : 1;
    }

    private static Accelerator buildAccel(Leaves leaves, int patches, IntersectOptions options) {
        int count = leaves.count();
        double[] bounds = leaves.bounds(0, count);
        if (!options.bvh()) {
            return FlatList.build(bounds, count);
        }
        if (BvhOptions.groupsPay(leaves.patchLeafCount(), patches)) {
            return Bvh.build(bounds, count, leaves.groupFirst(patches), options.bvhOptions());
        }
        return Bvh.build(bounds, count, options.bvhOptions());
    }

    /**
     * Edits in a row that keep the edited patches' old halvings ({@link Leaves#withPatches} with
     * {@code keepSplit}) and so, usually, refit the BVH; the next one splits its patches afresh and
     * rebuilds the whole BVH, so a long drag does not keep a tree fitted to the patches as they were
     * (at 15 pictures a second, one rebuild every two seconds of dragging) nor leaves finer than the
     * dragged patch needs.
     */
    static final int KEPT_EDITS = 32;

    /**
     * A new snapshot with patch {@code index} replaced: the leaves are remade for that patch only
     * where their kind allows it (sub-patches: only that patch is re-split, along its old halvings
     * where they still fit), as {@link #withPatches}.
     */
    public SceneIntersector withPatch(int index, BezierPatch patch) {
        return withPatches(scene.withPatch(index, patch), new int[] {index});
    }

    /**
     * A new snapshot of {@code edited}, a scene that differs from this one's only in the patches
     * {@code indices} (the same number of patches, planes, spheres and materials): those patches'
     * leaves are remade in one pass and the BVH is refitted once; it is rebuilt when the number of
     * leaves changed, when the edit remade other patches' leaves too
     * ({@link Leaves#keepsUntouchedLeaves}: the first rational or trimmed patch), and on every
     * {@link #KEPT_EDITS}-th edit in a row. An edit that moves a point shared by several patches builds one new scene and
     * calls this once, rather than {@link #withPatch} once per copy.
     */
    public SceneIntersector withPatches(Scene edited, int[] indices) {
        long t0 = System.nanoTime();
        double size = sizeOf(edited);
        // an approximate method's hits are its leaves': they must be a fresh split's (Method#exact)
        boolean keep = keptEdits < KEPT_EDITS && options.method().exact();
        Leaves newLeaves = leaves.withPatches(edited, indices, size, keep);
        Accelerator newAccel;
        if (keep && newLeaves.count() == leaves.count() && newLeaves.keepsUntouchedLeaves(leaves)
                && accel instanceof Bvh bvh) {
            // Same number of leaves: only the edited patches' moved; refit the range that covers
            // their leaves (and the ancestors)
            int first = Integer.MAX_VALUE, end = 0;
            for (int index : indices) {
                first = Math.min(first, newLeaves.firstLeaf(index));
                end = Math.max(end, newLeaves.firstLeaf(index) + newLeaves.leafCount(index));
            }
            int n = Math.max(0, end - first);
            newAccel = n == 0 ? accel : bvh.refit(newLeaves.bounds(first, n), first, n);
        } else {
            newAccel = buildAccel(newLeaves, edited.patches().size(), options);
        }
        return new SceneIntersector(edited, newLeaves, newAccel, options, size, (System.nanoTime() - t0) / 1e6,
                keep ? keptEdits + 1 : 0);
    }

    /** A fresh per-thread context, with this snapshot's kernel ({@link IntersectOptions#kernel}). */
    public TraceContext newContext() { return new TraceContext(options.kernel()); }

    /**
     * Closest hit of the ray {@code o + t d}, {@code tMin < t < tMax}. Fills {@code hit} and
     * returns true when there is one. {@code d} need not be unit; t is along d as given.
     */
    public boolean closestHit(TraceContext ctx, double ox, double oy, double oz, double dx, double dy, double dz,
                              double tMin, double tMax, Hit hit) {
        return closestHit(ctx, null, ox, oy, oz, dx, dy, dz, tMin, tMax, hit);
    }

    /**
     * Lists the leaves the rays added to {@code packet} may meet between {@code tMin} and {@code
     * tMax}, with one traversal of the hierarchy for them all ({@link Accelerator#gather}); each
     * ray's own interval must lie within those bounds. Returns false when they
     * cannot be traversed together; then pass {@code null} as the packet to {@link
     * #closestHit(TraceContext, RayPacket, double, double, double, double, double, double, double,
     * double, Hit)}, or call it anyway: it traverses for each ray alone.
     */
    public boolean gather(TraceContext ctx, RayPacket packet, double tMin, double tMax) {
        ctx.ensureStack(accel.stackSize());
        return accel.primCount() > 0 && accel.gather(packet, tMin, tMax, ctx.stack);
    }

    /**
     * {@link #closestHit(TraceContext, double, double, double, double, double, double, double, double,
     * Hit)} for a ray of {@code packet}, from the packet's leaves where {@link #gather} listed them
     * for this snapshot (the same answer), else by a traversal of its own.
     */
    public boolean closestHit(TraceContext ctx, RayPacket packet, double ox, double oy, double oz,
                              double dx, double dy, double dz, double tMin, double tMax, Hit hit) {
        if (batches(packet)) {
            // a single ray of a gathered packet is a batch of one
            RayBatch batch = ctx.batch;
            double[] r = batch.oneRay;
            r[0] = ox; r[1] = oy; r[2] = oz; r[3] = dx; r[4] = dy; r[5] = dz;
            closestHits(ctx, packet, r, 1, tMin, tMax, batch.oneHit, batch.oneAnswer, null);
            if (batch.oneAnswer[0]) {
                hit.set(batch.oneHit[0]);
            }
            return batch.oneAnswer[0];
        }
        ctx.ensureStack(accel.stackSize());
        ctx.setTraversal(ox, oy, oz, dx, dy, dz);
        ctx.beginClosestHit(tMin);
        leaves.beginRay(ctx);
        double best = tMax;
        if (accel.primCount() > 0) {
            best = accel.closestHit(ox, oy, oz, ctx.invDx, ctx.invDy, ctx.invDz, tMin, tMax, leaves, ctx, ctx.stack);
        }
        return finishClosestHit(ctx, tMin, best, hit);
    }

    /**
     * True when the rays of {@code packet} go as a {@link RayBatch}: the packet was gathered by this
     * snapshot's hierarchy and the leaves solve lanes.
     */
    private boolean batches(RayPacket packet) {
        return packet != null && packet.gatheredBy(accel) && accel instanceof Bvh && leaves.lanes() != null
                && leaves.anyLanes() != null;
    }

    /**
     * The end of a closest-hit query whose patch leaves have been searched (the context holds the
     * ray and its best patch hit): that hit, or a nearer plane or sphere, into {@code hit}.
     */
    private boolean finishClosestHit(TraceContext ctx, double tMin, double best, Hit hit) {
        double ox = ctx.ox, oy = ctx.oy, oz = ctx.oz, dx = ctx.dx, dy = ctx.dy, dz = ctx.dz;
        boolean any = ctx.found;
        boolean analytic = false;
        if (any) {
            hit.set(ctx.best);
            leaves.completeHit(ctx, hit);
            best = hit.t;
        }
        for (int k = 0; k < shapes.planeCount; k++) {
            double t = shapes.planeT(k, ctx);
            if (t > tMin && t < best) {
                best = t;
                any = true;
                analytic = true;
                hit.t = t;
                hit.kind = Hit.PLANE;
                hit.index = k;
                hit.subPatch = -1;
            }
        }
        for (int k = 0; k < shapes.sphereCount; k++) {
            double t = shapes.sphereT(k, ctx, tMin, best);
            if (t > tMin && t < best) {
                best = t;
                any = true;
                analytic = true;
                hit.t = t;
                hit.kind = Hit.SPHERE;
                hit.index = k;
                hit.subPatch = -1;
            }
        }
        if (analytic) {
            hit.b1 = 0;
            hit.b2 = 0;
            double px = ox + hit.t * dx, py = oy + hit.t * dy, pz = oz + hit.t * dz;
            if (hit.kind == Hit.PLANE) {
                shapes.planeUv(hit.index, px, py, pz, hit);
            } else {
                shapes.sphereUv(hit.index, px, py, pz, hit);
            }
        }
        return any;
    }

    /**
     * Closest hits of the {@code n} rays at {@code rays[6i .. 6i+6)} (origin, direction) on
     * {@code (tMin, tMax)}, as one {@link RayBatch}: one traversal for all of them (the packet,
     * {@code packet}, must hold the same rays and have been {@linkplain #gather gathered} for this
     * snapshot; otherwise each ray is traced alone), each leaf solving the lanes that reach it
     * together. Fills {@code hits[i]}, {@code found[i]} and, for each hit, its surface point
     * {@code points[i]} ({@link #surfacePoint}); every answer is the one {@link
     * #closestHit(TraceContext, RayPacket, double, double, double, double, double, double, double,
     * double, Hit)} gives the ray alone, to the bit.
     */
    public void closestHits(TraceContext ctx, RayPacket packet, double[] rays, int n, double tMin, double tMax,
                            Hit[] hits, boolean[] found, SurfacePoint[] points) {
        if (!batches(packet)) {
            for (int i = 0; i < n; i++) {
                int o = 6 * i;
                found[i] = closestHit(ctx, null, rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4],
                        rays[o + 5], tMin, tMax, hits[i]);
                if (found[i] && points != null) {
                    surfacePoint(ctx, hits[i], points[i]);
                }
            }
            return;
        }
        RayBatch batch = ctx.batch;
        batch.set(ctx, rays, n, tMin, tMax);
        ctx.beginClosestHit(tMin);
        ((Bvh) accel).closestHitsIn(packet, batch.traversal, n, tMin, batch.tMax, leaves.lanes(), ctx, batch.live,
                batch.reached);
        for (int i = 0; i < n; i++) {
            batch.loadResult(ctx, i);
            found[i] = finishClosestHit(ctx, tMin, tMax, hits[i]);
            if (found[i] && points != null) {
                surfacePoint(ctx, hits[i], points[i]);
            }
        }
    }

    /**
     * {@link #occludedLeaving} for the {@code n} shadow rays at {@code rays[6i .. 6i+6)} on
     * {@code (tMin, tMax)} as one {@link RayBatch}: ray {@code i} leaves the hit {@code from[i]} at
     * {@code at[i]} on the side of the unit normal {@code normals[3i .. 3i+3)}. One traversal for
     * all (the packet {@code packet} must hold the same rays and have been {@linkplain #gather
     * gathered} for this snapshot; otherwise each ray is traced alone), each leaf solving the lanes
     * that reach it together. Sets {@code blocked[i]} to each ray's answer: the one {@link
     * #occludedLeaving} gives it alone.
     */
    public void occludedLeaving(TraceContext ctx, RayPacket packet, double[] rays, int n, double tMin, double tMax,
                                Hit[] from, SurfacePoint[] at, double[] normals, boolean[] blocked) {
        if (!batches(packet)) {
            for (int i = 0; i < n; i++) {
                int o = 6 * i;
                blocked[i] = occludedLeaving(ctx, null, from[i], at[i], normals[3 * i], normals[3 * i + 1],
                        normals[3 * i + 2], rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5],
                        tMin, tMax);
            }
            return;
        }
        RayBatch batch = ctx.batch;
        batch.setShadows(ctx, rays, n, tMin, tMax, from, at, normals);
        for (int i = 0; i < n; i++) {
            // the spheres and planes first, as for a ray alone
            int o = 6 * i;
            ctx.setTraversal(rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5]);
            batch.occluded[i] = shapesBlock(ctx, tMin, tMax);
        }
        try {
            ((Bvh) accel).occludedAllIn(packet, batch.traversal, n, tMin, batch.tMax, leaves.anyLanes(), ctx,
                    batch.live, batch.reached, batch.occluded);
            batch.solvePutOff(ctx);
        } finally {
            batch.endShadows(ctx);
        }
        System.arraycopy(batch.occluded, 0, blocked, 0, n);
    }

    /** True when a sphere or a plane blocks the context's ray on {@code (tMin, tMax)}. */
    private boolean shapesBlock(TraceContext ctx, double tMin, double tMax) {
        for (int k = 0; k < shapes.sphereCount; k++) {
            if (!Double.isNaN(shapes.sphereT(k, ctx, tMin, tMax))) {
                return true;
            }
        }
        for (int k = 0; k < shapes.planeCount; k++) {
            double t = shapes.planeT(k, ctx);
            if (t > tMin && t < tMax) {
                return true;
            }
        }
        return false;
    }

    /** True when anything blocks the ray for {@code tMin < t < tMax} (any-hit query). */
    public boolean occluded(TraceContext ctx, double ox, double oy, double oz, double dx, double dy, double dz,
                            double tMin, double tMax) {
        return occluded(ctx, null, ox, oy, oz, dx, dy, dz, tMin, tMax);
    }

    /**
     * {@link #occluded(TraceContext, double, double, double, double, double, double, double, double)}
     * for a ray of {@code packet}: from the packet's leaves where {@link #gather} listed them for
     * this snapshot (the same answer), else by a traversal of its own.
     */
    public boolean occluded(TraceContext ctx, RayPacket packet, double ox, double oy, double oz,
                            double dx, double dy, double dz, double tMin, double tMax) {
        if (batches(packet)) {
            return occludedAlone(ctx, packet, null, null, 0, 0, 0, ox, oy, oz, dx, dy, dz, tMin, tMax);
        }
        ctx.ensureStack(accel.stackSize());
        ctx.setTraversal(ox, oy, oz, dx, dy, dz);
        ctx.tMin = tMin;
        ctx.anyHit = true;
        if (shapesBlock(ctx, tMin, tMax)) {
            return true;
        }
        leaves.beginRay(ctx);
        return accel.primCount() > 0
                && accel.occluded(ox, oy, oz, ctx.invDx, ctx.invDy, ctx.invDz, tMin, tMax, leaves, ctx, ctx.stack);
    }

    /**
     * {@link #occluded}, for a ray that leaves the surface at the patch hit {@code from}, whose
     * point is {@code at} and whose unit normal on the ray's side is {@code (nx, ny, nz)}: a
     * shadow ray. The answer is the same; the leaf that found the hit is skipped where {@link
     * OriginLeaf} proves that the ray cannot meet it, instead of searched.
     */
    public boolean occludedLeaving(TraceContext ctx, Hit from, SurfacePoint at, double nx, double ny, double nz,
                                   double ox, double oy, double oz, double dx, double dy, double dz,
                                   double tMin, double tMax) {
        return occludedLeaving(ctx, null, from, at, nx, ny, nz, ox, oy, oz, dx, dy, dz, tMin, tMax);
    }

    /** {@link #occludedLeaving} for a shadow ray of {@code packet} (see {@link #occluded(TraceContext, RayPacket, double, double, double, double, double, double, double, double)}). */
    public boolean occludedLeaving(TraceContext ctx, RayPacket packet, Hit from, SurfacePoint at,
                                   double nx, double ny, double nz, double ox, double oy, double oz,
                                   double dx, double dy, double dz, double tMin, double tMax) {
        if (batches(packet)) {
            return occludedAlone(ctx, packet, from, at, nx, ny, nz, ox, oy, oz, dx, dy, dz, tMin, tMax);
        }
        if (from.kind == Hit.PATCH) {
            ctx.leaving(from.subPatch, from.u, from.v, at, nx, ny, nz);
        }
        try {
            return occluded(ctx, null, ox, oy, oz, dx, dy, dz, tMin, tMax);
        } finally {
            ctx.originLeaf = -1;
        }
    }

    /** A single shadow ray of a gathered packet, leaving {@code from} (or nothing: null), as a batch of one. */
    private boolean occludedAlone(TraceContext ctx, RayPacket packet, Hit from, SurfacePoint at, double nx,
                                  double ny, double nz, double ox, double oy, double oz, double dx, double dy,
                                  double dz, double tMin, double tMax) {
        RayBatch batch = ctx.batch;
        double[] r = batch.oneRay, nrm = batch.oneNormal;
        r[0] = ox; r[1] = oy; r[2] = oz; r[3] = dx; r[4] = dy; r[5] = dz;
        nrm[0] = nx; nrm[1] = ny; nrm[2] = nz;
        batch.oneFrom[0] = from;
        batch.oneAt[0] = at;
        occludedLeaving(ctx, packet, r, 1, tMin, tMax, batch.oneFrom, batch.oneAt, nrm, batch.oneAnswer);
        return batch.oneAnswer[0];
    }

    /**
     * Evaluates the surface at a hit (position, dp/du, dp/dv, unit normal): for patch hits by the
     * leaves that found it ({@link Leaves#surfacePoint}: on the parent patch, or on the triangle
     * in tessellated mode). Call right after {@link #closestHit} with the same context (it uses
     * the context's ray and the solver's last evaluation).
     */
    public void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        sp.u = hit.u;
        sp.v = hit.v;
        sp.kind = hit.kind;
        sp.index = hit.index;
        if (hit.kind == Hit.PATCH || hit.kind == Hit.TRIANGLE || hit.kind == Hit.SPHERE && spheresInLeaves) {
            leaves.surfacePoint(ctx, hit, sp);
        } else if (hit.kind == Hit.PLANE) {
            shapes.planePoint(hit.index, hit, ctx, sp);
        } else {
            shapes.spherePoint(hit.index, hit, ctx, sp);
        }
    }

    /**
     * The curvature at a hit ({@link org.beziertracer.geometry.SurfaceCurvature} layout: K, H,
     * k1 ≥ k2 signed against the surface's own normal, the principal directions, that normal),
     * after {@link #surfacePoint} filled {@code sp} for it: exact on patches (second derivatives of
     * the parent patch), {@code −1/r} on a sphere of radius r, none on planes and triangles (mesh
     * triangles, and the tessellated mode's: a facet is flat, which is what a tessellation shows).
     */
    public void curvature(TraceContext ctx, Hit hit, SurfacePoint sp, double[] out) {
        if (hit.kind == Hit.SPHERE) {
            double r = scene.spheres().get(hit.index).radius();
            HitCurvature.umbilic(-1 / r, sp.nx, sp.ny, sp.nz, out);
        } else if (hit.kind == Hit.PLANE || !leaves.curvature(ctx, hit, out)) {
            HitCurvature.umbilic(0, sp.nx, sp.ny, sp.nz, out);
        }
    }

    public Scene scene() { return scene; }

    public IntersectOptions options() { return options; }

    /** Sub-patches in exact mode (whole patches with the BVH off). */
    public int subPatchCount() { return leaves.subPatchCount(); }

    /** Triangles in the BVH: of the tessellated mode and of the scene's meshes; 0 for exact patches alone. */
    public int triangleCount() { return leaves.triangleCount(); }

    /**
     * Primitives in the acceleration structure: sub-patches, or triangles in tessellated mode, and
     * the meshes' triangles and the spheres of a scene that holds them.
     */
    public int primitiveCount() { return accel.primCount(); }

    public int nodeCount() { return accel.nodeCount(); }

    /** Heap held by the leaves' data (sub-patch table or triangle mesh), in bytes. */
    public long leafBytes() { return leaves.bytes(); }

    /** Heap held by the acceleration structure's nodes (BVH or box list), in bytes. */
    public long accelBytes() { return accel.bytes(); }

    public int depth() { return accel.depth(); }

    public double buildMillis() { return buildMillis; }

    public double sceneSize() { return sceneSize; }
}
