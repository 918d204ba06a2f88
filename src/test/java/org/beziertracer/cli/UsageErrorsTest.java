package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A wrong command line (issue [5 of 6], "picocli usage errors print 10–54 lines of help") is one
 * line in the project's words with a pointer to the command's help, exit code 2, and no usage text.
 */
class UsageErrorsTest {

    @TempDir
    Path dir;

    @Test
    void aValueOfTheWrongTypeIsOneLineNamingTheOptionWhatItWantsAndWhatItGot() {
        String out = dir.resolve("x.png").toString();
        Run r = Run.of("render", "teapot", "-o", out, "--threads", "abc");
        assertEquals(2, r.code());
        assertEquals("beziertracer render: --threads: expected a whole number, found \"abc\" (see beziertracer render --help)",
                UserMessages.checkOneLineOutput(r.err()));
        assertEquals("beziertracer render: --zebra-width: expected a number, found \"wide\" (see beziertracer render --help)",
                UserMessages.checkOneLineOutput(Run.of("render", "teapot", "-o", out, "--zebra-width", "wide").err()));
    }

    @Test
    void unknownOptionsAndMissingParametersAreOneLineToo() {
        String[][] cases = {
            {"render", "teapot", "-o", dir.resolve("x.png").toString(), "--bogus"},
            {"trace", "teapot", "--random", "many"},
            {"analyze"},
            {"info", "teapot", "--frobnicate"},
            {"analyze", "teapot", "--g1", "wide"},
        };
        for (String[] args : cases) {
            Run r = Run.of(args);
            String what = String.join(" ", args);
            assertEquals(2, r.code(), what + " -> " + r.err());
            String line = UserMessages.checkOneLineOutput(r.err());
            assertTrue(line.startsWith("beziertracer " + args[0] + ": ") && line.endsWith("(see beziertracer " + args[0]
                    + " --help)"), what + " -> " + line);
            assertTrue(!r.err().contains("Usage:"), what + ": no usage text");
        }
    }

    @Test
    void renderHelpSaysWhenOutIsNeededAndEveryDefault() {
        Run help = Run.of("render", "--help");
        assertEquals(0, help.code());
        String text = help.out().replaceAll("\\s+", " ");
        var d = org.beziertracer.model.RenderSettings.defaults();
        assertTrue(text.contains("PNG to write (atomically), or .hdr (Radiance RGBE) or .pfm for the linear image; required unless --pixel"), text);
        assertTrue(text.contains("for the path tracer the most bounces of a path, 1.."
                + org.beziertracer.render.PathOptions.MAX_DEPTH + " (default "
                + org.beziertracer.render.PathOptions.defaults().maxDepth() + ")"), "path depth: " + text);
        assertTrue(text.contains("(default: the scene file's, else " + d.spp() + ")"), "spp: " + text);
        assertTrue(text.contains("(default: the scene file's, else " + d.sampler() + ")"), "sampler: " + text);
        assertTrue(text.contains("(default: the scene file's, else " + d.shading() + ";"), "shading: " + text);
        assertTrue(text.contains("(default: the scene file's, else " + d.maxDepth() + ")"), "depth: " + text);
        assertTrue(text.contains("(default: the scene's)"), "method: " + text);
    }
}
