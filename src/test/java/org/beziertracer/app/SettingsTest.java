package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.UserMessages;
import org.beziertracer.intersect.Method;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.render.ShadingMode;
import org.junit.jupiter.api.Test;

class SettingsTest {

    @Test
    void aFreshAppMatchesTheMemoirToolbox() {
        Settings s = Settings.defaults();
        for (Toggle t : Toggle.values()) {
            assertEquals(t.initial(), s.on(t), t.name());
        }
        assertEquals(12, s.level(Level.WIREFRAME_SUBDIVISION));
        assertEquals(36, s.level(Level.PERSPECTIVE));
        assertEquals(Method.CLIPPING, s.method());
        assertEquals(LightPlacement.EYE_ABOVE_LEFT, s.light(), "not at the eye: a first look that reads");
        assertEquals(LightPlacement.AT_EYE, LightPlacement.values()[s.light().ordinal() + 1], "at the eye is one preset away");
        assertEquals(ShadingMode.PHONG, s.shading());
        assertEquals(1, s.samplesPerPixel(), "no super-sampling");
    }

    @Test
    void changesMakeNewValuesAndLeaveTheOldOneAlone() {
        Settings a = Settings.defaults();
        Settings b = a.with(Toggle.NORMALS, true).with(Level.GRID_U, 7).with(Method.NEWTON);
        assertFalse(a.on(Toggle.NORMALS));
        assertEquals(4, a.level(Level.GRID_U));
        assertEquals(ShadingMode.NORMALS, b.shading());
        assertEquals(7, b.level(Level.GRID_U));
        assertNotEquals(a, b);
        assertEquals(b, Settings.defaults().with(Method.NEWTON).with(Level.GRID_U, 7).with(Toggle.NORMALS, true));
        assertEquals("grid points along v must be 2..10, got 11",
                UserMessages.of(IllegalArgumentException.class, () -> a.with(Level.GRID_V, 11)));
    }

    @Test
    void theExposureIsTheDoubleTheCommandLineReadsForTheSameDecimal() {
        for (int tenths = Level.EXPOSURE.min(); tenths <= Level.EXPOSURE.max(); tenths++) {
            String decimal = (tenths < 0 ? "-" : "") + Math.abs(tenths) / 10 + "." + Math.abs(tenths) % 10;
            assertEquals(Double.parseDouble(decimal), Settings.defaults().with(Level.EXPOSURE, tenths).exposure(),
                    "render --exposure " + decimal);
        }
        assertEquals(0, Settings.defaults().exposure(), "0 EV in a fresh app");
        assertEquals("exposure in tenths of a stop must be -50..50, got 51",
                UserMessages.of(IllegalArgumentException.class, () -> Settings.defaults().with(Level.EXPOSURE, 51)));
        Settings a = Settings.defaults().with(Toggle.PATH_TRACED, true);
        assertTrue(a.sameButExposure(a.with(Level.EXPOSURE, 12)));
        assertFalse(a.sameButExposure(a.with(Level.EXPOSURE, 12).with(Toggle.SHADOWS, false)));
        assertFalse(a.sameButExposure(null));
    }

    @Test
    void levelsStepWithinTheirRangeAndCycleThroughTheirChoices() {
        assertEquals(64, Level.WIREFRAME_SUBDIVISION.step(63, 5));
        assertEquals(1, Level.WIREFRAME_SUBDIVISION.step(1, -1));
        assertEquals(9, Level.SAMPLES_PER_PIXEL.next(4));
        assertEquals(4, Level.SAMPLES_PER_PIXEL.next(16), "wraps");
        assertEquals(2, Level.GRID_U.next(10), "the grid wraps 10 → 2");
        assertEquals(32, Level.TESSELLATION.next(16));
        assertEquals(8, Level.TESSELLATION.next(5), "off the list: the next choice up");
        assertEquals(9, Level.SAMPLES_PER_PIXEL.snap(6));
        assertEquals(16, Level.SAMPLES_PER_PIXEL.snap(100));
    }

    @Test
    void aSceneFilesSettingsAreParsedOnceIntoTheToolbox() {
        RenderSettings file = new RenderSettings(320, 200, 6, "jittered", "newton", false, "flat", 4, false, 0);
        Settings s = RenderChoices.fromScene(Settings.defaults().with(LightPlacement.BELOW), file);
        assertEquals(Method.NEWTON, s.method());
        assertFalse(s.on(Toggle.BVH));
        assertEquals(ShadingMode.FLAT, s.shading());
        assertTrue(s.on(Toggle.TEXTURE));
        assertFalse(s.on(Toggle.SHADOWS));
        assertFalse(s.on(Toggle.REFLECTIONS));
        assertTrue(s.on(Toggle.SUPER_SAMPLING));
        assertEquals(9, s.level(Level.SAMPLES_PER_PIXEL), "6 samples snap to the offered 9");
        assertEquals(LightPlacement.BELOW, s.light(), "the file's settings leave the light alone");
        assertEquals(LightPlacement.SCENE, RenderChoices.lightFor(s, true).light(), "a scene brings its own lights");
        assertEquals(LightPlacement.BELOW, RenderChoices.lightFor(s, false).light(), "a model keeps the chosen light");
        assertEquals(LightPlacement.EYE_ABOVE_LEFT, RenderChoices.lightFor(s.with(LightPlacement.SCENE), false).light(),
                "and gets the default instead of the scene's lights it does not have");
    }

    @Test
    void theRendererGetsWhatTheToolboxSays() {
        Settings s = Settings.defaults().with(Toggle.SUPER_SAMPLING, true).with(Level.SAMPLES_PER_PIXEL, 16)
                .with(Toggle.TEXTURE, true).with(Toggle.REFLECTIONS, false).with(Level.INTERACTIVITY, 3)
                .with(Toggle.TESSELLATED, true).with(Level.TESSELLATION, 8);
        RenderSettings r = RenderChoices.renderSettings(s, 64, 48);
        assertEquals(16, r.spp());
        assertEquals(RenderChoices.CHECKER_SQUARES, r.checker());
        assertEquals(0, r.maxDepth());
        assertEquals("phong", r.shading());
        assertEquals(3, RenderChoices.renderOptions(s).passesPerFrame());
        assertEquals(8, RenderChoices.intersectOptions(s).tessellate());
        assertEquals("tessellated 8", s.intersectionLabel());
        assertEquals(0, Settings.perspectiveOf(0));
        assertEquals(100, Settings.perspectiveOf(500), "a wider scene camera is clamped");
    }
}
