package org.beziertracer.ui;

import org.beziertracer.intersect.Method;
import org.beziertracer.model.RenderSettings;

/**
 * The toolbox state (memoir annex 2 plus our extras). Mutable and confined to the event thread;
 * the controller turns it into immutable {@link RenderSettings} for each render.
 */
public final class ToolSettings {

    /** Samples per pixel offered by the super-sampling control. */
    public static final int[] SPP_CHOICES = {4, 9, 16};
    /** Checker squares per unit of (u,v) when the texture is on. */
    public static final int CHECKER_SQUARES = 8;
    /** Cells per patch side offered by the tessellated mode (K×K cells, two triangles each). */
    public static final int[] TESSELLATION_CHOICES = {4, 8, 16, 32, 64};
    /**
     * Default K: the first offered choice whose teapot silhouette stays within 0.5 px of the exact
     * one at 800×600 (0.32 px; the smallest such K is 15; docs/performance.md, "Exact vs
     * tessellated at equal accuracy").
     */
    public static final int DEFAULT_TESSELLATION = 16;

    public boolean rayTrace = true;
    public boolean controlPolygon = true;
    public boolean controlPoints = true;
    public boolean phong = true;
    public boolean texture;
    public boolean normals;
    /** Iso-curves of the projected wireframe drawn over the ray-traced picture. */
    public boolean wireframeOverlay;
    /** Subdivisions per direction of the projected wireframe, 1..64. */
    public int wireframeSubdivision = 12;
    public boolean superSampling;
    public int samplesPerPixel = 4;
    /** Progressive passes per displayed frame, 1..8 (the memoir's interactivity). */
    public int interactivity = 1;
    /** 0 = orthographic .. 100 = strongest perspective. */
    public int perspective = 36;
    public Method method = Method.CLIPPING;
    public boolean bvh = true;
    /** Render a uniform {@link #tessellation}² triangle mesh per patch instead of the exact surface. */
    public boolean tessellated;
    /** K of the tessellated mode, one of {@link #TESSELLATION_CHOICES}. */
    public int tessellation = DEFAULT_TESSELLATION;
    public boolean shadows = true;
    public boolean reflections = true;
    public LightPlacement light = LightPlacement.SCENE;
    /** Control points of a new patch (Reset), 2..10 each way. */
    public int gridPointsU = 4;
    public int gridPointsV = 4;

    /** Horizontal field of view for the perspective slider position. */
    public double fovDegrees() {
        return perspective * OrbitView.MAX_FOV_DEGREES / 100.0;
    }

    /** Slider position of a field of view (inverse of {@link #fovDegrees()}). */
    public static int perspectiveOf(double fovDegrees) {
        return (int) Math.round(fovDegrees * 100 / OrbitView.MAX_FOV_DEGREES);
    }

    /** 0 (exact) or the K of the tessellated mode, for the render request. */
    public int tessellate() {
        return tessellated ? tessellation : 0;
    }

    /** What the status bar shows for the intersection: the method, or "tessellated K". */
    public String intersectionLabel() {
        return tessellated ? "tessellated " + tessellation : method.label();
    }

    /** Shading label for the renderer. */
    public String shading() {
        return normals ? "normals" : phong ? "phong" : "flat";
    }

    /** Takes over what a scene file sets: method, BVH, shading, checker, shadows, depth, samples. */
    public void apply(RenderSettings s) {
        method = Method.parse(s.method());
        bvh = s.bvh();
        normals = "normals".equals(s.shading());
        phong = !"flat".equals(s.shading());
        texture = s.checker() > 0;
        shadows = s.shadows();
        reflections = s.maxDepth() > 0;
        superSampling = s.spp() > 1;
        if (superSampling) {
            samplesPerPixel = s.spp() <= 4 ? 4 : s.spp() <= 9 ? 9 : 16;
        }
    }

    /** The renderer settings for a picture of {@code width × height} device pixels. */
    public RenderSettings renderSettings(int width, int height) {
        int spp = superSampling ? samplesPerPixel : 1;
        return new RenderSettings(width, height, spp, "jittered", method.label(), bvh, shading(),
                texture ? CHECKER_SQUARES : 0, shadows, reflections ? 5 : 0);
    }
}
