package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.model.AreaLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;
import org.beziertracer.model.io.BuiltIns;
import org.beziertracer.model.io.SceneDocument;
import org.junit.jupiter.api.Test;

/** The built-in studio scene: what it holds, and a small path-traced render of it without NaN and neither black nor white. */
class StudioSceneTest {

    @Test
    void theStudioHoldsAGoldTeapotAGlassTeacupAFloorOneRectLightAndAPlainSky() {
        Scene s = BuiltIns.find("studio").orElseThrow().load().scene();
        assertEquals(32 + 26, s.patchCount(), "teapot and teacup");
        assertEquals(1, s.planes().size(), "the floor");
        assertEquals(1, s.areaLights().size());
        assertEquals(AreaLight.Shape.RECT, s.areaLights().get(0).shape());
        assertTrue(s.lights().isEmpty() && s.spotLights().isEmpty(), "no point light");
        assertTrue(s.environment().isPresent() && s.environment().get().picture() == null, "a constant sky, no HDR image");
        assertEquals(Surface.Kind.CONDUCTOR, s.surfaceOrPhong(s.patchMaterial(0)).kind(), "the teapot is metal");
        assertEquals(Surface.Kind.DIELECTRIC, s.surfaceOrPhong(s.patchMaterial(32)).kind(), "the cup is glass");
        assertEquals(Surface.Kind.DIFFUSE, s.surfaceOrPhong(s.planes().get(0).material()).kind());
    }

    @Test
    void aSmallPathTracedRenderHasNoNanAndASensibleMeanLuminance() throws InterruptedException {
        SceneDocument doc = BuiltIns.find("studio").orElseThrow().load();
        RenderSettings s = doc.settings();
        RenderSettings small = new RenderSettings(80, 60, 4, s.sampler(), s.method(), s.bvh(), s.shading(), s.checker(),
                s.shadows(), s.maxDepth());
        RenderOptions o = RenderOptions.defaults().withThreads(2).withProgressive(false)
                .withPath(PathOptions.defaults().withIntegrator(Integrator.PATH));
        RenderResult r = Renderer.renderOnce(RenderJob.prepare(doc.scene(), small, o));
        float[] rgb = r.film().linearRgb();
        double sum = 0;
        int bad = 0;
        for (int p = 0; p < rgb.length; p += 3) {
            if (!(Float.isFinite(rgb[p]) && Float.isFinite(rgb[p + 1]) && Float.isFinite(rgb[p + 2]))) {
                bad++;
                continue;
            }
            sum += 0.2126 * rgb[p] + 0.7152 * rgb[p + 1] + 0.0722 * rgb[p + 2];
        }
        assertEquals(0, bad, "pixels with NaN or infinity");
        double mean = sum / (rgb.length / 3);
        // The floor lit by the sky (0.27) and the light (about 11 over 0.25 sr): about 0.3 to 0.6
        assertTrue(mean > 0.15 && mean < 1.5, "mean linear luminance " + mean);
        int[] argb = ToneMap.argb(r.film(), 0);
        int dark = 0, white = 0;
        for (int c : argb) {
            int g = (c >> 8) & 0xFF;
            dark += g < 10 ? 1 : 0;
            white += g > 250 ? 1 : 0;
        }
        assertTrue(dark < argb.length / 50 && white < argb.length / 20, "tone mapped: " + dark + " black, " + white
                + " white pixels of " + argb.length);
    }
}
