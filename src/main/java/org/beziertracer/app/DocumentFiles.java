package org.beziertracer.app;

import java.io.IOException;
import java.nio.file.Path;

import org.beziertracer.geometry.Tessellator;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.io.FileFormat;
import org.beziertracer.model.io.MeshObjWriter;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.WriteProgress;

/**
 * File → Save and Export Mesh (the picture's PNG is drawn and encoded by the desktop). Every write
 * is atomic (temporary file in the target folder, then rename), so a failed save never leaves a
 * half-written file. Stateless; the callers run it off the UI thread.
 */
public final class DocumentFiles {
    private DocumentFiles() {}

    /** Cells per patch side of an exported mesh. */
    public static final int MESH_SEGMENTS = 16;

    /** Saves the surfaces of {@code scene} in the model format its extension names ({@link ModelLoader#SAVE_FORMATS}). */
    public static void saveModel(Path file, Scene scene) throws IOException {
        saveModel(file, scene, WriteProgress.NONE);
    }

    /** As {@link #saveModel(Path, Scene)}, telling {@code progress} the patches written; when it throws, the old file stays. */
    public static void saveModel(Path file, Scene scene, WriteProgress progress) throws IOException {
        FileFormat format = ModelLoader.SAVE_FORMATS.stream().filter(f -> f.matches(file.toString())).findFirst()
                .orElseThrow(() -> new IllegalArgumentException(file + ": save as "
                        + org.beziertracer.model.io.FileFormats.extensionList(ModelLoader.SAVE_FORMATS)));
        format.write(file, new SceneDocument(scene, RenderSettings.defaults()), progress);
    }

    /** Tessellates every patch ({@value #MESH_SEGMENTS}² cells each) and writes a triangle OBJ. */
    public static Mesh exportMesh(Path file, Scene scene) throws IOException {
        Mesh mesh = Tessellator.tessellate(scene.patches(), MESH_SEGMENTS);
        MeshObjWriter.write(file, mesh.positions(), mesh.normals(), mesh.uvs(), mesh.triangles());
        return mesh;
    }
}
