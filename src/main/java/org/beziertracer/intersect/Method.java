package org.beziertracer.intersect;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.model.BezierPatch;

/**
 * The ray–patch solvers, each with the {@link PatchLeaves} that run it at the BVH leaves. A
 * constant is all the rest of the program knows of a method: its leaves, its pre-split, the heap
 * its leaves keep beside the sub-patch table ({@link HeapBudget}), its name ({@link #label()}, what
 * scene files, the command line and the app say) and a line describing it. Everything that lists
 * or checks method names asks {@link #labels()} and {@link #parse}, so a new method is its leaves
 * class plus one constant here.
 */
public enum Method {
    /** Bézier clipping (Nishita, Sederberg, Kakimoto 1990): exact, the default. */
    CLIPPING(ClippingLeaves::new, ClippingLeaves::estimateBytes, SplitOptions.defaults(), true,
            "Bézier clipping: exact, the default"),
    /**
     * Newton iteration from a start given by the leaf, on leaves refined until it converges from
     * there (memoir ch. I 3.3.3.3; Martin, Cohen, Fish, Shirley 2000): {@link NewtonSolver}.
     */
    NEWTON(NewtonLeaves::new, NewtonLeaves::estimateBytes, NewtonRefinement.SPLIT, true,
            "Newton iteration from each leaf's start: exact, on finer leaves"),
    /** Recursive subdivision, then the control mesh as triangles (memoir ch. I 3.3.3.1): approximate. */
    SUBDIVISION(SubdivisionLeaves::new, SubdivisionLeaves::estimateBytes, SplitOptions.defaults(), false,
            "recursive subdivision, then the control mesh as triangles: approximate");

    /** About the bytes a method's leaves keep beside the sub-patch table, beyond the table itself. */
    @FunctionalInterface
    interface LeafBytes {
        /**
         * @param patches the scene's patches, split into
         * @param leaves  about this many leaves ({@link org.beziertracer.geometry.SubPatchTable#estimate})
         */
        long estimate(List<BezierPatch> patches, long leaves);
    }

    /** Makes this method's leaves over a sub-patch table. */
    final PatchLeaves.Factory leaves;
    private final LeafBytes leafBytes;
    private final SplitOptions split;
    private final String description;
    private final boolean exact;

    Method(PatchLeaves.Factory leaves, LeafBytes leafBytes, SplitOptions split, boolean exact, String description) {
        this.exact = exact;
        this.leaves = leaves;
        this.leafBytes = leafBytes;
        this.split = split;
        this.description = description;
    }

    /**
     * True when the hits are the patch's own roots, found to rounding whatever the leaves (so an
     * edit may keep a patch's old halvings, {@link SceneIntersector#withPatches}); false for an
     * approximate method, whose hits are its leaves' (then an edit splits the patch afresh, so a
     * dragged model is traced as a fresh build of it would be).
     */
    public boolean exact() { return exact; }

    /** The pre-split this method's leaves want unless told otherwise. */
    public SplitOptions defaultSplit() { return split; }

    /**
     * About the bytes this method's leaves keep for {@code leaves} leaves of {@code patches} beyond
     * the sub-patch table (per-leaf records and the like; 0 when they keep none): {@link HeapBudget}'s
     * share of the solver, estimated by the leaves class itself.
     */
    long solverBytes(List<BezierPatch> patches, long leaves) {
        return leafBytes.estimate(patches, leaves);
    }

    /** The name scene files, the command line and the app use: the constant's in lower case ({@code newton}). */
    public String label() { return name().toLowerCase(Locale.ROOT); }

    /** One line on what the method does, for help texts and tooltips. */
    public String description() { return description; }

    /** Every method's {@link #label()}, in declaration order. */
    public static List<String> labels() {
        return Arrays.stream(values()).map(Method::label).toList();
    }

    /** The labels as a sentence lists them: {@code clipping, newton or subdivision}. */
    public static String choices() {
        List<String> l = labels();
        return l.size() == 1 ? l.get(0)
                : String.join(", ", l.subList(0, l.size() - 1)) + " or " + l.get(l.size() - 1);
    }

    /**
     * Parses a {@link #label()} (any case, surrounding blanks ignored): where a method's name from a
     * scene file, the command line or the app becomes a method, and the one check of it.
     *
     * @throws IllegalArgumentException one line naming the allowed labels:
     *                                  {@code unknown method 'clip': expected clipping, newton or subdivision}
     */
    public static Method parse(String s) {
        String name = s == null ? "" : s;
        for (Method m : values()) {
            if (m.name().equalsIgnoreCase(name.trim())) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown method '" + name + "': expected " + choices());
    }
}
