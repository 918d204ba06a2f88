package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An OBJ file's polygon faces in the commands: {@code render} draws a triangle floor under a patch
 * where it should be, {@code info} counts its triangles, a bad face is one error line.
 */
class MeshSceneTest {

    @TempDir
    Path dir;

    /** A red floor quad [-2,2]² at z = 0 (two triangles), seen from above beneath a blue patch [-0.5,0.5]² at z = 1. */
    private Path scene() throws IOException {
        Files.writeString(dir.resolve("floor.obj"), "# a floor\nv -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\nvn 0 0 1\n"
                + "f 1//1 2//1 3//1 4//1\n");
        String json = """
                {
                  "version": 1,
                  "materials": { "blue": { "color": [0, 0, 1] }, "red": { "color": [1, 0, 0] } },
                  "models": [
                    { "patches": [{ "degree": [1, 1], "points": [[-0.5,-0.5,1],[0.5,-0.5,1],[-0.5,0.5,1],[0.5,0.5,1]] }],
                      "material": "blue" },
                    { "file": "floor.obj", "material": "red" }
                  ],
                  "camera": { "eye": [0, 0, 10], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 40 },
                  "render": { "shading": "flat", "shadows": false }
                }
                """;
        Path file = dir.resolve("scene.json");
        Files.writeString(file, json);
        return file;
    }

    @Test
    void aRenderedPatchOverATriangleFloorHasTheFloorWhereItShouldBe() throws IOException {
        Path png = dir.resolve("out.png");
        Run r = Run.of("render", scene().toString(), "-o", png.toString(), "--size", "80x80", "--spp", "1");
        assertEquals(0, r.code(), r.err());
        BufferedImage img = ImageIO.read(png.toFile());
        // 40° field of view from 10 above: the image spans ±3.64 at the floor, ±3.28 at the patch
        int[][] patch = {{40, 40}, {36, 44}, {44, 36}};
        int[][] floor = {{57, 40}, {23, 40}, {40, 57}, {40, 23}, {60, 60}, {20, 20}};
        int[][] background = {{2, 2}, {77, 40}, {40, 77}};
        for (int[] p : patch) {
            int rgb = img.getRGB(p[0], p[1]);
            assertTrue(blue(rgb) > 100 && red(rgb) < 30, "patch at " + p[0] + "," + p[1] + ": " + Integer.toHexString(rgb));
        }
        for (int[] p : floor) {
            int rgb = img.getRGB(p[0], p[1]);
            assertTrue(red(rgb) > 100 && blue(rgb) < 30, "floor at " + p[0] + "," + p[1] + ": " + Integer.toHexString(rgb));
        }
        for (int[] p : background) {
            int rgb = img.getRGB(p[0], p[1]);
            assertTrue(red(rgb) < 60 && blue(rgb) < 60, "background at " + p[0] + "," + p[1] + ": "
                    + Integer.toHexString(rgb));
        }
    }

    private static int red(int rgb) { return (rgb >> 16) & 0xff; }

    private static int blue(int rgb) { return rgb & 0xff; }

    @Test
    void infoCountsTheTrianglesOfAModelAndOfAScene() throws IOException {
        Path scene = scene();
        Run model = Run.of("info", dir.resolve("floor.obj").toString());
        assertEquals(0, model.code(), model.err());
        assertTrue(model.out().contains("patches: 0"), model.out());
        assertTrue(model.out().contains("meshes: 1 mesh, 2 triangles"), model.out());
        Run whole = Run.of("info", "--accel", scene.toString());
        assertEquals(0, whole.code(), whole.err());
        assertTrue(whole.out().contains("meshes: 1 mesh, 2 triangles"), whole.out());
        assertTrue(whole.out().contains("bvh primitives: "), whole.out());
    }

    @Test
    void aBadFaceIsOneErrorLineNamingFileAndLine() throws IOException {
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
        Run r = Run.of("info", bad.toString());
        assertEquals(1, r.code());
        String err = r.err().strip();
        assertTrue(!err.contains("\n") && err.contains("bad.obj:4:") && err.contains("index out of range")
                && !err.contains("Exception"), err);
    }
}
