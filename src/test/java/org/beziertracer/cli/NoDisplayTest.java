package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.beziertracer.ChildJvm;
import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Starting the app where no display can be reached prints one line and exits with code 3: run as
 * its own process, with {@code DISPLAY} naming a display that does not exist (and, the other way
 * in, with no {@code DISPLAY} at all), {@code java.awt.headless} unset.
 */
class NoDisplayTest {

    @TempDir
    Path dir;

    private void assertOneLine(String display) throws Exception {
        ChildJvm.Result r = ChildJvm.runWithDisplay(dir, display, "org.beziertracer.Main");
        assertEquals(BezierTracerCommand.EXIT_NO_DISPLAY, r.code(), "exit code; stderr: " + r.err());
        assertEquals(DisplayCheck.noDisplay(), UserMessages.checkOneLineOutput(r.err()), "the one line on stderr");
        assertEquals("", r.out());
    }

    @Test
    void aDisplayThatCannotBeReachedGivesOneLine() throws Exception {
        assertOneLine(":4171");
    }

    @Test
    void noDisplayAtAllGivesTheSameLine() throws Exception {
        assertOneLine(null);
    }

    @Test
    void thePackagedLauncherNamesItselfInTheHint() throws Exception {
        ChildJvm.Result r = ChildJvm.runWithDisplay(dir, null,
                List.of("-Djpackage.app-path=/opt/beziertracer/bin/BezierTracer"), "org.beziertracer.Main");
        assertEquals(BezierTracerCommand.EXIT_NO_DISPLAY, r.code(), r.err());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.endsWith("(/opt/beziertracer/bin/BezierTracer --help)"), line);
        assertFalse(line.contains("java -jar"), line);
    }
}
