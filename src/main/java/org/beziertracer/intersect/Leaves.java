package org.beziertracer.intersect;

import org.beziertracer.accel.LeafIntersector;
import org.beziertracer.accel.LeafOccluder;
import org.beziertracer.model.Scene;

/**
 * The primitives in the acceleration structure's leaves, all of one kind, and how a ray meets one
 * of them: the seam between the scene queries of {@link SceneIntersector} and the ray–primitive
 * solvers. One implementation per kind of leaf:
 * <ul>
 *   <li>{@link PatchLeaves}: sub-patches of Bézier patches, one subclass per solver
 *       ({@link ClippingLeaves}, {@link NewtonLeaves}, {@link SubdivisionLeaves}; the
 *       {@link Method} names which);</li>
 *   <li>{@link TriangleLeaves}: the triangles of the tessellated mode;</li>
 *   <li>{@link MeshLeaves}: the triangles of the scene's meshes;</li>
 *   <li>{@link SphereLeaves}: the scene's spheres.</li>
 * </ul>
 * The leaves are chosen once, by {@link #of}, when a {@link SceneIntersector} is built: a scene
 * of patches only (and planes) gets its patch leaves alone, as it always did; a scene with meshes
 * or spheres gets one {@link LeafKind} per kind it holds, in consecutive ranges of one BVH
 * ({@link MixedLeaves}, or the one kind alone). Nothing on the per-ray path asks which kind it
 * is beyond the range a primitive falls in. A new solver is one {@link PatchLeaves} class and one
 * {@link Method} constant; a new kind of primitive is one {@code Leaves} class and one
 * {@link LeafKind} constant, not a new branch in the queries.
 *
 * <h2>Contract</h2>
 * A query runs, for one ray set in the caller's {@link TraceContext}: {@link #beginRay} once,
 * then the accelerator's per-primitive callbacks ({@link LeafIntersector#intersect} for a
 * closest hit, {@link LeafOccluder#occludes} for an any hit), with the context as the query
 * state. A closest-hit callback that finds a hit nearer than its {@code tMax} (and beyond
 * {@code ctx.tMin}) records it in {@code ctx.best} (its {@link Hit#kind}, the patch, mesh or sphere index, the
 * primitive, t and whatever it needs later), sets {@code ctx.found} and returns the hit's t. After
 * the traversal the winner goes once through {@link #completeHit}, and on demand through
 * {@link #surfacePoint}. Primitives are indexed {@code 0..count()-1} with the boxes of
 * {@link #bounds()}.
 *
 * <p>Implementations are immutable snapshots shared by every render thread; all per-ray state
 * lives in the context, and nothing is allocated per ray.
 */
interface Leaves extends LeafIntersector<TraceContext>, LeafOccluder<TraceContext> {

    /**
     * The leaves for {@code scene} under {@code options}: the triangles of the tessellated mode,
     * else the pre-split sub-patches solved by the chosen method.
     *
     * @param sceneSize the scene's size (control-box diagonal, 1 when empty), the scale of
     *                  solver tolerances
     */
    static Leaves of(Scene scene, IntersectOptions options, double sceneSize) {
        if (scene.meshes().isEmpty() && scene.spheres().isEmpty()) {
            return patchLeaves(scene, options, sceneSize);
        }
        return MixedLeaves.of(scene, options, sceneSize);
    }

    /** The patch leaves alone: the triangles of the tessellated mode, else the pre-split sub-patches. */
    static Leaves patchLeaves(Scene scene, IntersectOptions options, double sceneSize) {
        if (options.tessellated() && !scene.patches().isEmpty()) {
            return TriangleLeaves.build(scene, options.tessellate());
        }
        return PatchLeaves.build(scene, options, sceneSize);
    }

    /** Number of primitives. */
    int count();

    /**
     * The boxes of primitives {@code first .. first+n-1}, {@code minX minY minZ maxX maxY maxZ}
     * each, in an array the caller may keep (for an accelerator build or refit).
     */
    double[] bounds(int first, int n);

    /** The primitives of patch {@code k}: {@code firstLeaf(k) .. firstLeaf(k)+leafCount(k)-1}. */
    int firstLeaf(int k);

    /** Number of primitives of patch {@code k}. */
    int leafCount(int k);

    /** Per-ray set-up after {@link TraceContext#setRay}, before the traversal; nothing by default. */
    default void beginRay(TraceContext ctx) {}

    /** Completes the winning hit of a closest-hit query (fields its leaves left out); nothing by default. */
    default void completeHit(Hit hit) {}

    /**
     * {@link #completeHit(Hit)}, with the query's context (its ray) for leaves that need it; the
     * queries call this one.
     */
    default void completeHit(TraceContext ctx, Hit hit) {
        completeHit(hit);
    }

    /**
     * The curvature at a hit of these leaves ({@link org.beziertracer.geometry.SurfaceCurvature}
     * layout, signed against the surface's own normal) into {@code out}; false when these leaves
     * have no curvature to give (flat triangles), and the caller reports a flat point.
     */
    default boolean curvature(TraceContext ctx, Hit hit, double[] out) { return false; }

    /** True when the scene's spheres are among these leaves (then the queries do not test them apart). */
    default boolean holdsSpheres() { return false; }

    /** These leaves as the callback of a batch query ({@link SceneIntersector#closestHits}), or null. */
    default org.beziertracer.accel.LaneIntersector<TraceContext> lanes() { return null; }

    /**
     * The batch callback for shadow rays ({@link org.beziertracer.accel.LaneOccluder}), or null when
     * these leaves solve no lanes (then a batch's rays are traced one at a time); given with
     * {@link #lanes()}.
     */
    default org.beziertracer.accel.LaneOccluder<TraceContext> anyLanes() { return null; }

    /**
     * The groups of a two-level build ({@link org.beziertracer.accel.Bvh#build(double[], int, int[],
     * org.beziertracer.accel.BvhOptions)}): the first leaf of each of the {@code patches} patches,
     * then of any further group, then {@link #count()}.
     */
    default int[] groupFirst(int patches) {
        int[] groupFirst = new int[patches + 1];
        for (int k = 0; k < patches; k++) {
            groupFirst[k] = firstLeaf(k);
        }
        groupFirst[patches] = count();
        return groupFirst;
    }

    /** The leaves that belong to patches (all of them, unless other kinds share the BVH). */
    default int patchLeafCount() { return count(); }

    /**
     * The geometry at {@code hit}, one of these leaves' hits: position, dp/du, dp/dv and the unit
     * normal into {@code sp}. Called right after the closest-hit query that found it, with the
     * same context. The caller fills {@code sp.u, v, kind, index}.
     */
    void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp);

    /**
     * The same kind of leaves after patch {@code index} of the scene was replaced ({@code edited}
     * is the new scene). Primitive indices stay comparable when {@link #count()} is unchanged, so
     * the accelerator may then be refitted instead of rebuilt.
     */
    Leaves withPatch(Scene edited, int index, double sceneSize);

    /**
     * {@link #withPatch} for several patches at once ({@code edited} differs from the old scene in
     * patches {@code indices} only): the data is remade once, not once per patch. With
     * {@code keepSplit}, leaves that subdivide a patch may keep its old subdivision where it still
     * fits (a drag then usually keeps {@link #count()}); without, the edited patches are made as a
     * fresh build makes them.
     */
    Leaves withPatches(Scene edited, int[] indices, double sceneSize, boolean keepSplit);

    /**
     * True when these leaves, made by {@link #withPatches} from {@code before}, are
     * {@code before}'s leaves for every patch the edit did not touch, in the same order, so that
     * refitting the edited patches' range of the accelerator suffices (when {@link #count()} is
     * unchanged).
     */
    boolean keepsUntouchedLeaves(Leaves before);

    /** Heap held by these leaves' data (not the model's patches), in bytes. */
    long bytes();

    /** Sub-patches (BVH leaves) of the exact mode; the number of whole patches for other kinds. */
    int subPatchCount();

    /** Triangles of the tessellated mode; 0 for other kinds. */
    default int triangleCount() { return 0; }
}
