package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.beziertracer.ChildJvm;
import org.beziertracer.UserMessages;
import org.beziertracer.cli.LimitsFixtures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** In the app, a model that would not fit in the heap is one line in the error dialog; the current model stays. */
class ModelTooBigTest {

    @TempDir
    Path dir;

    @Test
    void aModelThatWouldNotFitShowsTheOneLineLimitAndKeepsTheCurrentModel() throws Exception {
        Path big = LimitsFixtures.wavyModel(dir.resolve("big.bpt"), 80);
        ChildJvm.Result r = ChildJvm.run(dir, List.of("-Xmx32m"), OpenTooBigProbe.class.getName(), big.toString());
        assertEquals(0, r.code(), r.err());
        List<String> lines = r.out().lines().toList();
        assertEquals("opened=false", lines.get(0), r.out());
        assertEquals("patches=1->1", lines.get(1), "the default patch stays: " + r.out());
        assertEquals(3, lines.size(), "one error dialog: " + r.out());
        String message = UserMessages.check(lines.get(2).substring("error=".length()));
        assertTrue(message.startsWith(big + ": 80 patches need about "), message);
        assertTrue(message.contains(" of heap; this JVM allows "), message);
    }
}
