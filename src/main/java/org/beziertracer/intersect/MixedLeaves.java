package org.beziertracer.intersect;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.accel.LaneIntersector;
import org.beziertracer.accel.LaneOccluder;
import org.beziertracer.model.Scene;

/**
 * Leaves of several kinds in one BVH: consecutive ranges of primitives, one per {@link LeafKind}
 * the scene holds, in the enum's order (the patches' sub-patches or tessellated triangles first,
 * then the meshes' triangles, then the spheres). Primitive {@code p} belongs to the part {@code j}
 * with {@code firstOf[j] <= p < firstOf[j+1]} and is handed to that part's leaves as its own
 * index {@code p - firstOf[j]}; a hit is completed and evaluated by the part its {@link Hit#kind}
 * names. The patch range starts at 0, so patch hits keep their sub-patch numbers (the shadow
 * query's origin leaf, {@link OriginLeaf}, means the same leaf).
 *
 * <p>Each part is called from its own call site ({@link #intersect(TraceContext, int, double)}
 * unrolls the first two), so each site sees one class of leaves and stays monomorphic. A batch
 * query ({@link SceneIntersector#closestHits}) hands a primitive to its part's lane method where it
 * has one ({@link PatchLeaves}); the other parts solve lane by lane ({@link RayBatch#load},
 * {@link RayBatch#store}), with the same answers as for each ray alone.
 *
 * <p>An edit of patches ({@link #withPatches}) remakes the patch part only; the mesh and sphere
 * parts are kept as they are (the same objects). Made only when a scene holds more than one
 * kind; a scene of patches only never sees this class. Immutable; shared by render threads.
 */
final class MixedLeaves implements Leaves, LaneIntersector<TraceContext>, LaneOccluder<TraceContext> {

    private final LeafKind[] kinds;
    private final Leaves[] parts;
    /** The first primitive of each part, then {@link #count()}. */
    private final int[] firstOf;
    /** Per {@link Hit#kind} (0..3) the part that makes such hits, or -1. */
    private final int[] partOfHit = {-1, -1, -1, -1};
    /** The part of {@link LeafKind#PATCHES}, or -1. */
    private final int patchPart;
    /** Each part's batch callbacks, or null (then lane by lane). */
    private final LaneIntersector<TraceContext>[] laneOf;
    private final LaneOccluder<TraceContext>[] anyLaneOf;
    /** The first two parts, each called from a call site of its own. */
    private final Leaves part0, part1;
    private final boolean spheres;

    @SuppressWarnings("unchecked")
    private MixedLeaves(LeafKind[] kinds, Leaves[] parts) {
        this.kinds = kinds;
        this.parts = parts;
        this.firstOf = new int[parts.length + 1];
        this.laneOf = new LaneIntersector[parts.length];
        this.anyLaneOf = new LaneOccluder[parts.length];
        int patch = -1;
        boolean holdsSpheres = false;
        for (int j = 0; j < parts.length; j++) {
            firstOf[j + 1] = firstOf[j] + parts[j].count();
            partOfHit[kinds[j].hitKind] = j;
            laneOf[j] = parts[j].lanes();
            anyLaneOf[j] = parts[j].anyLanes();
            holdsSpheres |= parts[j].holdsSpheres();
            if (kinds[j] == LeafKind.PATCHES) {
                patch = j;
            }
        }
        this.patchPart = patch;
        this.part0 = parts[0];
        this.part1 = parts.length > 1 ? parts[1] : parts[0];
        this.spheres = holdsSpheres;
    }

    /**
     * The leaves of every kind {@code scene} holds; the one kind's leaves alone when it holds one
     * ({@link LeafKind}).
     */
    static Leaves of(Scene scene, IntersectOptions options, double sceneSize) {
        List<LeafKind> kinds = new ArrayList<>();
        List<Leaves> parts = new ArrayList<>();
        for (LeafKind kind : LeafKind.values()) {
            Leaves leaves = kind.factory.build(scene, options, sceneSize);
            if (leaves != null) {
                kinds.add(kind);
                parts.add(leaves);
            }
        }
        if (parts.isEmpty()) {
            return Leaves.patchLeaves(scene, options, sceneSize);
        }
        if (parts.size() == 1) {
            return parts.get(0);
        }
        return new MixedLeaves(kinds.toArray(new LeafKind[0]), parts.toArray(new Leaves[0]));
    }

    /** The part primitive {@code prim} belongs to. */
    private int part(int prim) {
        int j = 0;
        while (prim >= firstOf[j + 1]) {
            j++;
        }
        return j;
    }

    @Override
    public void beginRay(TraceContext ctx) {
        for (Leaves p : parts) {
            p.beginRay(ctx);
        }
    }

    @Override
    public double intersect(TraceContext ctx, int prim, double tMax) {
        int j = part(prim);
        int local = prim - firstOf[j];
        switch (j) {
            case 0:
                return part0.intersect(ctx, local, tMax);
            case 1:
                return part1.intersect(ctx, local, tMax);
            default:
                return parts[j].intersect(ctx, local, tMax);
        }
    }

    @Override
    public boolean occludes(TraceContext ctx, int prim, double tMax) {
        int j = part(prim);
        int local = prim - firstOf[j];
        switch (j) {
            case 0:
                return part0.occludes(ctx, local, tMax);
            case 1:
                return part1.occludes(ctx, local, tMax);
            default:
                return parts[j].occludes(ctx, local, tMax);
        }
    }

    /**
     * The primitive's part's lane method where it has one; else each lane alone, its ray loaded into
     * the context ({@link RayBatch#loadRay}) and a nearer hit kept in its slots
     * ({@link RayBatch#recordBest}).
     */
    @Override
    public void intersect(TraceContext ctx, int prim, int[] lanes, int count, double[] tMax) {
        int j = part(prim);
        int local = prim - firstOf[j];
        LaneIntersector<TraceContext> batchLeaves = laneOf[j];
        if (batchLeaves != null) {
            batchLeaves.intersect(ctx, local, lanes, count, tMax);
            return;
        }
        Leaves leaves = parts[j];
        RayBatch batch = ctx.batch;
        for (int i = 0; i < count; i++) {
            int lane = lanes[i];
            batch.loadRay(ctx, lane);
            leaves.beginRay(ctx);
            double t = leaves.intersect(ctx, local, tMax[lane]);
            if (t < tMax[lane]) {
                tMax[lane] = t;
                batch.recordBest(ctx, lane);
            }
        }
    }

    /** As {@link #intersect(TraceContext, int, int[], int, double[])}, for shadow rays. */
    @Override
    public void occludes(TraceContext ctx, int prim, int[] lanes, int count, double[] tMax, boolean[] occluded) {
        int j = part(prim);
        int local = prim - firstOf[j];
        LaneOccluder<TraceContext> batchLeaves = anyLaneOf[j];
        if (batchLeaves != null) {
            batchLeaves.occludes(ctx, local, lanes, count, tMax, occluded);
            return;
        }
        Leaves leaves = parts[j];
        RayBatch batch = ctx.batch;
        for (int i = 0; i < count; i++) {
            int lane = lanes[i];
            batch.loadShadowRay(ctx, lane);
            leaves.beginRay(ctx);
            if (leaves.occludes(ctx, local, tMax[lane])) {
                occluded[lane] = true;
            }
        }
    }

    @Override
    public LaneIntersector<TraceContext> lanes() { return this; }

    @Override
    public LaneOccluder<TraceContext> anyLanes() { return this; }

    private Leaves partOf(Hit hit) {
        return parts[partOfHit[hit.kind]];
    }

    @Override
    public void completeHit(Hit hit) {
        partOf(hit).completeHit(hit);
    }

    @Override
    public void completeHit(TraceContext ctx, Hit hit) {
        partOf(hit).completeHit(ctx, hit);
    }

    @Override
    public boolean curvature(TraceContext ctx, Hit hit, double[] out) {
        return partOf(hit).curvature(ctx, hit, out);
    }

    @Override
    public void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        partOf(hit).surfacePoint(ctx, hit, sp);
    }

    @Override
    public boolean holdsSpheres() { return spheres; }

    @Override
    public Leaves withPatch(Scene edited, int index, double sceneSize) {
        if (patchPart < 0) {
            return this;
        }
        Leaves[] edit = parts.clone();
        edit[patchPart] = parts[patchPart].withPatch(edited, index, sceneSize);
        return new MixedLeaves(kinds, edit);
    }

    /** The patch part remade ({@link Leaves#withPatches}); the other parts kept. */
    @Override
    public Leaves withPatches(Scene edited, int[] indices, double sceneSize, boolean keepSplit) {
        if (patchPart < 0) {
            return this;
        }
        Leaves[] edit = parts.clone();
        edit[patchPart] = parts[patchPart].withPatches(edited, indices, sceneSize, keepSplit);
        return new MixedLeaves(kinds, edit);
    }

    @Override
    public boolean keepsUntouchedLeaves(Leaves before) {
        if (!(before instanceof MixedLeaves m) || m.parts.length != parts.length) {
            return false;
        }
        for (int j = 0; j < parts.length; j++) {
            boolean kept = j == patchPart ? parts[j].keepsUntouchedLeaves(m.parts[j]) : parts[j] == m.parts[j];
            if (!kept || m.firstOf[j] != firstOf[j]) {
                return false;
            }
        }
        return true;
    }

    @Override
    public long bytes() {
        long b = 0;
        for (Leaves p : parts) {
            b += p.bytes();
        }
        return b;
    }

    @Override
    public int count() { return firstOf[parts.length]; }

    @Override
    public double[] bounds(int first, int n) {
        double[] out = new double[6 * n];
        for (int j = 0; j < parts.length; j++) {
            int lo = Math.max(first, firstOf[j]), hi = Math.min(first + n, firstOf[j + 1]);
            if (lo < hi) {
                double[] b = parts[j].bounds(lo - firstOf[j], hi - lo);
                System.arraycopy(b, 0, out, 6 * (lo - first), b.length);
            }
        }
        return out;
    }

    @Override
    public int firstLeaf(int k) { return firstOf[patchPart] + parts[patchPart].firstLeaf(k); }

    @Override
    public int leafCount(int k) { return parts[patchPart].leafCount(k); }

    /** The patches' groups, then one group per other part. */
    @Override
    public int[] groupFirst(int patches) {
        int[] groups = new int[patches + parts.length + (patchPart >= 0 ? 0 : 1)];
        int g = 0;
        for (int j = 0; j < parts.length; j++) {
            if (j == patchPart) {
                for (int k = 0; k < patches; k++) {
                    groups[g++] = firstLeaf(k);
                }
            } else {
                groups[g++] = firstOf[j];
            }
        }
        groups[g++] = count();
        return java.util.Arrays.copyOf(groups, g);
    }

    @Override
    public int patchLeafCount() { return patchPart < 0 ? 0 : parts[patchPart].count(); }

    @Override
    public int subPatchCount() { return patchPart < 0 ? 0 : parts[patchPart].subPatchCount(); }

    @Override
    public int triangleCount() {
        int n = 0;
        for (Leaves p : parts) {
            n += p.triangleCount();
        }
        return n;
    }
}
