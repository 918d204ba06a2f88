package org.beziertracer.app;

/**
 * The on/off settings of the toolbox (memoir annex 2 plus our extras), each with its value in a
 * fresh app. {@link Settings} holds the set of those that are on.
 */
public enum Toggle {
    /** The ray-traced picture; off: the wireframe view (overlay on a plain background). */
    RAY_TRACE(true),
    CONTROL_POLYGON(true),
    /** Control points drawn and pickable. */
    CONTROL_POINTS(true),
    /** Phong lighting; off: flat, unlit colour. */
    PHONG(true),
    /** Procedural checker in (u, v). */
    TEXTURE(false),
    /** Colour = (n + 1) / 2 of the unit normal (wins over Phong). */
    NORMALS(false),
    /** Iso-curves of the projected wireframe drawn over the ray-traced picture. */
    WIREFRAME(false),
    /** Several jittered samples per pixel ({@link Level#SAMPLES_PER_PIXEL}). */
    SUPER_SAMPLING(false),
    SHADOWS(true),
    /** Whitted reflection and refraction rays (depth 5; off: depth 0). */
    REFLECTIONS(true),
    /**
     * Render → Path Traced: the picture is path traced ({@link org.beziertracer.render.Integrator#PATH})
     * and keeps refining, one sample a pixel a pass, up to {@link Level#PATH_SAMPLES} or
     * {@link Level#PATH_SECONDS}; off: the Whitted renderer (the default). An analysis view wins.
     */
    PATH_TRACED(false),
    /** Pre-split patches in a sub-patch BVH; off: whole patches in a list. */
    BVH(true),
    /** Every patch as a uniform K×K triangle mesh ({@link Level#TESSELLATION}) instead of the exact surface. */
    TESSELLATED(false),
    /** "Keep tangent continuity": moving a point keeps the cross-border rows straight ({@link SmoothMove}). */
    SMOOTH_JOINS(false),
    /**
     * "Keep curvature continuity": moving a point keeps the cross-border rows C2 where they are, on
     * borders of degree 3 and more on both sides ({@link CurvatureJoins}); implies {@link #SMOOTH_JOINS}.
     */
    CURVATURE_JOINS(false),
    /** The light drawn as a marker in the view, where it can be dragged ({@link LightRig}). */
    SHOW_LIGHT(false),
    /**
     * View → Difference to clipping: the pixels where the selected method's primary-ray hit differs
     * from Bézier clipping's marked over the picture, their count in the status bar ({@link DifferenceModel}).
     */
    DIFFERENCE_TO_CLIPPING(false),
    /**
     * View → Continuity: every shared border certified G0/G1/G2 ({@link ContinuityModel}), listed
     * worst first in a panel and marked on the view (green G2, yellow G1, red G0 only or a gap).
     */
    CONTINUITY(false),
    /** The inspector panel: the selected points' patch, indices and coordinates, editable. */
    INSPECTOR(true);

    private final boolean initial;

    Toggle(boolean initial) { this.initial = initial; }

    /** On in a fresh app. */
    public boolean initial() { return initial; }
}
