package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.beziertracer.intersect.Method;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The commands take their method names from {@link Method}: a scene file naming an unknown method
 * fails every command as it loads, in one line naming the file, the key and every label; a bad
 * {@code --method} or {@code --difference-to} fails before anything renders; the help lists the labels.
 */
class MethodNamesTest {

    @TempDir
    Path dir;

    private Path room(String method) throws IOException {
        return org.beziertracer.model.io.TestRooms.withMethod(dir, method, true);
    }

    @Test
    void aSceneFileWithAnUnknownMethodFailsEveryCommandAtLoadListingEveryLabel() throws IOException {
        Path room = room("bogus"), png = dir.resolve("out.png");
        String expected = room + ": render.method: unknown method 'bogus': expected " + Method.choices();
        String[][] commands = {
                {"info", room.toString()},
                {"trace", room.toString(), "--random", "1"},
                {"render", room.toString(), "-o", png.toString(), "--size", "8x6"},
                {"render", room.toString(), "-o", png.toString(), "--size", "8x6", "--method", "newton"}};
        for (String[] args : commands) {
            Run r = Run.of(args);
            assertEquals(1, r.code(), String.join(" ", args));
            assertEquals("beziertracer " + args[0] + ": " + expected, UserMessages.checkOneLineOutput(r.err()));
            for (String label : Method.labels()) {
                assertTrue(r.err().contains(label), label + " in: " + r.err());
            }
        }
        assertFalse(Files.exists(png), "nothing rendered");
    }

    @Test
    void aSceneFilesMethodInAnyCaseRenders() throws IOException {
        Path png = dir.resolve("out.png");
        Run r = Run.of("render", room("Newton").toString(), "-o", png.toString(), "--size", "8x6", "--stats");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("\"method\":\"newton\""), r.out());
    }

    @Test
    void aBadMethodOptionFailsBeforeAnythingRenders() {
        Path png = dir.resolve("out.png");
        for (String option : new String[] {"--method", "--difference-to"}) {
            Run r = Run.of("render", "teapot", "-o", png.toString(), "--size", "8x6", option, "bogus");
            assertEquals(1, r.code(), option);
            assertEquals("beziertracer render: unknown method 'bogus': expected " + Method.choices(),
                    UserMessages.checkOneLineOutput(r.err()), option);
        }
        Run t = Run.of("trace", "teapot", "--random", "1", "--method", "bogus");
        assertEquals("beziertracer trace: unknown method 'bogus': expected " + Method.choices(),
                UserMessages.checkOneLineOutput(t.err()));
        assertFalse(Files.exists(png));
    }

    @Test
    void theHelpListsEveryLabel() {
        String labels = String.join(", ", Method.labels());
        for (String command : new String[] {"render", "trace"}) {
            String help = Run.of(command, "--help").out().replaceAll("\\s+", " ");
            assertTrue(help.contains("--method=METHOD ray-patch solver: " + labels), help);
        }
        String render = Run.of("render", "--help").out().replaceAll("\\s+", " ");
        assertTrue(render.contains("--difference-to=METHOD also render with this method (" + labels + ")"), render);
    }
}
