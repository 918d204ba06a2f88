package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.FileFormats;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The app with an OBJ file whose polygon faces are a triangle mesh: it opens with the mesh, frames
 * it, keeps it through a patch edit (the render snapshot is patched, not rebuilt) and saves it back.
 */
class MeshDocumentTest {

    @TempDir
    Path dir;

    private final FakeDialogs dialogs = new FakeDialogs();
    private final AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());

    private static final String FILE = "v -5 -5 -1\nv 5 -5 -1\nv 5 5 -1\nv -5 5 -1\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n"
            + "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 -4 -3 -2 -1\nend\n";

    @Test
    void anObjWithFacesOpensEditsAndSavesWithItsMesh() throws Exception {
        Path obj = Files.writeString(dir.resolve("floor.obj"), FILE);
        app.files().open(obj);
        assertTrue(dialogs.errors.isEmpty(), dialogs.errors.toString());
        Scene scene = app.document().scene();
        assertEquals(1, scene.patchCount());
        assertEquals(1, scene.meshes().size());
        assertEquals(2, scene.meshes().get(0).triangleCount());
        assertEquals(-5, scene.bounds().minX(), 0, "the framing box holds the floor");
        // a patch edit keeps the mesh, and the render snapshot is patched, not rebuilt
        IntersectOptions io = IntersectOptions.defaults();
        SceneIntersector before = SnapshotCache.update(null, scene, io);
        BezierPatch p = scene.patches().get(0);
        double[] net = p.copyNet();
        net[2] += 0.25;
        Scene edited = scene.withPatch(0, p.withNet(net));
        assertSame(scene.meshes().get(0), edited.meshes().get(0));
        SceneIntersector after = SnapshotCache.update(before, edited, io);
        assertSame(edited, after.scene());
        assertEquals(before.primitiveCount(), after.primitiveCount());
        // saved as OBJ: the faces are written back
        Path saved = dir.resolve("saved.obj");
        app.files().saveTo(saved, () -> {});
        Scene back = FileFormats.OBJ.read(saved).scene();
        assertEquals(scene.meshes(), back.meshes());
        assertEquals(scene.patches(), back.patches());
    }
}
