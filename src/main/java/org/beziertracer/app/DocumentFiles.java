package org.beziertracer.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.geometry.Tessellator;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.io.AtomicFiles;
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

    /** Patches between two progress reports of a mesh export (each is {@value #MESH_SEGMENTS}² cells). */
    public static final int MESH_STEP = 64;

    /** As {@link #exportMesh(Path, Scene, WriteProgress)} without reports. */
    public static long exportMesh(Path file, Scene scene) throws IOException {
        return exportMesh(file, scene, WriteProgress.NONE);
    }

    /**
     * Tessellates every patch ({@value #MESH_SEGMENTS}² cells each, {@link Tessellator}) and writes
     * a triangle OBJ atomically, one patch at a time (only one patch's triangles are in memory),
     * telling {@code progress} the patches written every {@value #MESH_STEP}; when it throws, the
     * old file stays. Returns the number of triangles written.
     *
     * @throws IllegalArgumentException when the model has no patches
     */
    public static long exportMesh(Path file, Scene scene, WriteProgress progress) throws IOException {
        List<BezierPatch> patches = scene.patches();
        if (patches.isEmpty()) {
            throw new IllegalArgumentException("nothing to export as a mesh: the model has no patches");
        }
        int total = patches.size();
        long vertices = (long) (MESH_SEGMENTS + 1) * (MESH_SEGMENTS + 1), triangles = 2L * MESH_SEGMENTS * MESH_SEGMENTS;
        AtomicFiles.write(file, out -> {
            MeshObjWriter.header(out, total * vertices, total * triangles);
            for (int p = 0; p < total; p++) {
                Mesh piece = Tessellator.tessellate(patches.get(p), MESH_SEGMENTS);
                MeshObjWriter.writePiece(out, piece.positions(), piece.normals(), piece.uvs(), piece.triangles(),
                        p * vertices);
                progress.patch(p + 1, total, MESH_STEP);
            }
        });
        return total * triangles;
    }
}
