package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class MeshObjWriterTest {

    // A unit square in z = 0 as two triangles
    private static final double[] POSITIONS = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    private static final double[] NORMALS = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    private static final double[] UVS = {0, 0, 1, 0, 1, 1, 0, 0.5};
    private static final int[] TRIANGLES = {0, 1, 2, 0, 2, 3};

    @TempDir
    Path dir;

    private static String write(double[] normals, double[] uvs) throws IOException {
        StringWriter out = new StringWriter();
        MeshObjWriter.write(out, POSITIONS, normals, uvs, TRIANGLES);
        return out.toString();
    }

    @Test
    void aTinyMeshIsWrittenWithOneBasedVTVnIndices() throws IOException {
        String text = write(NORMALS, UVS);
        String body = text.substring(text.indexOf('\n') + 1);
        assertEquals("""
                v 0 0 0
                v 1 0 0
                v 1 1 0
                v 0 1 0
                vt 0 0
                vt 1 0
                vt 1 1
                vt 0 0.5
                vn 0 0 1
                vn 0 0 1
                vn 0 0 1
                vn 0 0 1
                f 1/1/1 2/2/2 3/3/3
                f 1/1/1 3/3/3 4/4/4
                """, body);
        assertTrue(text.startsWith("# "), text);
    }

    @Test
    void aSecondPieceCountsTheVerticesOfTheFirst() throws IOException {
        StringWriter out = new StringWriter();
        MeshObjWriter.header(out, 8, 4);
        MeshObjWriter.writePiece(out, POSITIONS, null, null, TRIANGLES, 0);
        MeshObjWriter.writePiece(out, POSITIONS, null, null, TRIANGLES, 4);
        String text = out.toString();
        assertTrue(text.startsWith("# Bézier Tracer mesh: 8 vertices, 4 triangles\n"), text);
        assertTrue(text.endsWith("""
                v 0 1 0
                f 1 2 3
                f 1 3 4
                v 0 0 0
                v 1 0 0
                v 1 1 0
                v 0 1 0
                f 5 6 7
                f 5 7 8
                """), text);
        UserMessages.of(IllegalArgumentException.class,
                () -> MeshObjWriter.writePiece(out, POSITIONS, null, null, new int[] {0, 1, 4}, 4));
    }

    @Test
    void missingNormalsOrUvsChangeTheFaceForm() throws IOException {
        assertTrue(write(null, UVS).contains("f 1/1 2/2 3/3\n"));
        assertTrue(write(NORMALS, null).contains("f 1//1 2//2 3//3\n"));
        String plain = write(null, null);
        assertTrue(plain.contains("f 1 3 4\n"), plain);
        assertTrue(!plain.contains("vt") && !plain.contains("vn"), plain);
    }

    @Test
    void inconsistentArraysAreRejectedBeforeWriting() {
        StringWriter out = new StringWriter();
        UserMessages.of(IllegalArgumentException.class,
                () -> MeshObjWriter.write(out, new double[] {0, 0}, null, null, new int[0]));
        UserMessages.of(IllegalArgumentException.class,
                () -> MeshObjWriter.write(out, POSITIONS, new double[3], null, TRIANGLES));
        UserMessages.of(IllegalArgumentException.class,
                () -> MeshObjWriter.write(out, POSITIONS, null, new double[3], TRIANGLES));
        String e = UserMessages.of(IllegalArgumentException.class,
                () -> MeshObjWriter.write(out, POSITIONS, null, null, new int[] {0, 1, 4}));
        assertTrue(e.contains("vertex 4"), e);
        assertEquals("", out.toString());
    }

    @Test
    void savingToAFileWritesTheSameText() throws IOException {
        Path file = dir.resolve("mesh.obj");
        MeshObjWriter.write(file, POSITIONS, NORMALS, UVS, TRIANGLES);
        assertEquals(write(NORMALS, UVS), Files.readString(file));
    }
}
