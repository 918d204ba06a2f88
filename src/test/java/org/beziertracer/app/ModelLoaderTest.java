package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.beziertracer.intersect.Method;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** File → Open refuses a scene file naming an unknown method as it loads, in the error dialog's one line. */
class ModelLoaderTest {

    @TempDir
    Path dir;

    private Path room(String method) throws IOException {
        return org.beziertracer.model.io.TestRooms.withMethod(dir, method, false);
    }

    @Test
    void anUnknownMethodIsRefusedAtLoadAndAKnownOneReachesTheSettings() throws IOException {
        Path bad = room("bogus");
        assertEquals(bad + ": render.method: unknown method 'bogus': expected " + Method.choices(),
                UserMessages.of(IllegalArgumentException.class, () -> ModelLoader.load(bad)));
        for (Method m : Method.values()) {
            Path file = room(m.label());
            Settings s = RenderChoices.fromScene(Settings.defaults(), ModelLoader.load(file).settings());
            assertSame(m, s.method());
        }
    }
}
