package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class DocumentFilesTest {

    @TempDir
    Path dir;

    @Test
    void savedModelsReadBackExactlyAsBptAndObj() throws IOException {
        Scene s = NetEdits.randomize(Models.patch(), 9);
        for (String name : new String[] {"s.bpt", "s.obj"}) {
            Path f = dir.resolve(name);
            DocumentFiles.saveModel(f, s);
            assertEquals(s.patches(), Models.load(f.toString()).patches(), name);
        }
        UserMessages.of(IllegalArgumentException.class, () -> DocumentFiles.saveModel(dir.resolve("s.txt"), s));
        try (var files = Files.list(dir)) {
            assertTrue(files.noneMatch(p -> p.getFileName().toString().endsWith(".tmp")), "no temporary file left");
        }
    }

    @Test
    void meshExportsAreComplete() throws IOException {
        Path obj = dir.resolve("m.obj");
        var mesh = DocumentFiles.exportMesh(obj, Models.teapot());
        assertEquals(32 * 2 * DocumentFiles.MESH_SEGMENTS * DocumentFiles.MESH_SEGMENTS, mesh.triangleCount());
        long faces = Files.readAllLines(obj).stream().filter(l -> l.startsWith("f ")).count();
        assertEquals(mesh.triangleCount(), faces);
    }
}
