package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.beziertracer.geometry.Tessellator;
import org.beziertracer.model.Mesh;
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
    void meshExportsAreCompleteAndReadBackAsTheTessellation() throws IOException {
        Path obj = dir.resolve("m.obj");
        Scene teapot = Models.teapot();
        long triangles = DocumentFiles.exportMesh(obj, teapot);
        assertEquals(32 * 2 * DocumentFiles.MESH_SEGMENTS * DocumentFiles.MESH_SEGMENTS, triangles);
        long faces = Files.readAllLines(obj).stream().filter(l -> l.startsWith("f ")).count();
        assertEquals(triangles, faces);
        // Written a patch at a time, the file reads back as the whole model's tessellation, corner for corner
        Mesh expected = Tessellator.tessellate(teapot.patches(), DocumentFiles.MESH_SEGMENTS);
        Mesh read = Models.load(obj.toString()).meshes().get(0);
        assertEquals(expected.triangleCount(), read.triangleCount());
        for (int t = 0; t < expected.triangleCount(); t++) {
            for (int c = 0; c < 3; c++) {
                int e = expected.triangleVertex(t, c), r = read.triangleVertex(t, c);
                for (int k = 0; k < 3; k++) {
                    assertEquals(expected.position(e, k), read.position(r, k), "triangle " + t + " corner " + c);
                }
                assertEquals(expected.uv(e, 0), read.uv(r, 0), "triangle " + t + " corner " + c);
                assertEquals(expected.uv(e, 1), read.uv(r, 1), "triangle " + t + " corner " + c);
            }
        }
    }

    @Test
    void aModelWithoutPatchesIsNoMeshAndLeavesNoFile() {
        Scene spheres = Scene.builder().addSphere(new org.beziertracer.model.Sphere(org.beziertracer.math.Vec3.ZERO, 1))
                .build();
        UserMessages.of(IllegalArgumentException.class, () -> DocumentFiles.exportMesh(dir.resolve("none.obj"), spheres));
        assertFalse(Files.exists(dir.resolve("none.obj")));
    }
}
