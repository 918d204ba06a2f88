package org.beziertracer.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

import org.beziertracer.geometry.Tessellator;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.beziertracer.model.io.MeshObjWriter;

/**
 * File → Save and Export Mesh (the picture's PNG is drawn and encoded by the desktop). Every write
 * is atomic (temporary file in the target folder, then rename), so a failed save never leaves a
 * half-written file. Stateless; the callers run it off the UI thread.
 */
public final class DocumentFiles {
    private DocumentFiles() {}

    /** Cells per patch side of an exported mesh. */
    public static final int MESH_SEGMENTS = 16;

    /** Saves the patches of {@code scene} as BPT or OBJ by the file's extension. */
    public static void saveModel(Path file, Scene scene) throws IOException {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!name.endsWith(".bpt") && !name.endsWith(".obj")) {
            throw new IllegalArgumentException(file + ": save as .bpt or .obj");
        }
        Models.save(file, scene.patches());
    }

    /** Tessellates every patch ({@value #MESH_SEGMENTS}² cells each) and writes a triangle OBJ. */
    public static Mesh exportMesh(Path file, Scene scene) throws IOException {
        Mesh mesh = Tessellator.tessellate(scene.patches(), MESH_SEGMENTS);
        MeshObjWriter.write(file, mesh.positions(), mesh.normals(), mesh.uvs(), mesh.triangles());
        return mesh;
    }
}
