package org.beziertracer.geometry;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.junit.jupiter.api.Test;

class TessellatorTest {

    /** Triangles with a smaller area (relative to the squared teapot size) count as degenerate. */
    private static final double DEGENERATE_AREA = 1e-9;

    @Test
    void theTeapotGivesAUniformGridPerPatchWithMatchingCounts() {
        List<BezierPatch> teapot = TestNets.teapot();
        int k = 8;
        Mesh mesh = Tessellator.tessellate(teapot, k);
        assertEquals(32 * (k + 1) * (k + 1), mesh.vertexCount());
        assertEquals(32 * 2 * k * k, mesh.triangleCount());
        assertEquals(5, mesh.patchOfTriangle(5 * 2 * k * k), "first triangle of patch 5");
        assertEquals(31, mesh.patchOfTriangle(mesh.triangleCount() - 1));
    }

    @Test
    void verticesLieOnTheSurfaceWithUnitNormalsAndTheirParameters() {
        List<BezierPatch> teapot = TestNets.teapot();
        int k = 5;
        Mesh mesh = Tessellator.tessellate(teapot, k);
        for (int p = 0; p < teapot.size(); p++) {
            double[] net = teapot.get(p).copyNet();
            for (int b = 0; b <= k; b++) {
                for (int a = 0; a <= k; a++) {
                    int vert = p * (k + 1) * (k + 1) + b * (k + 1) + a;
                    double u = (double) a / k, v = (double) b / k;
                    String where = "patch " + p + " vertex (" + a + "," + b + ")";
                    assertEquals(u, mesh.uv(vert, 0), 0, where + " u");
                    assertEquals(v, mesh.uv(vert, 1), 0, where + " v");
                    double[] s = TestNets.eval(net, 0, 3, 3, 3, u, v);
                    double len = 0;
                    for (int c = 0; c < 3; c++) {
                        assertEquals(s[c], mesh.position(vert, c), ROUNDING * 100, where + " position");
                        len += mesh.normal(vert, c) * mesh.normal(vert, c);
                    }
                    assertEquals(1, Math.sqrt(len), ROUNDING, where + " normal length");
                }
            }
        }
    }

    @Test
    void trianglesWindCounterClockwiseAroundTheVertexNormals() {
        Mesh mesh = Tessellator.tessellate(TestNets.teapot(), 12);
        int checked = 0;
        for (int t = 0; t < mesh.triangleCount(); t++) {
            int a = mesh.triangleVertex(t, 0), b = mesh.triangleVertex(t, 1), c = mesh.triangleVertex(t, 2);
            double[] e1 = new double[3], e2 = new double[3], avg = new double[3];
            for (int i = 0; i < 3; i++) {
                e1[i] = mesh.position(b, i) - mesh.position(a, i);
                e2[i] = mesh.position(c, i) - mesh.position(a, i);
                avg[i] = mesh.normal(a, i) + mesh.normal(b, i) + mesh.normal(c, i);
            }
            double gx = e1[1] * e2[2] - e1[2] * e2[1], gy = e1[2] * e2[0] - e1[0] * e2[2], gz = e1[0] * e2[1] - e1[1] * e2[0];
            double area = Math.sqrt(gx * gx + gy * gy + gz * gz);
            if (area < DEGENERATE_AREA * 240 * 240) {
                continue;   // zero-area triangle at a collapsed edge
            }
            checked++;
            double dot = gx * avg[0] + gy * avg[1] + gz * avg[2];
            assertTrue(dot > 0, "triangle " + t + " of patch " + mesh.patchOfTriangle(t) + " winds against its normals");
        }
        assertTrue(checked > mesh.triangleCount() * 9 / 10, "checked only " + checked + " triangles");
    }

    @Test
    void aSegmentCountOutOfRangeIsRejected() {
        List<BezierPatch> teapot = TestNets.teapot();
        String e = UserMessages.of(IllegalArgumentException.class, () -> Tessellator.tessellate(teapot, 0));
        assertTrue(e.contains("got 0"), e);
        UserMessages.of(IllegalArgumentException.class, () -> Tessellator.tessellate(List.of(), 4));
    }

    @Test
    void theOnePatchFormIsTheListFormOfThatPatch() {
        BezierPatch lid = TestNets.teapot().get(28);
        Mesh one = Tessellator.tessellate(lid, 4), list = Tessellator.tessellate(List.of(lid), 4);
        assertEquals(list.triangleCount(), one.triangleCount());
        org.junit.jupiter.api.Assertions.assertArrayEquals(list.positions(), one.positions(), 0);
        assertEquals(0, one.patchOfTriangle(one.triangleCount() - 1));
    }
}
