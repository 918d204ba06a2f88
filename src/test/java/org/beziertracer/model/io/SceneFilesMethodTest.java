package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link SceneFiles#load(String, Consumer)}: the model layer reads the method as a word, and the
 * check the caller passes (the intersection layer's {@code Method::parse}) refuses an unknown one
 * at load time, in the one line naming the file and the key that any bad value gets.
 */
class SceneFilesMethodTest {

    @TempDir
    Path dir;

    private Path room(String method) throws IOException {
        return org.beziertracer.model.io.TestRooms.withMethod(dir, method, false);
    }

    /** Knows {@code alpha} and {@code beta} only. */
    private static void twoMethods(String name) {
        if (!name.equals("alpha") && !name.equals("beta")) {
            throw new IllegalArgumentException("unknown method '" + name + "': expected alpha or beta");
        }
    }

    @Test
    void theCheckSeesTheFilesMethodAndItsRefusalNamesTheFileAndKey() throws IOException {
        Path file = room("Gamma");
        assertEquals("gamma", SceneFiles.load(file.toString()).settings().method(), "the model layer keeps the word");
        assertEquals(file + ": render.method: unknown method 'gamma': expected alpha or beta",
                UserMessages.of(ModelFormatException.class, () -> SceneFiles.load(file.toString(), SceneFilesMethodTest::twoMethods)));
        List<String> seen = new ArrayList<>();
        Path ok = room("Beta");
        assertEquals("beta", SceneFiles.load(ok.toString(), seen::add).settings().method());
        assertEquals(List.of("beta"), seen);
    }

    @Test
    void aMethodThatIsNoWordFailsInTheReaderWithTheSamePath() throws IOException {
        Path file = room("two words");
        assertEquals(file + ": render.method: method must be a name (one word), got \"two words\"",
                UserMessages.of(ModelFormatException.class, () -> SceneFiles.load(file.toString())));
    }

    @Test
    void aBuiltInSceneLoadsThroughTheCheck() {
        List<String> seen = new ArrayList<>();
        SceneFiles.load("teapot-room", seen::add);
        assertEquals(1, seen.size(), "the check ran once");
    }
}
