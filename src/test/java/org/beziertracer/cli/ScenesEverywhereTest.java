package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every command opens what the format registry opens: models, scene files and built-in names. */
class ScenesEverywhereTest {

    @TempDir
    Path dir;

    private Path room() throws IOException {
        Path p = dir.resolve("room.json");
        Files.writeString(p, "{\"version\": 1, \"models\": [{\"builtin\": \"patch\"}],"
                + " \"spheres\": [{\"center\": [0, 0, 10], \"radius\": 1}],"
                + " \"lights\": [{\"position\": [0, 0, 50]}]}");
        return p;
    }

    @Test
    void infoOpensASceneFileAndCountsItsObjects() throws IOException {
        Run r = Run.of("info", room().toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("patches: 1\n"), r.out());
        assertTrue(r.out().contains("objects: 0 planes, 1 sphere, 1 light\n"), r.out());
    }

    @Test
    void infoOpensTheBuiltInScene() {
        Run r = Run.of("info", "teapot-room");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("patches: 32\n"), r.out());
        assertTrue(r.out().contains("objects: 1 plane, 2 spheres, 1 light\n"), r.out());
    }

    @Test
    void renderPathTracesTheBuiltInStudioAndCountsItsSamplesASecond() throws IOException {
        Path png = dir.resolve("studio.png");
        Run r = Run.of("render", "studio", "--integrator", "path", "--size", "32x24", "--spp", "2", "--threads", "1",
                "--stats", "-o", png.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(Files.size(png) > 0, "the PNG is written");
        assertTrue(r.out().contains("\"integrator\":\"path\""), r.out());
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\"samplesPerSecond\":([0-9.]+)").matcher(r.out());
        assertTrue(m.find() && Double.parseDouble(m.group(1)) > 0, "samples a second: " + r.out());
    }

    @Test
    void traceOpensASceneFileAndNamesWhatEachRayHit() throws IOException {
        Path rays = dir.resolve("rays.txt");
        Files.writeString(rays, "0 0 30 0 0 -1\n0.5 0.5 5 0 0 -1\n");
        Run r = Run.of("trace", room().toString(), "-i", rays.toString());
        assertEquals(0, r.code(), r.err());
        String[] lines = r.out().split("\n");
        assertEquals(TraceCommand.HEADER + ",object", lines[0]);
        String[] sphere = lines[1].split(",", -1), patch = lines[2].split(",", -1);
        assertEquals(13, sphere.length, lines[1]);
        assertEquals(19, Double.parseDouble(sphere[2]), 1e-9, "the sphere's top at z = 11: " + lines[1]);
        assertEquals("", sphere[3], "no patch index for a sphere: " + lines[1]);
        assertEquals("sphere 0", sphere[12], lines[1]);
        assertEquals(5, Double.parseDouble(patch[2]), 1e-9, "the patch at z = 0: " + lines[2]);
        assertEquals("0", patch[3], lines[2]);
        assertEquals("patch 0", patch[12], lines[2]);
    }

    @Test
    void anUnknownNameListsEveryBuiltInAndEveryExtension() {
        Run r = Run.of("info", "kettle");
        assertEquals(1, r.code());
        assertEquals("beziertracer info: kettle: not a built-in name (patch, teapot, teacup, teaspoon, sphere, torus,"
                + " trimmed-plate, wavy6, wavy10, curved, teapot-room, studio) and not a"
                + " .bpt, .obj, .igs, .iges, .stp, .step or .json file", UserMessages.checkOneLineOutput(r.err()));
    }

    @Test
    void everyCommandsHelpListsTheRegisteredFormatsAndBuiltIns() {
        for (String command : new String[] {"info", "trace", "render"}) {
            String help = Run.of(command, "--help").out().replaceAll("\\s+", " ");
            assertTrue(help.contains("a .bpt, .obj, .igs, .iges, .stp, .step or .json file, or a built-in: patch, teapot, teacup, teaspoon, sphere,"
                    + " torus, trimmed-plate,"
                    + " wavy6, wavy10, curved, teapot-room, studio"), help);
        }
    }
}
