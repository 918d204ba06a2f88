package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.SplineBasis;
import org.junit.jupiter.api.Test;

/**
 * The work of reading a big OBJ model, counted in bytes allocated rather than timed: a vertex
 * table that never copies itself, lines read where they lie, no knot vector made to check a
 * range, and one-piece Bézier surfaces whose patch keeps the surface's own points. Taking any of
 * these back raises the count past the bound: this grid allocated 3.2 KB a patch without the
 * last two (and 4.1 KB on the 100,000-patch model without all of them); now 1.8 KB, most of it
 * the patch and its surface, which the model keeps.
 */
class ObjReadCostTest {

    /** {@code side}² bicubic patches on a grid of shared vertices, one statement a line. */
    static String grid(int side) {
        StringBuilder sb = new StringBuilder("cstype bezier\ndeg 3 3\n");
        int row = 3 * side + 1;
        for (int j = 0; j < row; j++) {
            for (int i = 0; i < row; i++) {
                sb.append("v ").append(i * 0.25).append(' ').append(j * 0.25).append(' ')
                        .append(((i * 7 + j * 3) % 11) * 0.01).append('\n');
            }
        }
        for (int b = 0; b < side; b++) {
            for (int a = 0; a < side; a++) {
                sb.append("surf 0 1 0 1");
                for (int j = 0; j < 4; j++) {
                    for (int i = 0; i < 4; i++) {
                        sb.append(' ').append((3 * b + j) * row + 3 * a + i + 1);
                    }
                }
                sb.append("\nend\n");
            }
        }
        return sb.toString();
    }

    private static long allocatedBytes() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean()).getCurrentThreadAllocatedBytes();
    }

    private static ObjReader.Model read(byte[] bytes) throws IOException {
        return ObjReader.readModel(new TextSource(new ByteArrayInputStream(bytes), "grid.obj"));
    }

    @Test
    void aBigBicubicModelAllocatesLittleMoreThanItKeeps() throws IOException {
        int side = 60; // 3,600 patches on 32,761 vertices: past the vertex table's first blocks
        byte[] bytes = grid(side).getBytes(StandardCharsets.UTF_8);
        read(bytes); // classes loaded, caches filled
        long before = allocatedBytes();
        ObjReader.Model model = read(bytes);
        long perPatch = (allocatedBytes() - before) / model.patches().size();
        assertEquals(side * side, model.patches().size());
        assertTrue(perPatch < 2_200, "bytes allocated a patch: " + perPatch);
    }

    /** A {@code side}×{@code side} grid of vertices cut into two triangles a cell, plain {@code f a b c} faces. */
    static String mesh(int side) {
        StringBuilder sb = new StringBuilder();
        for (int j = 0; j < side; j++) {
            for (int i = 0; i < side; i++) {
                sb.append("v ").append(i * 0.5).append(' ').append(j * 0.5).append(' ').append((i * j) % 7 * 0.1)
                        .append('\n');
            }
        }
        for (int j = 0; j + 1 < side; j++) {
            for (int i = 0; i + 1 < side; i++) {
                int a = j * side + i + 1, b = a + 1, c = a + side, d = c + 1;
                sb.append("f ").append(a).append(' ').append(b).append(' ').append(d).append("\nf ").append(a)
                        .append(' ').append(d).append(' ').append(c).append('\n');
            }
        }
        return sb.toString();
    }

    @Test
    void aBigTriangleMeshAllocatesLittleMoreThanItKeeps() throws IOException {
        byte[] bytes = mesh(150).getBytes(StandardCharsets.UTF_8); // 22,500 vertices, 44,402 triangles
        read(bytes);
        long before = allocatedBytes();
        ObjReader.Model model = read(bytes);
        long perTriangle = (allocatedBytes() - before) / model.mesh().triangleCount();
        assertEquals(2 * 149 * 149, model.mesh().triangleCount());
        assertEquals(150 * 150, model.mesh().vertexCount()); // a plain corner is one mesh vertex per v
        // faces read in place and plain corners found by index: 140 B a triangle; split into
        // strings and hashed as (v, vt, vn) records, they took 690 B
        assertTrue(perTriangle < 250, "bytes allocated a triangle: " + perTriangle);
    }

    @Test
    void aOnePieceBezierSurfaceGivesThePatchTheDecompositionGives() {
        BezierPatch p = ObjReader.read(grid(1), "one.obj").get(0);
        FreeFormSurface bezier = p.origin().surface();
        // the same net as a clamped B-spline goes through the knot-insertion path
        double[] knots = {0, 0, 0, 0, 1, 1, 1, 1};
        FreeFormSurface bspline = new FreeFormSurface(SplineBasis.BSPLINE, 3, 3, knots, knots, 4, 4,
                bezier.points(), null, new double[] {0, 1, 0, 1}, null);
        assertEquals(bspline.toPatches(), bezier.toPatches());
        assertEquals(List.of(p), bezier.toPatches());
    }

    @Test
    void theVertexTableHoldsEveryVertexAcrossItsBlocks() {
        ObjVertices v = new ObjVertices();
        int n = 3 * ObjVertices.BLOCK + 5;
        for (int k = 0; k < n; k++) {
            v.add(k, -k, 0.5 * k, 1 + k % 3);
        }
        assertEquals(n, v.count());
        for (int k = 0; k < n; k += 97) {
            assertEquals(k, v.vertex(k, 0));
            assertEquals(-k, v.vertex(k, 1));
            assertEquals(0.5 * k, v.vertex(k, 2));
            assertEquals(1 + k % 3, v.vertex(k, 3));
        }
        assertEquals(-(double) (n - 1), v.vertex(ObjVertices.resolve(-1, n), 1));
    }
}
