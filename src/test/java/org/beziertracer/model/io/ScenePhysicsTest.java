package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.UserMessages;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.AreaLight;
import org.beziertracer.model.Environment;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;
import org.junit.jupiter.api.Test;

/**
 * The path tracer's scene keys (issue 34): typed materials, sphere and rect lights, the
 * environment; read, written and read back to the same scene; bad values give one line naming
 * the file and the key; old Phong materials still read.
 */
class ScenePhysicsTest {
    private static final String SPHERE = "\"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}]";

    private static Scene read(String json) {
        return SceneFiles.parse(json, "studio.json", null).scene();
    }

    private static void assertError(String expectedPart, String json) {
        String message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse(json, "studio.json", null));
        assertTrue(message.startsWith("studio.json:") && message.contains(expectedPart),
                "expected \"" + expectedPart + "\" in: " + message);
    }

    private static String withMaterial(String material) {
        return "{\"version\": 1, \"materials\": {\"m\": " + material + "}, " + SPHERE + "}";
    }

    @Test
    void typedMaterialsReadAsSurfacesBesideTheirPhongLook() {
        Scene s = read(withMaterial("{\"type\": \"conductor\", \"metal\": \"gold\", \"roughness\": 0.3}"));
        Surface gold = s.surface(0);
        assertEquals(Surface.Kind.CONDUCTOR, gold.kind());
        assertEquals(0.3, gold.roughness());
        assertEquals(3.9831604247, gold.k().r());
        assertEquals("gold", gold.metal());
        assertTrue(s.materials().get(0).reflectivity() > 0, "the Whitted look of a metal reflects");
        Surface glass = read(withMaterial("{\"type\": \"dielectric\", \"ior\": 1.33}")).surface(0);
        assertEquals(Surface.Kind.DIELECTRIC, glass.kind());
        assertEquals(1.33, glass.ior());
        assertEquals(0, glass.roughness(), "glass is smooth unless told");
        Surface plastic = read(withMaterial("{\"type\": \"plastic\", \"color\": [0.8, 0.1, 0.1], \"roughness\": 0.2}"))
                .surface(0);
        assertEquals(0.1, plastic.g());
        assertEquals(Surface.Kind.DIFFUSE, read(withMaterial("{\"type\": \"diffuse\", \"color\": [0.5, 0.5, 0.5]}"))
                .surface(0).kind());
    }

    @Test
    void oldPhongMaterialsStillReadAndHaveNoSurface() {
        Scene s = read(withMaterial("{\"color\": [1, 0, 0], \"reflectivity\": 0.2}"));
        assertNull(s.surface(0));
        assertEquals(Surface.Kind.DIFFUSE, s.surfaceOrPhong(0).kind(), "the path tracer reads it as diffuse");
        assertEquals(Surface.Kind.DIELECTRIC, read(withMaterial("{\"transparency\": 0.9, \"ior\": 1.5}"))
                .surfaceOrPhong(0).kind(), "and a transparent one as glass");
    }

    @Test
    void areaLightsAndTheEnvironmentRead() {
        Scene s = read("{\"version\": 1, " + SPHERE.replace(", \"material\": \"m\"", "") + ", \"lights\": ["
                + "{\"position\": [0, 0, 5]},"
                + "{\"type\": \"sphere\", \"center\": [1, 2, 3], \"radius\": 0.5, \"color\": [1, 0.9, 0.8], \"power\": 100},"
                + "{\"type\": \"rect\", \"corner\": [0, 0, 4], \"edge1\": [1, 0, 0], \"edge2\": [0, 1, 0]},"
                + "{\"type\": \"spot\", \"position\": [0, 0, 5], \"direction\": [0, 0, -1], \"angle\": 40}],"
                + "\"environment\": {\"color\": [0.1, 0.2, 0.3], \"intensity\": 2}}");
        assertEquals(30, s.spotLights().get(0).falloff(), "falloff defaults to 3/4 of the angle");
        assertEquals(1, s.lights().size());
        assertEquals(2, s.areaLights().size());
        AreaLight sphere = s.areaLights().get(0);
        assertEquals(new Vec3(1, 2, 3), sphere.center());
        assertEquals(100 / (Math.PI * 4 * Math.PI * 0.25), sphere.radiance()[0], 1e-12, "power / (π · area)");
        AreaLight rect = s.areaLights().get(1);
        assertEquals(1, rect.radiance()[2], "without power the colour is the radiance");
        Environment e = s.environment().orElseThrow();
        assertEquals(0.2, e.g());
        assertEquals(2, e.intensity());
    }

    @Test
    void aSceneWithTheNewKeysIsWrittenAndReadBackTheSame() {
        Scene s = read("{\"version\": 1, \"materials\": {\"m\": {\"type\": \"conductor\", \"metal\": \"copper\", "
                + "\"roughness\": 0.25}, \"g\": {\"type\": \"dielectric\", \"ior\": 1.5, \"roughness\": 0.1}, "
                + "\"c\": {\"type\": \"conductor\", \"eta\": [1, 2, 3], \"k\": [4, 5, 6]}, "
                + "\"p\": {\"type\": \"plastic\", \"color\": [0.2, 0.3, 0.4], \"checker\": 8}}, "
                + SPHERE + ", \"planes\": [{\"point\": [0, 0, -1], \"normal\": [0, 0, 1], \"material\": \"p\"}], "
                + "\"lights\": [{\"type\": \"rect\", \"corner\": [0, 0, 4], \"edge1\": [1, 0, 0], \"edge2\": [0, 1, 0], "
                + "\"power\": 20}, {\"type\": \"sphere\", \"center\": [1, 2, 3], \"radius\": 0.5}, "
                + "{\"type\": \"spot\", \"position\": [0, 0, 5], \"direction\": [1, 0, -1], \"angle\": 25, \"falloff\": 10}], "
                + "\"environment\": {\"color\": [0.1, 0.2, 0.3], \"rotate\": 30}}");
        SceneDocument doc = new SceneDocument(s, org.beziertracer.model.RenderSettings.defaults());
        Scene back = SceneFiles.parse(SceneFiles.toJson(doc), "back.json", null).scene();
        assertEquals(s.materials(), back.materials());
        for (int k = 0; k < s.materials().size(); k++) {
            assertEquals(s.surface(k), back.surface(k), "surface " + k);
        }
        assertEquals(s.areaLights(), back.areaLights());
        assertEquals(1, back.spotLights().size());
        assertEquals(s.spotLights(), back.spotLights());
        assertEquals(s.environment(), back.environment());
    }

    @org.junit.jupiter.api.io.TempDir
    java.nio.file.Path dir;

    @Test
    void anHdrImageEnvironmentIsReadBesideTheSceneAndWrittenBackByName() throws java.io.IOException {
        // a 2×1 flat RGBE picture: (128, 64, 32, 129) and black
        java.io.ByteArrayOutputStream hdr = new java.io.ByteArrayOutputStream();
        hdr.writeBytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        hdr.writeBytes(new byte[] {(byte) 128, 64, 32, (byte) 129, 0, 0, 0, 0});
        java.nio.file.Files.write(dir.resolve("sky.hdr"), hdr.toByteArray());
        String json = "{\"version\": 1, " + SPHERE.replace(", \"material\": \"m\"", "")
                + ", \"environment\": {\"image\": \"sky.hdr\", \"intensity\": 3, \"rotate\": 45}}";
        Scene s = SceneFiles.parse(json, "studio.json", dir).scene();
        Environment e = s.environment().orElseThrow();
        assertEquals("sky.hdr", e.image());
        assertEquals(2, e.picture().width());
        assertEquals((128 + 0.5) / 128, e.picture().get(0, 0, 0), 1e-6, "(R + ½)·2^(129 − 136), as Radiance");
        assertEquals(45, e.rotate());
        String written = SceneFiles.toJson(new SceneDocument(s, org.beziertracer.model.RenderSettings.defaults()));
        Environment back = SceneFiles.parse(written, "back.json", dir).scene().environment().orElseThrow();
        assertEquals("sky.hdr", back.image());
        assertEquals(3, back.intensity());
        assertEquals(e.picture().get(0, 0, 1), back.picture().get(0, 0, 1));
    }

    @Test
    void badValuesAreOneLineErrorsNamingFileAndKey() {
        assertError("materials.m.type: unknown material type \"metal\"", withMaterial("{\"type\": \"metal\"}"));
        assertError("materials.m.metal: unknown metal \"brass\"", withMaterial("{\"type\": \"conductor\", \"metal\": \"brass\"}"));
        assertError("materials.m: a conductor needs \"metal\"", withMaterial("{\"type\": \"conductor\"}"));
        assertError("materials.m.roughness: roughness must be in 0..1, found 2",
                withMaterial("{\"type\": \"plastic\", \"roughness\": 2}"));
        assertError("materials.m.ior: ior must be a finite number > 1, found 0.5",
                withMaterial("{\"type\": \"dielectric\", \"ior\": 0.5}"));
        assertError("materials.m.color: a physically based colour is an albedo in 0..1",
                withMaterial("{\"type\": \"diffuse\", \"color\": [2, 0, 0]}"));
        assertError("materials.m.metal: \"metal\" belongs to a conductor",
                withMaterial("{\"type\": \"diffuse\", \"metal\": \"gold\"}"));
        assertError("materials.m.eta: expected 3 numbers > 0",
                withMaterial("{\"type\": \"conductor\", \"eta\": [0, 1, 1], \"k\": [1, 1, 1]}"));
        String lights = "{\"version\": 1, " + SPHERE.replace(", \"material\": \"m\"", "") + ", \"lights\": [";
        assertError("lights[0].radius: expected a positive number",
                lights + "{\"type\": \"sphere\", \"center\": [0, 0, 3], \"radius\": -1}]}");
        assertError("lights[0]: a rect light's edge1 and edge2 must not be parallel",
                lights + "{\"type\": \"rect\", \"corner\": [0, 0, 3], \"edge1\": [1, 0, 0], \"edge2\": [2, 0, 0]}]}");
        assertError("lights[0].type: unknown light type \"tube\"", lights + "{\"type\": \"tube\"}]}");
        assertError("lights[0]: spot angles must satisfy 0 < falloff <= angle <= 90 degrees, got falloff 40",
                lights + "{\"type\": \"spot\", \"position\": [0, 0, 3], \"direction\": [0, 0, -1], \"angle\": 30, "
                + "\"falloff\": 40}]}");
        assertError("lights[0].power: power must be a finite number >= 0, found -3",
                lights + "{\"type\": \"sphere\", \"center\": [0, 0, 3], \"radius\": 1, \"power\": -3}]}");
        assertError("lights[0]: unknown key \"radius\"",
                lights + "{\"type\": \"rect\", \"corner\": [0, 0, 3], \"radius\": 1}]}");
        String env = "{\"version\": 1, " + SPHERE.replace(", \"material\": \"m\"", "") + ", \"environment\": ";
        assertError("environment.image: an environment image must be a Radiance .hdr file, found \"sky.png\"",
                env + "{\"image\": \"sky.png\", \"intensity\": 2}}");
        assertError("environment.image: sky.hdr: no such image file", env + "{\"image\": \"sky.hdr\"}}");
        assertError("environment: give either \"color\" or \"image\", not both",
                env + "{\"image\": \"sky.hdr\", \"color\": [1, 1, 1]}}");
        assertError("environment.intensity: intensity must be a finite number >= 0, found -1",
                env + "{\"color\": [1, 1, 1], \"intensity\": -1}}");
        assertError("environment: missing key \"color\" (or \"image\")", env + "{\"intensity\": 1}}");
        assertError("environment.color: expected a colour", env + "{\"color\": [1, -1, 1]}}");
    }
}
