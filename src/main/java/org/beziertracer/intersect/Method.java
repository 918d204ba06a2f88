package org.beziertracer.intersect;

import java.util.Locale;

import org.beziertracer.geometry.SplitOptions;

/** The ray–patch solvers, each with the {@link PatchLeaves} that run it at the BVH leaves. */
public enum Method {
    /** Bézier clipping (Nishita, Sederberg, Kakimoto 1990): exact, the default. */
    CLIPPING(ClippingLeaves::new, SplitOptions.defaults()),
    /**
     * Newton iteration from a start given by the leaf, on leaves refined until it converges from
     * there (memoir ch. I 3.3.3.3; Martin, Cohen, Fish, Shirley 2000): {@link NewtonSolver}.
     */
    NEWTON(NewtonLeaves::new, NewtonRefinement.SPLIT),
    /** Recursive subdivision, then the control mesh as triangles (memoir ch. I 3.3.3.1): approximate. */
    SUBDIVISION(SubdivisionLeaves::new, SplitOptions.defaults());

    /** Makes this method's leaves over a sub-patch table. */
    final PatchLeaves.Factory leaves;
    private final SplitOptions split;

    Method(PatchLeaves.Factory leaves, SplitOptions split) {
        this.leaves = leaves;
        this.split = split;
    }

    /** The pre-split this method's leaves want unless told otherwise. */
    public SplitOptions defaultSplit() { return split; }

    /** Parses {@code clipping|newton|subdivision} (case-insensitive) with a one-line error. */
    public static Method parse(String s) {
        for (Method m : values()) {
            if (m.name().equalsIgnoreCase(s.trim())) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown method '" + s + "': expected clipping, newton or subdivision");
    }

    public String label() { return name().toLowerCase(Locale.ROOT); }
}
