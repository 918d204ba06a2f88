package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.TrimCurves;
import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;

/**
 * Per-thread scratch for ray queries: the current ray and its ray-space frame, the BVH stack,
 * the arena of clipping sub-nets, the solver's result and the best hit so far. It belongs to no
 * scene: one context serves any {@link SceneIntersector} (a render thread keeps its context
 * across edits), and the scene's {@link Leaves} receive it as the accelerator's query state.
 * Create one per render thread with {@link SceneIntersector#newContext()}; never share one
 * between threads. Nothing here is allocated per ray.
 *
 * <h2>Ray space</h2>
 * The ray {@code o + t d} is written as the intersection of two planes through {@code o} with
 * unit normals {@code n1}, {@code n2} perpendicular to {@code d} and to each other (Nishita,
 * Sederberg, Kakimoto 1990). A point {@code P} maps to {@code (n1·(P−o), n2·(P−o), d̂·(P−o))}:
 * the ray is the third axis, and a surface point lies on the ray exactly when its first two
 * coordinates vanish. The map is affine, so a control net maps to the control net of the
 * transformed surface.
 */
public final class TraceContext {

    /** Most sub-nets the clipping and subdivision stacks hold. */
    static final int MAX_ENTRIES = 64;
    static final int NET_LENGTH = DeCasteljau.MAX_ORDER * DeCasteljau.MAX_ORDER * 3;

    // The ray and its frame
    double ox, oy, oz, dx, dy, dz;
    double invDx, invDy, invDz;
    double n1x, n1y, n1z, n2x, n2y, n2z, n3x, n3y, n3z;
    /** 1/|d|: converts the third ray-space coordinate (a distance) into the ray parameter t. */
    double invLength;
    /** True when {@code n1, n2, n3} and {@link #invLength} are the current ray's ({@link #setTraversal}). */
    boolean planesSet;

    // Tessellated mode: the watertight triangle test's per-ray permutation and shear (TriangleMesh.setRay)
    int kx, ky, kz;
    double shearX, shearY, shearZ;
    double permOx, permOy, permOz;

    // Scratch owned by this thread
    /** BVH traversal stack; grown (rarely, outside the per-ray loop) when a deeper BVH arrives. */
    int[] stack = new int[256];
    final double[] arena = new double[MAX_ENTRIES * NET_LENGTH];
    /** The weights of the arena's nets, for rational leaves ({@link RationalNets}); same slots. */
    final double[] weightArena = new double[MAX_ENTRIES * RationalNets.WEIGHT_SLOT];
    /** Scratch of the trim test ({@link TrimmedLeaves}). */
    final double[] trimScratch = new double[TrimCurves.SCRATCH_LENGTH];
    final double[] entryBoxes = new double[MAX_ENTRIES * 4];
    final int[] entryDepth = new int[MAX_ENTRIES];
    final double[] tmpNet = new double[NET_LENGTH];
    final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
    /** Scratch of {@link SceneIntersector#curvature} (second derivatives at a hit). */
    final double[] curvatureScratch = new double[org.beziertracer.geometry.SurfaceCurvature.SCRATCH];
    final double[] eval = new double[9];
    final double[] refineEval = new double[9];
    /** {@link #eval} holds S, Su, Sv of patch {@code evalPatch} at {@code (evalU, evalV)} (-1: unknown). */
    int evalPatch = -1;
    double evalU, evalV;
    /**
     * S, Su, Sv of the best patch hit so far, at {@code (hitEvalU, hitEvalV)} of patch
     * {@code hitEvalPatch} (-1: none), copied from the solver's last evaluation so that
     * {@link PatchLeaves#surfacePoint} need not evaluate the same point again.
     */
    final double[] hitEval = new double[9];
    int hitEvalPatch = -1;
    double hitEvalU, hitEvalV;
    /** Pieces of a leaf's border curves in ray space ({@link BoundaryWinding}), and their depths. */
    final double[] curveStack = new double[2 * DeCasteljau.MAX_ORDER * (BoundaryWinding.MAX_DEPTH + 2)];
    final int[] curveDepth = new int[BoundaryWinding.MAX_DEPTH + 2];
    final double[] normal = new double[3];
    final double[] columnMin = new double[DeCasteljau.MAX_ORDER];
    final double[] columnMax = new double[DeCasteljau.MAX_ORDER];
    final double[] clip = new double[2];
    final double[] rayBounds = new double[6];
    /** First two ray-space coordinates of a net's corners (u,v) = (0,0), (1,0), (0,1), (1,1). */
    final double[] corners = new double[8];
    /** {@link NewtonSolver}'s attempt limits: the leaf's overlapped domain, the t range, a root to avoid. */
    final double[] newton = new double[NewtonSolver.SCRATCH];
    /** A leaf quarter's record in the making ({@link LeafQuarters}). */
    final double[] quarterFrame = new double[NewtonLeafRecords.STRIDE];

    // The query in flight (set by SceneIntersector)
    double tMin;
    /** Best patch hit of the current closest-hit query. */
    final Hit best = new Hit();
    boolean found;
    /** The query in progress is an any-hit one ({@link SceneIntersector#occluded}): any root in range answers it. */
    boolean anyHit;

    // Root found by the last solver call, in the parent patch's parameters
    double rootT, rootU, rootV;
    /** Tessellated mode: barycentric weights of the hit triangle's second and third corner. */
    double rootB1, rootB2;

    /**
     * A single-root leaf whose Newton solve {@link BezierClipper#begin} left for next: its start
     * (leaf parameters) and what {@link BezierClipper#afterNewton} needs to know of the leaf.
     */
    double pendingSu, pendingSv;
    boolean pendingOwn, pendingWindingFirst, pendingPolynomial;

    // A solver's search over the pieces of one leaf (BezierClipper, SubdivisionSolver): the
    // nearest root so far, in the solver's own parameters
    double pieceBestT, pieceBestU, pieceBestV;
    boolean pieceFound;
    /** Bézier clipping: Newton attempts on single-root pieces of the leaf so far. */
    int clipNewtonTries;
    /** Bézier clipping: the leaf is rational (its arena nets are weighted, {@link RationalNets}). */
    boolean leafRational;
    /** The iterate with which the last diverged Newton solve left its box. */
    double escapeU, escapeV;
    /** Newton: the residuals (distances to the ray's two planes) at the last evaluated iterate. */
    double residual1, residual2;

    /**
     * The surface point an any-hit query leaves ({@link SceneIntersector#occludedLeaving}): the
     * leaf whose solve found it ({@code -1}: none), the surface's (u, v) there, the point and the
     * unit normal on the ray's side ({@link OriginLeaf}); and that test's scratch.
     */
    int originLeaf = -1;
    double originU, originV, originPx, originPy, originPz, originNx, originNy, originNz;
    /**
     * The surface's derivatives at the origin's point (as {@link SurfacePoint} has them: with
     * respect to the surface's parameters), which with the point are the patch's own evaluation
     * there when the patch's domain is the unit square ({@link RayPatchNewton} starts from it).
     */
    double originSux, originSuy, originSuz, originSvx, originSvy, originSvz;
    /** True when the origin* derivatives belong to the current origin. */
    boolean originDerivatives;
    final double[] originScratch = new double[OriginLeaf.SCRATCH];
    /** Per slot {@code s & (MEMORY-1)}: {@code s + 1} when leaf s's last {@link OriginLeaf} test failed, and rays since. */
    final int[] originFailed = new int[OriginLeaf.MEMORY], originSkipped = new int[OriginLeaf.MEMORY];

    /** Counters for statistics (not reset by queries). */
    public long solverCalls, clipIterations;
    /**
     * Evaluations of a patch with its first derivatives that the solvers and the surface point made
     * (Newton's iterates, their refinement, a hit's point when no iterate stood there): with the
     * counters above, the work of a frame, which repeats exactly where times do not.
     */
    public long evaluations;
    /**
     * Of those, the evaluations made for several lanes of a ray batch together ({@link NewtonLanes},
     * in SIMD registers with the vector kernel).
     */
    public long laneEvaluations;
    /** Any-hit queries that Newton answered on a leaf that may hold several roots ({@link BezierClipper}). */
    long anyRootsByNewton;
    /** Quarters of a shadow ray's own leaf cleared by {@link OriginRoot} ({@link LeafQuarters}). */
    long originQuarters;
    /** Any-hit Newton attempts not made on the ray's own leaf, their start near its origin ({@link OriginLeaf#awayFromOrigin}). */
    long nearOriginStarts;
    /** Single-root leaves the winding test settled before Newton ran (the model's start outside the leaf). */
    long besideFirst;
    /** Quarters of a leaf whose Newton attempt failed and the winding of their border was asked ({@link LeafQuarters}). */
    long quarterWindings;
    /** Leaves whose record rejected the ray, no evaluation made ({@link NewtonSolver#start} returning MISS). */
    long recordMisses;
    /** Leaves the ray misses by their {@link LeafSlabs} ({@code BezierClipper.beside}). */
    long slabMisses;
    /** Single-root leaves the winding of their border proved empty ({@code BezierClipper.holdsNoRoot}). */
    long windingMisses;
    /** Newton starts where the ray meets the leaf's quadratic model ({@link LeafQuadratics#start} true). */
    long quadraticStarts;
    /** Leaves proven single-root for the ray before any search (by the record or {@link RootUniqueness}). */
    long singleRootLeaves;
    /** Leaves {@link LeafQuarters} settled (a miss or a root) before any clipping. */
    long quarterLeaves;
    /** Newton's last steps taken without an evaluation ({@link RayPatchNewton#extrapolate} true). */
    long extrapolations;
    /** A shadow ray's own leaves proven to hold only the origin's point, behind it ({@link OriginRoot#behind}). */
    long originBehind;
    /** Leaves of the patch a shadow ray leaves skipped as provably behind it ({@link OriginLeaf#cannotMeet}). */
    long originCannotMeet;
    /** Newton starts on a shadow ray's own leaf at the origin's point ({@link OriginLeaf#startAtOrigin}). */
    long originStarts;
    /** Newton's first evaluations taken from the origin's point ({@code RayPatchNewton.fromOrigin}). */
    long originEvaluations;
    /** Surface points at a hit made from the solver's last evaluation ({@link PatchLeaves#surfacePoint}). */
    long hitEvaluations;

    /** The kernel that evaluates a batch's lanes together ({@link NewtonLanes}). */
    final LaneKernel kernel;
    /** The ray batch in flight ({@link SceneIntersector#closestHits}) and its Newton lanes. */
    final RayBatch batch = new RayBatch();
    final NewtonLanes newtonLanes = new NewtonLanes();

    TraceContext() {
        this(Kernels.best());
    }

    TraceContext(LaneKernel kernel) {
        this.kernel = kernel;
    }

    /**
     * The work counters of the shortcuts (those above besides the public ones, and the lanes'
     * {@link NewtonLanes#extrapolations}) by name, cumulative over this context's life: tests pin
     * the work of fixed frames by them (each shortcut only saves work, never changes an answer).
     */
    public java.util.Map<String, Long> shortcutCounts() {
        java.util.Map<String, Long> m = new java.util.LinkedHashMap<>();
        m.put("recordMisses", recordMisses);
        m.put("slabMisses", slabMisses);
        m.put("windingMisses", windingMisses);
        m.put("quadraticStarts", quadraticStarts);
        m.put("besideFirst", besideFirst);
        m.put("singleRootLeaves", singleRootLeaves);
        m.put("quarterLeaves", quarterLeaves);
        m.put("quarterWindings", quarterWindings);
        m.put("extrapolations", extrapolations);
        m.put("laneExtrapolations", newtonLanes.extrapolations);
        m.put("originBehind", originBehind);
        m.put("originQuarters", originQuarters);
        m.put("originCannotMeet", originCannotMeet);
        m.put("originStarts", originStarts);
        m.put("nearOriginStarts", nearOriginStarts);
        m.put("anyRootsByNewton", anyRootsByNewton);
        m.put("originEvaluations", originEvaluations);
        m.put("hitEvaluations", hitEvaluations);
        return m;
    }

    /** Squared direction lengths strictly between these take {@link #setRay}'s unscaled path. */
    static final double SQUARES_FROM = 1e-280, SQUARES_TO = 1e280;

    /**
     * Sets the ray and computes its ray-space frame. {@code d} must be finite and non-zero; its
     * length may be anything from about 1e-300 to 1e300.
     */
    void setRay(double ox, double oy, double oz, double dx, double dy, double dz) {
        setTraversal(ox, oy, oz, dx, dy, dz);
        planes();
    }

    /**
     * The ray {@code o + t·d} for a traversal: origin, direction and reciprocals only. Its frame
     * ({@code n1, n2, n3}, {@link #invLength}) is made by {@link #ensurePlanes} when a patch leaf
     * first needs it: most rays (those that miss every leaf box, every ray of the tessellated mode)
     * never do, and the frame costs two square roots and two divisions.
     */
    void setTraversal(double ox, double oy, double oz, double dx, double dy, double dz) {
        this.ox = ox; this.oy = oy; this.oz = oz;
        this.dx = dx; this.dy = dy; this.dz = dz;
        invDx = 1.0 / dx; invDy = 1.0 / dy; invDz = 1.0 / dz;
        planesSet = false;
    }

    /** Makes the current ray's frame unless it is made already (see {@link #setTraversal}). */
    void ensurePlanes() {
        if (!planesSet) {
            planes();
        }
    }

    /** The ray's frame: {@code n3} along d, {@code n1}, {@code n2} across it, and {@link #invLength}. */
    private void planes() {
        planesSet = true;
        double squared = dx * dx + dy * dy + dz * dz;
        if (squared > SQUARES_FROM && squared < SQUARES_TO) {
            // the usual direction: its squared length neither underflows nor overflows, so one
            // square root and one division; n1's, from d itself, does not wait for it
            double inv = 1.0 / Math.sqrt(squared);
            invLength = inv;
            n3x = dx * inv; n3y = dy * inv; n3z = dz * inv;
            across(dx, dy, dz);
        } else {
            // scale by the largest component first, so tiny or huge directions neither underflow nor overflow
            double big = Math.max(Math.abs(dx), Math.max(Math.abs(dy), Math.abs(dz)));
            double sx = dx / big, sy = dy / big, sz = dz / big;
            double scaledLength = Math.sqrt(sx * sx + sy * sy + sz * sz);
            invLength = 1.0 / (scaledLength * big);
            n3x = sx / scaledLength; n3y = sy / scaledLength; n3z = sz / scaledLength;
            across(sx, sy, sz);
        }
        // n2 = d̂ × n1
        n2x = n3y * n1z - n3z * n1y;
        n2y = n3z * n1x - n3x * n1z;
        n2z = n3x * n1y - n3y * n1x;
    }

    /**
     * n1: the unit vector across {@code (x, y, z)} (a multiple of d whose squares neither
     * underflow nor overflow) built from its two largest components, whose squares are at least a
     * third of its own.
     */
    private void across(double x, double y, double z) {
        double ax, ay, az;
        if (Math.abs(x) > Math.abs(z)) {
            ax = -y; ay = x; az = 0;
        } else {
            ax = 0; ay = -z; az = y;
        }
        double inv = 1.0 / Math.sqrt(ax * ax + ay * ay + az * az);
        n1x = ax * inv; n1y = ay * inv; n1z = az * inv;
    }

    /**
     * The next any-hit query leaves the surface point {@code at} found in leaf {@code leaf} at the
     * surface's {@code (u, v)}, on the side of the unit normal {@code n}: as the other {@code
     * leaving}, and the point's derivatives are kept too.
     */
    void leaving(int leaf, double u, double v, SurfacePoint at, double nx, double ny, double nz) {
        leaving(leaf, u, v, at.px, at.py, at.pz, nx, ny, nz);
        originSux = at.dpdux; originSuy = at.dpduy; originSuz = at.dpduz;
        originSvx = at.dpdvx; originSvy = at.dpdvy; originSvz = at.dpdvz;
        originDerivatives = true;
    }

    /**
     * The next any-hit query leaves the surface point {@code (px, py, pz)} found in leaf
     * {@code leaf} at the surface's {@code (u, v)}, on the side of the unit normal {@code n}
     * ({@link OriginLeaf}); {@code leaf = -1}: it leaves none.
     */
    void leaving(int leaf, double u, double v, double px, double py, double pz, double nx, double ny, double nz) {
        originLeaf = leaf;
        originDerivatives = false;
        originU = u;
        originV = v;
        originPx = px;
        originPy = py;
        originPz = pz;
        originNx = nx;
        originNy = ny;
        originNz = nz;
    }

    /** Grows the traversal stack to at least {@code size} (a deeper BVH than any before). */
    void ensureStack(int size) {
        if (stack.length < size) {
            stack = new int[size];
        }
    }

    /** Starts a closest-hit query: no hit yet. */
    /**
     * Forgets what earlier queries left behind that could change the work of later ones (never
     * their answers): {@link OriginLeaf}'s memory of failed proofs and the last evaluations kept
     * for reuse. A context reused for another render then works as a new one would (the render's
     * work counts repeat to the unit on one thread).
     */
    public void forgetHistory() {
        java.util.Arrays.fill(originFailed, 0);
        java.util.Arrays.fill(originSkipped, 0);
        evalPatch = -1;
        hitEvalPatch = -1;
        originLeaf = -1;
    }

    void beginClosestHit(double tMin) {
        this.tMin = tMin;
        anyHit = false;
        found = false;
        hitEvalPatch = -1;
    }

    /**
     * Records the last root ({@link #rootT}) as the best hit so far, on primitive {@code prim} of
     * patch {@code patch}; the caller adds the parameters its kind of leaf keeps.
     */
    void recordHit(int patch, int prim) {
        found = true;
        best.t = rootT;
        best.kind = Hit.PATCH;
        best.index = patch;
        best.subPatch = prim;
        best.b1 = 0;                                        // only triangles have barycentrics
        best.b2 = 0;
    }

    /** {@link #recordHit(int, int)} for a primitive of another kind ({@link Hit#kind}) and its {@code index}. */
    void recordHit(int kind, int index, int prim) {
        found = true;
        best.t = rootT;
        best.kind = kind;
        best.index = index;
        best.subPatch = prim;
        best.b1 = 0;
        best.b2 = 0;
    }

    /**
     * Keeps the solver's last evaluation ({@link #eval}, at {@code (evalU, evalV)} of patch
     * {@code evalPatch}) as the evaluation at the best hit.
     */
    void keepEvaluationForHit() {
        System.arraycopy(eval, 0, hitEval, 0, 9);
        hitEvalPatch = evalPatch;
        hitEvalU = evalU;
        hitEvalV = evalV;
    }

    /** Maps {@code count} points from {@code src[srcOff..]} into ray space at {@code dest[destOff..]}. */
    void project(double[] src, int srcOff, int count, double[] dest, int destOff) {
        for (int k = 0, s = srcOff, d = destOff; k < count; k++, s += 3, d += 3) {
            double qx = src[s] - ox, qy = src[s + 1] - oy, qz = src[s + 2] - oz;
            dest[d] = n1x * qx + n1y * qy + n1z * qz;
            dest[d + 1] = n2x * qx + n2y * qy + n2z * qz;
            dest[d + 2] = n3x * qx + n3y * qy + n3z * qz;
        }
    }

    /**
     * Writes the first two ray-space coordinates of the four corner points of the degree
     * {@code n}×{@code m} net at {@code net[off..]} to {@code out[0..8)}, in the order
     * {@code P00, Pn0, P0m, Pnm}.
     */
    void projectCorners(double[] net, int off, int n, int m, double[] out) {
        int row = 3 * (n + 1);
        projectXY(net, off, out, 0);
        projectXY(net, off + 3 * n, out, 2);
        projectXY(net, off + row * m, out, 4);
        projectXY(net, off + row * m + 3 * n, out, 6);
    }

    private void projectXY(double[] src, int s, double[] out, int o) {
        double qx = src[s] - ox, qy = src[s + 1] - oy, qz = src[s + 2] - oz;
        out[o] = n1x * qx + n1y * qy + n1z * qz;
        out[o + 1] = n2x * qx + n2y * qy + n2z * qz;
    }
}
