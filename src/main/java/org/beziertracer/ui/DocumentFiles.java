package org.beziertracer.ui;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

import javax.imageio.ImageIO;

import org.beziertracer.geometry.Tessellator;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.AtomicFiles;
import org.beziertracer.model.io.Models;
import org.beziertracer.model.io.MeshObjWriter;

/**
 * File → Save, Export PNG and Export Mesh. Every write is atomic (temporary file in the target
 * folder, then rename), so a failed save never leaves a half-written file. Stateless.
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

    /** Writes the picture as PNG. */
    public static void exportPng(Path file, BufferedImage image) throws IOException {
        AtomicFiles.writeBytes(file, out -> {
            if (!ImageIO.write(image, "png", out)) {
                throw new IOException("no PNG writer available");
            }
        });
    }

    /** Tessellates every patch ({@value #MESH_SEGMENTS}² cells each) and writes a triangle OBJ. */
    public static Mesh exportMesh(Path file, Scene scene) throws IOException {
        Mesh mesh = Tessellator.tessellate(scene.patches(), MESH_SEGMENTS);
        MeshObjWriter.write(file, mesh.positions(), mesh.normals(), mesh.uvs(), mesh.triangles());
        return mesh;
    }
}
