package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/**
 * Starting the app where no display can be reached prints one line and exits with code 3: run as
 * its own process, with {@code DISPLAY} naming a display that does not exist (and, the other way
 * in, with no {@code DISPLAY} at all), {@code java.awt.headless} unset.
 */
class NoDisplayTest {

    private static Process start(String display) throws IOException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-cp", System.getProperty("java.class.path"),
                "org.beziertracer.Main"));
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().remove("JAVA_TOOL_OPTIONS");
        pb.environment().remove("_JAVA_OPTIONS");
        if (display == null) {
            pb.environment().remove("DISPLAY");
        } else {
            pb.environment().put("DISPLAY", display);
        }
        return pb.start();
    }

    private static void assertOneLine(String display) throws Exception {
        Process p = start(display);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the app did not exit");
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(BezierTracerCommand.EXIT_NO_DISPLAY, p.exitValue(), "exit code; stderr: " + err);
        assertEquals(DisplayCheck.NO_DISPLAY + System.lineSeparator(), err, "exactly one line on stderr");
        assertEquals("", out);
    }

    @Test
    void aDisplayThatCannotBeReachedGivesOneLine() throws Exception {
        assertOneLine(":4171");
    }

    @Test
    void noDisplayAtAllGivesTheSameLine() throws Exception {
        assertOneLine(null);
    }
}
