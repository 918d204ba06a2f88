package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

class RenderCommandTest {

    @TempDir
    Path dir;

    private static Run run(String... args) {
        return Run.of(args);
    }

    @Test
    void statsPrintOneJsonLineWithEveryField() throws IOException {
        Path png = dir.resolve("teapot.png");
        Run r = run("render", "teapot", "-o", png.toString(), "--size", "80x60", "--stats", "--repeat", "3",
                "--threads", "2", "--light", "-200,-350,450");
        assertEquals(0, r.code(), r.err());
        String[] lines = r.out().strip().split("\n");
        assertEquals(1, lines.length, r.out());
        JsonObject json = JsonParser.parseString(lines[0]).getAsJsonObject();
        for (String key : new String[] {"width", "height", "spp", "threads", "method", "bvh", "primaryRays", "shadowRays",
                "secondaryRays", "totalRays", "solverCalls", "clipSteps", "patchEvaluations", "buildMillis", "frameMillis",
                "renderMillis", "mraysPerSecond", "subPatches", "bvhNodes"}) {
            assertTrue(json.has(key), "missing " + key + " in " + lines[0]);
        }
        assertEquals(80, json.get("width").getAsInt());
        assertEquals(3, json.get("frameMillis").getAsJsonArray().size());
        assertEquals(4800, json.get("primaryRays").getAsLong());
        assertTrue(json.get("shadowRays").getAsLong() > 0);
        BufferedImage img = ImageIO.read(png.toFile());
        assertEquals(80, img.getWidth());
        assertEquals(60, img.getHeight());
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count(), "no temporary file left behind");
        }
    }

    @Test
    void theWorkCountsRepeatExactlyOnOneThreadAndTrianglesMakeNoPatchWork() {
        // The work a frame makes (leaf-solver calls, clipping steps, patch evaluations) is the
        // measure that does not swing with the machine: on one thread it repeats to the unit
        String[] exact = {"render", "curved", "-o", dir.resolve("c.png").toString(), "--size", "120x90", "--stats",
                "--threads", "1", "--eye", "-4.5,-5,2.5", "--target", "0,0,0.6", "--light", "-2,-4,5"};
        JsonObject a = stats(run(exact)), b = stats(run(exact));
        for (String key : new String[] {"solverCalls", "clipSteps", "patchEvaluations"}) {
            assertTrue(a.get(key).getAsLong() > 0, key + " counted: " + a);
            assertEquals(a.get(key).getAsLong(), b.get(key).getAsLong(), key + " repeats");
        }
        // Each hit of the curved patch costs at least one evaluation, a shadow ray's own leaf often none
        assertTrue(a.get("patchEvaluations").getAsLong() > a.get("primaryRays").getAsLong() / 10, a.toString());
        JsonObject mesh = stats(run("render", "curved", "-o", dir.resolve("m.png").toString(), "--size", "120x90",
                "--stats", "--threads", "1", "--tessellate", "8"));
        assertEquals(0, mesh.get("patchEvaluations").getAsLong(), "triangles: " + mesh);
        assertEquals(0, mesh.get("clipSteps").getAsLong(), "triangles: " + mesh);
    }

    private static JsonObject stats(Run r) {
        assertEquals(0, r.code(), r.err());
        String[] lines = r.out().strip().split("\n");
        return JsonParser.parseString(lines[lines.length - 1]).getAsJsonObject();
    }

    @Test
    void anAnalysisViewRendersWithItsRangeInTheStats() throws IOException {
        Path png = dir.resolve("k.png");
        JsonObject auto = stats(run("render", "sphere", "-o", png.toString(), "--size", "80x60", "--stats",
                "--analysis", "gaussian"));
        assertEquals("gaussian", auto.get("shading").getAsString());
        assertEquals(0, auto.get("shadowRays").getAsLong(), "an analysis view traces no shadow rays");
        assertEquals(1, auto.getAsJsonArray("analysisRange").get(1).getAsDouble(), 1e-9, "the unit sphere: K = 1");
        JsonObject fixed = stats(run("render", "teapot", "-o", png.toString(), "--size", "80x60", "--stats",
                "--analysis", "min-radius", "--analysis-range", "0.5,50"));
        assertEquals(50, fixed.getAsJsonArray("analysisRange").get(1).getAsDouble(), 0);
        assertTrue(Files.size(png) > 0);
        Run zebra = run("render", "teapot", "-o", png.toString(), "--size", "80x60", "--analysis", "zebra",
                "--zebra-axis", "1,0,0", "--zebra-stripes", "8", "--zebra-width", "0.3");
        assertEquals(0, zebra.code(), zebra.err());
    }

    @Test
    void cameraTextureAndShadingOptionsAreAccepted() {
        Run r = run("render", "patch", "-o", dir.resolve("p.png").toString(), "--size", "40x30", "--spp", "4",
                "--sampler", "jittered", "--method", "newton", "--no-bvh", "--shading", "flat", "--texture", "checker:4",
                "--eye", "0,-5,5", "--target", "0,0,0", "--up", "0,0,1", "--fov", "30", "--no-shadows", "--depth", "2",
                "--filter", "tent");
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err());
    }

    @Test
    void tessellateRendersTheTriangleMeshAndReportsKInTheStats() throws IOException {
        Path exact = dir.resolve("exact.png"), mesh = dir.resolve("mesh.png");
        Run e = run("render", "teapot", "-o", exact.toString(), "--size", "80x60", "--stats", "--threads", "1");
        Run t = run("render", "teapot", "-o", mesh.toString(), "--size", "80x60", "--stats", "--threads", "1",
                "--tessellate", "16");
        assertEquals(0, e.code(), e.err());
        assertEquals(0, t.code(), t.err());
        JsonObject je = JsonParser.parseString(e.out().strip()).getAsJsonObject();
        JsonObject jt = JsonParser.parseString(t.out().strip()).getAsJsonObject();
        assertEquals(0, je.get("tessellate").getAsInt(), "exact by default");
        assertEquals(0, je.get("triangles").getAsInt());
        assertEquals(16, jt.get("tessellate").getAsInt());
        assertEquals(32 * 16 * 16 * 2, jt.get("triangles").getAsInt(), "teapot: 32 patches, 2 triangles per cell");
        assertEquals(je.get("primaryRays").getAsLong(), jt.get("primaryRays").getAsLong());
        BufferedImage a = ImageIO.read(exact.toFile()), b = ImageIO.read(mesh.toFile());
        int differing = 0, covered = 0;
        for (int y = 0; y < 60; y++) {
            for (int x = 0; x < 80; x++) {
                int pa = a.getRGB(x, y), pb = b.getRGB(x, y);
                if (pa != a.getRGB(0, 0)) {
                    covered++;
                }
                if (Math.abs((pa & 0xff) - (pb & 0xff)) > 24) {
                    differing++;
                }
            }
        }
        assertTrue(covered > 500, "the teapot covers the frame: " + covered);
        assertTrue(differing < covered / 20, "K = 16 looks like the exact teapot: " + differing + " of " + covered);
    }

    @Test
    void aModelWithoutLightsIsLitByTheAppsDefaultLightNotALightAtTheEye() throws IOException {
        Path byDefault = dir.resolve("default.png"), placed = dir.resolve("placed.png"), atEye = dir.resolve("eye.png");
        assertEquals(0, run("render", "sphere", "-o", byDefault.toString(), "--size", "80x60", "--threads", "1").code());
        var scene = org.beziertracer.model.io.Models.sphere();
        var camera = org.beziertracer.render.RenderJob.defaultCamera(scene, 80.0 / 60).spec();
        var light = org.beziertracer.render.DefaultLight.position(camera, org.beziertracer.render.RenderJob.bounds(scene));
        String xyz = light.x() + "," + light.y() + "," + light.z();
        assertEquals(0, run("render", "sphere", "-o", placed.toString(), "--size", "80x60", "--threads", "1", "--light", xyz).code());
        var eye = camera.eye();
        assertEquals(0, run("render", "sphere", "-o", atEye.toString(), "--size", "80x60", "--threads", "1", "--light",
                eye.x() + "," + eye.y() + "," + eye.z()).code());
        BufferedImage a = ImageIO.read(byDefault.toFile()), b = ImageIO.read(placed.toFile()), c = ImageIO.read(atEye.toFile());
        int same = 0, eyeSame = 0;
        for (int y = 0; y < 60; y++) {
            for (int x = 0; x < 80; x++) {
                same += a.getRGB(x, y) == b.getRGB(x, y) ? 1 : 0;
                eyeSame += a.getRGB(x, y) == c.getRGB(x, y) ? 1 : 0;
            }
        }
        assertEquals(80 * 60, same, "lit exactly as with --light at DefaultLight's place " + xyz);
        assertTrue(eyeSame < 80 * 60 - 500, "not as with the light at the eye: " + eyeSame + " pixels alike");
    }

    @Test
    void pixelTracePrintsRaysHitsAndTerms() {
        Run r = run("render", "teapot", "--size", "80x60", "--pixel", "40,30");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("ray depth=0"), r.out());
        assertTrue(r.out().contains("hit patch"), r.out());
        assertTrue(r.out().contains("diffuse="), r.out());
    }

    @Test
    void differenceToAnotherMethodPrintsTheCountAndWritesTheMarkedImage() throws IOException {
        Path newton = dir.resolve("newton.png");
        Run n = run("render", "teapot", "-o", newton.toString(), "--size", "80x60", "--method", "newton",
                "--difference-to", "clipping");
        assertEquals(0, n.code(), n.err());
        assertEquals("0 of 4800 pixels differ from clipping by more than 10 %", n.out().strip());
        BufferedImage img = ImageIO.read(newton.toFile());
        int grey = 0;
        for (int y = 0; y < 60; y++) {
            for (int x = 0; x < 80; x++) {
                int c = img.getRGB(x, y);
                grey += (c & 0xff) == ((c >> 8) & 0xff) && (c & 0xff) == ((c >> 16) & 0xff) ? 1 : 0;
            }
        }
        assertEquals(4800, grey, "nothing differs: the whole overlay is the dimmed grey picture (marks: ImageDifferenceTest)");
    }

    @Test
    void absurdOrBadInputIsOneErrorLineAndExitCodeOne() {
        String out = dir.resolve("x.png").toString();
        String[][] cases = {
                {"render", "teapot", "-o", dir.resolve("x.txt").toString()},
                {"render", "teapot", "-o", out, "--size", "100000x100000"},
                {"render", "teapot", "-o", out, "--spp", "0"},
                {"render", "teapot", "-o", out, "--shading", "toon"},
                {"render", "teapot", "-o", out, "--size", "abc"},
                {"render", "teapot", "-o", out, "--eye", "1,2"},
                {"render", "teapot", "-o", out, "--depth", "99"},
                {"render", "teapot", "-o", out, "--texture", "stripes"},
                {"render", "nosuchmodel.bpt", "-o", out},
                {"render", "teapot", "-o", dir.resolve("missing/dir/x.png").toString(), "--size", "8x8"},
                {"render", "teapot"},
                {"render", "teapot", "-o", out, "--tessellate", "-1"},
                {"render", "teapot", "-o", out, "--tessellate", "1025"},
                {"render", "teapot", "-o", out, "--tessellate", "1000"},
                {"render", "teapot", "-o", out, "--difference-to", "marching"},
                {"render", "teapot", "-o", out, "--analysis", "phong"},
                {"render", "teapot", "-o", out, "--analysis", "curvy"},
                {"render", "teapot", "-o", out, "--analysis", "gaussian", "--analysis-range", "1"},
                {"render", "teapot", "-o", out, "--analysis", "gaussian", "--analysis-range", "2,1"},
                {"render", "teapot", "-o", out, "--analysis", "zebra", "--zebra-stripes", "500"},
                {"render", "teapot", "-o", out, "--analysis", "draft", "--draft-pull", "0,0,0"},
                {"render", "teapot", "-o", out, "--analysis", "isophotes", "--isophote-step", "0"},
                {"render", "teapot", "-o", out, "--analysis", "emap", "--emap", "no-such-image.png"},
                {"render", "teapot", "-o", out, "--analysis", "emap", "--emap", "pom.xml"},
        };
        for (String[] args : cases) {
            Run r = run(args);
            assertEquals(1, r.code(), String.join(" ", args) + " -> " + r.err());
            String line = UserMessages.checkOneLineOutput(r.err());
            assertTrue(line.startsWith("beziertracer render: "), line);
        }
        assertFalse(Files.exists(dir.resolve("x.png")));
    }
}
