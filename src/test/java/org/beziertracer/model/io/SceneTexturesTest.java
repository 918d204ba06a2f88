package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.beziertracer.UserMessages;
import org.beziertracer.model.HdrImage;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;
import org.beziertracer.model.Texture;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A typed material's {@code "color"} as a checker or an image (issue 34): read, written and read
 * back the same; the image's pixels decoded from sRGB to linear; bad textures are one-line errors
 * naming the file and the key.
 */
class SceneTexturesTest {
    private static final String SPHERE = "\"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}]";

    @TempDir
    Path dir;

    private Scene read(String json) {
        return SceneFiles.parse(json, "studio.json", dir).scene();
    }

    private static String withColor(String type, String color) {
        return "{\"version\": 1, \"materials\": {\"m\": {\"type\": \"" + type + "\", \"color\": " + color + "}}, "
                + SPHERE + "}";
    }

    private void assertError(String expectedPart, String json) {
        String message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse(json, "studio.json", dir));
        assertTrue(message.startsWith("studio.json:") && message.contains(expectedPart),
                "expected \"" + expectedPart + "\" in: " + message);
    }

    /** A 2×2 PNG "wood.png" of sRGB bytes (0, 64, 128), (255, 188, 1), (10, 20, 30), (200, 100, 50). */
    private Path wood() throws IOException {
        BufferedImage img = new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, 0x004080);
        img.setRGB(1, 0, 0xFFBC01);
        img.setRGB(0, 1, 0x0A141E);
        img.setRGB(1, 1, 0xC86432);
        Path file = dir.resolve("wood.png");
        ImageIO.write(img, "png", file.toFile());
        return file;
    }

    private static double linear(int srgb) {
        double c = srgb / 255.0;
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    @Test
    void aCheckerColourReadsWithItsSquaresAndScaleAndItsMeanAsTheColour() {
        Surface s = read(withColor("diffuse",
                "{\"checker\": {\"even\": [0.9, 0.5, 0.1], \"odd\": [0.1, 0.3, 0.7]}, \"scale\": [4, 2]}")).surface(0);
        Texture.Checker c = (Texture.Checker) s.texture();
        assertEquals(new Surface.Vec(0.9, 0.5, 0.1), c.even());
        assertEquals(new Surface.Vec(0.1, 0.3, 0.7), c.odd());
        assertEquals(4, c.su());
        assertEquals(2, c.sv());
        assertEquals(0.5, s.r(), 1e-15, "the mean colour stands for the texture where one colour is needed");
        assertEquals(0.4, s.g(), 1e-15);
        assertNull(read(withColor("diffuse", "[0.5, 0.5, 0.5]")).surface(0).texture(), "a plain colour has no texture");
    }

    @Test
    void anImageColourHoldsThePngsPixelsDecodedFromSrgbToLinear() throws IOException {
        wood();
        for (String type : new String[] {"diffuse", "plastic", "dielectric", "conductor\", \"metal\": \"gold"}) {
            Surface s = read(withColor(type, "{\"image\": \"wood.png\", \"scale\": [3, 1.5]}")).surface(0);
            Texture.Image t = (Texture.Image) s.texture();
            assertEquals("wood.png", t.name(), type);
            assertEquals(3, t.su());
            HdrImage p = t.pixels();
            assertEquals(2, p.width());
            int[][] bytes = {{0x00, 0x40, 0x80}, {0xFF, 0xBC, 0x01}, {0x0A, 0x14, 0x1E}, {0xC8, 0x64, 0x32}};
            for (int k = 0; k < 4; k++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(linear(bytes[k][c]), p.get(k % 2, k / 2, c), 1e-6, type + " pixel " + k + " channel " + c);
                }
            }
        }
    }

    @Test
    void texturedColoursAreWrittenAndReadBackTheSame() throws IOException {
        wood();
        Scene s = read("{\"version\": 1, \"materials\": {\"m\": {\"type\": \"plastic\", \"color\": {\"checker\": "
                + "{\"even\": [1, 1, 1], \"odd\": [0, 0.25, 0]}, \"scale\": [8, 0.5]}, \"roughness\": 0.2}, "
                + "\"w\": {\"type\": \"diffuse\", \"color\": {\"image\": \"wood.png\"}}}, " + SPHERE
                + ", \"planes\": [{\"point\": [0, 0, -1], \"normal\": [0, 0, 1], \"material\": \"w\"}]}");
        String written = SceneFiles.toJson(new SceneDocument(s, RenderSettings.defaults()));
        assertTrue(written.contains("\"image\": \"wood.png\""), written);
        Scene back = SceneFiles.parse(written, "back.json", dir).scene();
        assertEquals(s.surface(0), back.surface(0), "the checker plastic");
        Texture.Image a = (Texture.Image) s.surface(1).texture(), b = (Texture.Image) back.surface(1).texture();
        assertEquals(a.name(), b.name());
        assertEquals(1, b.su());
        assertEquals(a.pixels().get(1, 1, 2), b.pixels().get(1, 1, 2));
        assertEquals(s.surface(1).withTexture(null), back.surface(1).withTexture(null), "all else the same");
        assertEquals(SceneFiles.toJson(new SceneDocument(back, RenderSettings.defaults())), written, "a fixed point");
    }

    @Test
    void aMaterialListedTwiceDecodesItsImageOnce() throws IOException {
        wood();
        Scene s = read("{\"version\": 1, \"materials\": {\"m\": {\"type\": \"diffuse\", \"color\": {\"image\": "
                + "\"wood.png\"}}}, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}, "
                + "{\"center\": [3, 0, 0], \"radius\": 1, \"material\": \"m\"}]}");
        assertEquals(1, s.materials().size());
        assertSame(s.surface(0).texture(), s.surface(0).texture());
    }

    @Test
    void badTexturesAreOneLineErrorsNamingFileAndKey() throws IOException {
        assertError("materials.m.color.image: " + dir.resolve("oak.png") + ": no such image file",
                withColor("diffuse", "{\"image\": \"oak.png\"}"));
        assertError("materials.m.color.image: a texture image must be a .png, .jpg or .jpeg file, found \"sky.hdr\"",
                withColor("diffuse", "{\"image\": \"sky.hdr\"}"));
        Files.writeString(dir.resolve("fake.png"), "not a picture");
        assertError("materials.m.color.image: " + dir.resolve("fake.png") + ": not a PNG or JPEG image",
                withColor("diffuse", "{\"image\": \"fake.png\"}"));
        assertError("materials.m.color.scale: scale must be 2 numbers > 0 (repeats along u and v), found [0, 1]",
                withColor("diffuse", "{\"image\": \"oak.png\", \"scale\": [0, 1]}"));
        assertError("materials.m.color.scale: expected an array of 2 numbers, found 4",
                withColor("diffuse", "{\"checker\": {}, \"scale\": 4}"));
        assertError("materials.m.color: unknown key \"size\"", withColor("diffuse", "{\"checker\": {}, \"size\": 4}"));
        assertError("materials.m.color.checker: unknown key \"white\"",
                withColor("diffuse", "{\"checker\": {\"white\": [1, 1, 1]}}"));
        assertError("materials.m.color.checker.scale: \"scale\" belongs beside \"checker\"",
                withColor("diffuse", "{\"checker\": {\"scale\": [2, 2]}}"));
        assertError("materials.m.color.checker.odd: a physically based colour is an albedo in 0..1, found [2, 0, 0]",
                withColor("diffuse", "{\"checker\": {\"odd\": [2, 0, 0]}}"));
        assertError("materials.m.color: a textured colour needs exactly one of \"checker\" or \"image\"",
                withColor("diffuse", "{\"scale\": [2, 2]}"));
        assertError("materials.m.checker: give either a textured \"color\" or \"checker\", not both",
                "{\"version\": 1, \"materials\": {\"m\": {\"type\": \"diffuse\", \"color\": {\"checker\": {}}, "
                        + "\"checker\": 8}}, " + SPHERE + "}");
    }
}
