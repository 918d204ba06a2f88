package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;

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
        assertEquals(DisplayCheck.NO_DISPLAY, UserMessages.checkOneLineOutput(r.err()), "the one line on stderr");
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
}
