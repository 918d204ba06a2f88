package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Writes patches as Wavefront OBJ free-form surfaces, the form read by {@link ObjReader}. A plain
 * patch is written as
 * <pre>
 * cstype bezier
 * v x y z                     # (n+1)(m+1) vertices per patch, u fastest
 * deg n m
 * surf 0 1 0 1 1 2 3 4 \      # one row of control points per line (u fastest),
 *      5 6 7 8 …              # continued with a trailing backslash
 * parm u 0 1
 * parm v 0 1
 * end
 * </pre>
 * Rational patches get {@code cstype rat bezier} and {@code v x y z w}; patches with a domain
 * their range and {@code trim}/{@code hole} loops; a free-form surface read from a file whose
 * pieces are all still there is written back as it was read ({@link ObjSurfaceWriter}). Each
 * patch gets its own vertices (no sharing), written with the shortest round-trip number text, so
 * reading the file back gives equal patches bit for bit. Stateless and thread-safe.
 */
public final class ObjWriter {
    private ObjWriter() {}

    /** Writes the patches to {@code file} atomically (see {@link AtomicFiles}). */
    public static void write(Path file, List<BezierPatch> patches) throws IOException {
        AtomicFiles.write(file, out -> write(out, patches));
    }

    /** The OBJ text of the patches. */
    public static String toString(List<BezierPatch> patches) {
        return AtomicFiles.toText(out -> write(out, patches));
    }

    /** Writes OBJ text to {@code out} (not closed). */
    public static void write(Writer out, List<BezierPatch> patches) throws IOException {
        new ObjSurfaceWriter(out).write(patches);
    }

    /**
     * Writes the scene's patches and, after them, its meshes as {@code v}/{@code vt}/{@code vn}
     * and {@code f} statements (all in one file: reading it back gives the patches and one mesh
     * of all the triangles).
     */
    public static void write(Writer out, Scene scene) throws IOException {
        write(out, scene, WriteProgress.NONE);
    }

    /** As {@link #write(Writer, Scene)}, telling {@code progress} the patches written. */
    public static void write(Writer out, Scene scene, WriteProgress progress) throws IOException {
        new ObjSurfaceWriter(out).write(scene.patches(), scene.meshes(), progress);
    }

    /** Writes the scene's patches and meshes to {@code file} atomically (see {@link AtomicFiles}). */
    public static void write(Path file, Scene scene) throws IOException {
        AtomicFiles.write(file, out -> write(out, scene));
    }

    /** The OBJ text of the scene's patches and meshes. */
    public static String toString(Scene scene) {
        return AtomicFiles.toText(out -> write(out, scene));
    }
}
