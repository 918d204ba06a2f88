package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.beziertracer.model.io.SceneDocument;
import org.junit.jupiter.api.Test;

/** The first look: the light above left of the eye, at the eye one preset away, shown and dragged in the view. */
class LightTest {

    private final FakeEngine engine = new FakeEngine();
    private final AppModel app = new AppModel(engine, new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());

    LightTest() {
        app.view().resize(800, 600, 1);
    }

    private RenderRequest last() { return engine.requests.get(engine.requests.size() - 1); }

    @Test
    void theDefaultLightFollowsTheViewAndAtTheEyeIsOnePresetAway() {
        Vec3 light = last().lights().get(0).position();
        app.view().rotate(120, 40);
        CameraSpec cam = last().camera();
        Vec3 turned = last().lights().get(0).position();
        assertNotEquals(light, turned, "the light turned with the view");
        Vec3 rel = LightRig.offsetOf(LightPlacement.EYE_ABOVE_LEFT, turned, cam, app.view().view().framing());
        assertEquals(LightPlacement.EYE_ABOVE_LEFT.preset().x(), rel.x(), 1e-9, "still above left of the eye");
        assertEquals(LightPlacement.EYE_ABOVE_LEFT.preset().y(), rel.y(), 1e-9);
        app.settings().cycleLight();
        assertEquals(LightPlacement.AT_EYE, app.settings().current().light(), "one preset away");
        assertEquals(last().camera().eye(), last().lights().get(0).position());
    }

    @Test
    void aLightThatMovesNeedsNoNewSnapshotOnlyNewLights() {
        RenderRequest a = last();
        app.view().rotate(30, 0);
        RenderRequest b = last();
        assertEquals(a.scene(), b.scene(), "the scene handed to the engine is the same: its snapshot is reused");
        assertNotEquals(a.lights(), b.lights());
    }

    @Test
    void showLightDrawsAMarkerThatDragsTheLight() {
        assertEquals(List.of(), app.overlay().snapshot().lights());
        app.settings().toggle(Toggle.SHOW_LIGHT);
        List<LightMarker> markers = app.overlay().snapshot().lights();
        assertEquals(1, markers.size());
        LightMarker m = markers.get(0);
        assertTrue(m.inside(), "the default light shows inside the default view: " + m);
        assertTrue(m.x() < 400 && m.y() < 300, "above left: " + m);
        for (int[] size : new int[][] {{430, 535}, {1100, 600}, {600, 900}}) {
            app.view().resize(size[0], size[1], 1);
            LightMarker other = app.overlay().snapshot().lights().get(0);
            assertTrue(other.inside() && other.x() < size[0] / 2.0 && other.y() < size[1] / 2.0,
                    "inside and above left in a " + size[0] + "×" + size[1] + " picture too: " + other);
        }
        app.view().resize(800, 600, 1);
        m = app.overlay().snapshot().lights().get(0);
        Vec3 before = last().lights().get(0).position();
        app.pointer().pressed(m.x(), m.y(), Modifiers.NONE);
        app.pointer().dragged(m.x() + 100, m.y() + 50);
        app.pointer().released(m.x() + 100, m.y() + 50);
        LightMarker moved = app.overlay().snapshot().lights().get(0);
        assertEquals(m.x() + 100, moved.x(), 1e-6, "the marker followed the mouse");
        assertEquals(m.y() + 50, moved.y(), 1e-6);
        assertNotEquals(before, last().lights().get(0).position(), "and the light with it");
        assertTrue(app.settings().current().lightMoved());
        assertFalse(app.document().history().canUndo(), "moving the light is a setting, not an edit of the model");
        app.settings().set(LightPlacement.EYE_ABOVE_LEFT);
        assertFalse(app.settings().current().lightMoved(), "choosing a preset puts the light back");
    }

    @Test
    void aFixedLightDragsInTheSceneAndAScenesOwnLightsShowButDoNotDrag() {
        app.settings().set(LightPlacement.ABOVE_LEFT);
        app.settings().toggle(Toggle.SHOW_LIGHT);
        Vec3 fixed = last().lights().get(0).position();
        app.view().rotate(50, 0);
        assertEquals(fixed, last().lights().get(0).position(), "fixed in the scene");
        Scene lit = Models.patch().toBuilder().lights(List.of(new PointLight(new Vec3(0.5, 0.5, 3)))).build();
        app.files().open("lit", () -> new SceneDocument(lit, RenderSettings.defaults()));
        assertEquals(LightPlacement.SCENE, app.settings().current().light(), "a scene with lights is lit by them");
        assertNull(last().lights(), "the renderer takes the scene's own");
        List<LightMarker> markers = app.overlay().snapshot().lights();
        assertEquals(1, markers.size());
        assertFalse(markers.get(0).draggable());
        Vec3 none = null;
        app.pointer().pressed(markers.get(0).x(), markers.get(0).y(), Modifiers.NONE);
        app.pointer().released(markers.get(0).x(), markers.get(0).y());
        assertEquals(none, last().lights());
        app.files().openBuiltIn("patch");
        assertEquals(LightPlacement.EYE_ABOVE_LEFT, app.settings().current().light(), "a model without lights: the default");
    }

    /** Luminance of an sRGB ARGB pixel, 0..255. */
    private static double luminance(int argb) {
        return 0.2126 * (argb >> 16 & 255) + 0.7152 * (argb >> 8 & 255) + 0.0722 * (argb & 255);
    }

    @Test
    void theDefaultLightLightsMostOfTheSpheresDiscSoItReadsAsASolid() throws Exception {
        app.files().openBuiltIn("sphere");
        assertEquals(LightPlacement.EYE_ABOVE_LEFT, app.settings().current().light());
        RenderRequest r = last();
        int w = 160, h = 120;
        RenderSettings s = r.settings();
        RenderSettings small = new RenderSettings(w, h, 1, s.sampler(), s.method(), s.bvh(), s.shading(), s.checker(),
                s.shadows(), s.maxDepth());
        var si = org.beziertracer.intersect.SceneIntersector.build(r.scene(), r.intersect());
        var options = r.options().withProgressive(false).withThreads(2);
        var camera = new org.beziertracer.render.Camera(r.camera());
        // The same view lit from far behind the sphere: every pixel of its disc gets the ambient term only
        Framing f = app.view().view().framing();
        Vec3 behind = f.target().add(camera.forward().scale(1000 * f.radius()));
        int[] lit, dark;
        try (var session = new org.beziertracer.render.RenderSession(2, org.beziertracer.render.FrameSink.NONE,
                org.beziertracer.render.RenderProgress.NONE)) {
            lit = session.render(new org.beziertracer.render.RenderJob(si, camera, small, options, r.lights())).argb();
            dark = session.render(new org.beziertracer.render.RenderJob(si, camera, small, options,
                    List.of(new PointLight(behind)))).argb();
        }
        int background = dark[0], disc = 0, litCount = 0;
        for (int k = 0; k < lit.length; k++) {
            if (dark[k] != background) {
                disc++;
                litCount += luminance(lit[k]) > luminance(dark[k]) + 10 ? 1 : 0;
            }
        }
        assertTrue(disc > w * h / 10, "the sphere covers the picture's middle: " + disc + " pixels");
        double fraction = (double) litCount / disc;
        // The old light (from the eye, 3/4 of the way to the target) lit 64 %: the dark side took a third of the disc
        assertTrue(fraction >= 0.75, "lit over " + Math.round(100 * fraction) + " % of its disc (" + litCount + " of "
                + disc + " pixels), light at " + r.lights());
        assertTrue(fraction < 1, "with a terminator (not lit head-on as a flat disc): " + fraction);
    }
}
