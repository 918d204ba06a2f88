package org.beziertracer.model;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

class MeshTest {

    private static double[] square() { return new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}; }

    private static double[] up() { return new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}; }

    private static double[] uvs() { return new double[] {0, 0, 1, 0, 1, 1, 0, 1}; }

    @Test
    void aMeshCopiesItsArraysAndReportsItsLayout() {
        double[] pos = square();
        int[] tris = {0, 1, 2, 0, 2, 3};
        Mesh mesh = new Mesh(pos, up(), uvs(), tris, new int[] {0, 0});
        pos[0] = 99;
        tris[0] = 3;
        assertEquals(0, mesh.position(0, 0), "constructor must copy positions");
        assertEquals(0, mesh.triangleVertex(0, 0), "constructor must copy triangles");
        mesh.positions()[0] = 42;
        assertEquals(0, mesh.position(0, 0), "accessor must return a copy");
        assertEquals(4, mesh.vertexCount());
        assertEquals(2, mesh.triangleCount());
        assertEquals(1, mesh.uv(2, 1));
        assertEquals(1, mesh.normal(3, 2));
        assertArrayEquals(new int[] {0, 0}, mesh.patchOfTriangle());
        assertEquals(new Mesh(square(), up(), uvs(), new int[] {0, 1, 2, 0, 2, 3}, new int[] {0, 0}), mesh);
    }

    @Test
    void inconsistentArraysAreRejectedWithAClearMessage() {
        String e = UserMessages.of(IllegalArgumentException.class,
                () -> new Mesh(square(), new double[3], uvs(), new int[] {0, 1, 2}, new int[] {0}));
        assertTrue(e.contains("4 vertices"), e);
        e = UserMessages.of(IllegalArgumentException.class,
                () -> new Mesh(square(), up(), uvs(), new int[] {0, 1, 4}, new int[] {0}));
        assertTrue(e.contains("vertex 4"), e);
        e = UserMessages.of(IllegalArgumentException.class,
                () -> new Mesh(square(), up(), uvs(), new int[] {0, 1, 2}, new int[] {0, 0}));
        assertTrue(e.contains("patchOfTriangle"), e);
        double[] bad = square();
        bad[4] = Double.NaN;
        e = UserMessages.of(IllegalArgumentException.class,
                () -> new Mesh(bad, up(), uvs(), new int[] {0, 1, 2}, new int[] {0}));
        assertTrue(e.contains("positions[4]"), e);
    }
}
