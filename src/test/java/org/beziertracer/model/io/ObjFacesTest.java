package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * OBJ polygon faces ({@code v}, {@code vt}, {@code vn}, {@code f}) load as one triangle mesh beside
 * the free-form surfaces: quads and polygons as fans, negative indices, the v/vt/vn forms; their
 * errors name file and line; writing the scene and reading it back keeps the mesh; scene files
 * carry it.
 */
class ObjFacesTest {

    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    private static final String SURFACE = "v 0 0 2\nv 1 0 2\nv 0 1 2\nv 1 1 3\n"
            + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 -4 -3 -2 -1\nend\n";

    private static Mesh mesh(String text) {
        Mesh m = ObjReader.readModel(text, "m.obj").mesh();
        assertTrue(m != null, text);
        return m;
    }

    private static String fails(String text) {
        return UserMessages.of(ModelFormatException.class, () -> ObjReader.readModel(text, "bad.obj"));
    }

    private static void assertMessage(String text, String prefix, String... parts) {
        String msg = fails(text);
        assertTrue(msg.startsWith(prefix), () -> "message should start with \"" + prefix + "\": " + msg + "\n" + text);
        for (String part : parts) {
            assertTrue(msg.contains(part), () -> "message should contain \"" + part + "\": " + msg + "\n" + text);
        }
        assertFalse(msg.contains("\n"), () -> "one line: " + msg);
    }

    @Test
    void aQuadIsTwoTrianglesAndAPolygonAFan() {
        Mesh quad = mesh(SQUARE + "f 1 2 3 4\n");
        assertEquals(2, quad.triangleCount());
        assertEquals(4, quad.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, quad.triangles());
        assertFalse(quad.hasNormals() || quad.hasUvs(), "no vt or vn given");
        Mesh pentagon = mesh(SQUARE + "v 0.5 1.5 0\nf 1 2 3 5 4\n");
        assertEquals(3, pentagon.triangleCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3, 0, 3, 4}, pentagon.triangles());
        assertEquals(0.5, pentagon.position(3, 0), 0, "the fifth corner is vertex 5");
    }

    @Test
    void negativeIndicesCountBackFromTheLastVertex() {
        Mesh m = mesh(SQUARE + "f -4 -3 -2\nv 5 5 5\nf -1 -2 -3\n");
        assertEquals(2, m.triangleCount());
        assertEquals(5, m.position(m.triangleVertex(1, 0), 0), 0, "-1 after the fifth v is vertex 5");
        assertEquals(1, m.position(m.triangleVertex(1, 1), 1), 0, "-2 is vertex 4 (0, 1, 0)");
    }

    @Test
    void texturesAndNormalsAreUsedWhenEveryCornerGivesThem() {
        String attrs = "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 2\nvn 0 0 -1\n";
        Mesh full = mesh(SQUARE + attrs + "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
        assertTrue(full.hasUvs() && full.hasNormals());
        assertEquals(1, full.normal(0, 2), 0, "normals made unit");
        assertEquals(1, full.uv(2, 0), 0);
        assertEquals(1, full.uv(2, 1), 0);
        Mesh normals = mesh(SQUARE + attrs + "f 1//1 2//1 3//2\n");
        assertTrue(normals.hasNormals());
        assertFalse(normals.hasUvs());
        assertEquals(-1, normals.normal(2, 2), 0);
        Mesh uvs = mesh(SQUARE + attrs + "f 1/4 2/3 3/2\n");
        assertTrue(uvs.hasUvs());
        assertFalse(uvs.hasNormals());
        assertEquals(0, uvs.uv(0, 0), 0);
        assertEquals(1, uvs.uv(0, 1), 0);
        Mesh mixed = mesh(SQUARE + attrs + "f 1/1/1 2/2/1 3/3/1\nf 1 3 4\n");
        assertFalse(mixed.hasUvs() || mixed.hasNormals(), "a corner without them: the mesh has none");
        // the same v with two normals is two vertices
        Mesh split = mesh(SQUARE + attrs + "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n");
        assertEquals(6, split.vertexCount());
    }

    @Test
    void facesLoadBesideTheSurfacesWhichReadAsBefore() {
        List<BezierPatch> alone = ObjReader.read(SURFACE, "s.obj");
        ObjReader.Model both = ObjReader.readModel(SQUARE + "f 1 2 3 4\n" + SURFACE, "s.obj");
        assertEquals(alone, both.patches());
        assertEquals(2, both.mesh().triangleCount());
        assertNull(ObjReader.readModel(SURFACE, "s.obj").mesh(), "no faces, no mesh");
        Scene scene = SceneFiles.parse("{\"version\": 1, \"models\": [{\"patches\": [{\"degree\": [1, 1], "
                + "\"points\": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]}]}]}", "x.json", null).scene();
        assertTrue(scene.meshes().isEmpty());
        Scene faces = FileFormats.OBJ.read(new java.io.ByteArrayInputStream((SQUARE + "f 1 2 3\n").getBytes()),
                "faces.obj", null).scene();
        assertEquals(0, faces.patchCount(), "a file of faces only is a scene of one mesh");
        assertEquals(1, faces.meshes().size());
        assertEquals(0, faces.meshMaterial(0));
    }

    @Test
    void badFacesAreOneLineErrorsNamingFileAndLine() {
        assertMessage(SQUARE + "f 1 2 5\n", "bad.obj:5: ", "corner 3", "in 1..4", "index out of range");
        assertMessage(SQUARE + "f 1 -5 2\n", "bad.obj:5: ", "corner 2", "index out of range");
        assertMessage(SQUARE + "f 0 1 2\n", "bad.obj:5: ", "corner 1", "index out of range");
        assertMessage(SQUARE + "\nf 1 2\n", "bad.obj:6: ", "at least 3 vertex references", "found 2");
        assertMessage("f 1 2 3\n", "bad.obj:1: ", "no vertex (v) is defined before this line");
        assertMessage(SQUARE + "f 1/1 2/1 3/1\n", "bad.obj:5: ", "texture vertex", "no texture vertex (vt)");
        assertMessage(SQUARE + "vn 0 0 1\nf 1//1 2//2 3//1\n", "bad.obj:6: ", "normal index for corner 2",
                "in 1..1", "index out of range");
        assertMessage(SQUARE + "f 1/2/3/4 2 3\n", "bad.obj:5: ", "vertex reference (v, v/vt, v//vn or v/vt/vn)");
        assertMessage(SQUARE + "f a 2 3\n", "bad.obj:5: ", "vertex index for corner 1");
        assertMessage("v 0 0 0\nv NaN 0 0\n", "bad.obj:2: ", "finite number", "x coordinate of vertex 2");
        assertMessage(SQUARE + "vt 0 nan\n", "bad.obj:5: ", "finite number", "v of texture vertex 1");
        assertMessage(SQUARE + "vn 0 0\n", "bad.obj:5: ", "expected 3 coordinates after vn");
        assertMessage(SQUARE + "vn 0 inf 1\n", "bad.obj:5: ", "finite number", "normal 1");
        // through the format registry too: one line, no stack trace
        String msg = UserMessages.of(ModelFormatException.class, () -> FileFormats.OBJ.read(
                new java.io.ByteArrayInputStream((SQUARE + "f 1 2 9\n").getBytes()), "reg.obj", null));
        assertTrue(msg.startsWith("reg.obj:5: "), msg);
    }

    @Test
    void writingAndReadingBackKeepsTheMesh(@TempDir Path dir) throws Exception {
        Random random = new Random(7);
        for (String attrs : new String[] {"", "vt", "vn", "vt vn"}) {
            Scene scene = sceneWithMesh(random, attrs.contains("vn"), attrs.contains("vt"));
            String text = ObjWriter.toString(scene);
            ObjReader.Model back = ObjReader.readModel(text, "round.obj");
            assertEquals(scene.patches(), back.patches(), attrs + "\n" + text);
            assertEquals(scene.meshes().get(0), back.mesh(), attrs + "\n" + text);
            Path file = dir.resolve("round" + attrs.replace(' ', '-') + ".obj");
            FileFormats.OBJ.write(file, new SceneDocument(scene, RenderSettings.defaults()));
            Scene read = FileFormats.OBJ.read(file).scene();
            assertEquals(scene.meshes(), read.meshes(), attrs);
            assertEquals(scene.patches(), read.patches(), attrs);
            try (var listing = Files.list(dir)) {
                assertTrue(listing.allMatch(p -> p.toString().endsWith(".obj")), "no temporary file left");
            }
        }
        // a scene without meshes writes exactly what it wrote before
        Scene patches = Scene.builder().patches(ObjReader.read(SURFACE, "s.obj")).build();
        assertEquals(ObjWriter.toString(patches.patches()), ObjWriter.toString(patches));
    }

    private static Scene sceneWithMesh(Random random, boolean normals, boolean uvs) {
        int vertices = 12, triangles = 15;
        double[] p = new double[3 * vertices], n = normals ? new double[3 * vertices] : null,
                uv = uvs ? new double[2 * vertices] : null;
        for (int k = 0; k < p.length; k++) {
            p[k] = random.nextGaussian() * 3;
        }
        for (int k = 0; n != null && k < vertices; k++) {
            n[3 * k + k % 3] = k % 2 == 0 ? 1 : -1;
        }
        for (int k = 0; uv != null && k < uv.length; k++) {
            uv[k] = random.nextDouble();
        }
        int[] t = new int[3 * triangles];
        for (int k = 0; k < triangles; k++) {
            // every vertex used, in order of first use (as a reader numbers them)
            t[3 * k] = k % vertices;
            t[3 * k + 1] = (k + 1) % vertices;
            t[3 * k + 2] = (k + 2) % vertices;
        }
        Mesh mesh = Mesh.faces(p, n, uv, t);
        return Scene.builder().patches(ObjReader.read(SURFACE, "s.obj")).addMesh(mesh, 0).build();
    }

    @Test
    void aSceneFileListingAnObjWithFacesHoldsItsMeshWithTheModelsMaterialAndTransform(@TempDir Path dir)
            throws Exception {
        Files.writeString(dir.resolve("floor.obj"), SQUARE + "vn 0 0 1\nf 1//1 2//1 3//1 4//1\n" + SURFACE);
        String json = "{\"version\": 1, \"materials\": {\"a\": {\"color\": [1, 0, 0]}, \"b\": {\"color\": [0, 0, 1]}},"
                + " \"models\": [{\"builtin\": \"patch\", \"material\": \"a\"},"
                + " {\"file\": \"floor.obj\", \"material\": \"b\", \"transform\": {\"translate\": [10, 0, 0],"
                + " \"scale\": 2, \"rotate\": [90, 0, 0]}}]}";
        Files.writeString(dir.resolve("s.json"), json);
        Scene scene = FileFormats.SCENE.read(dir.resolve("s.json")).scene();
        assertEquals(1, scene.meshes().size());
        assertEquals(1, scene.meshMaterial(0));
        Mesh m = scene.meshes().get(0);
        assertEquals(2, m.triangleCount());
        assertEquals(12, m.position(2, 0), 1e-12, "(1,1,0) scaled by 2, turned about x, moved by 10 in x");
        assertEquals(0, m.position(2, 1), 1e-12);
        assertEquals(2, m.position(2, 2), 1e-12);
        assertEquals(-1, m.normal(0, 1), 1e-12, "the normal +z turned about x by 90 degrees is -y");
        // written as a scene file and read back: the mesh is inline, equal
        SceneDocument doc = new SceneDocument(scene, RenderSettings.defaults());
        Scene back = SceneFiles.parse(SceneFiles.toJson(doc), "back.json", null).scene();
        assertEquals(scene.meshes(), back.meshes());
        assertEquals(scene.meshMaterial(0), back.meshMaterial(0));
        assertEquals(scene.patches(), back.patches());
        // a bad inline mesh names its JSON path
        String bad = "{\"version\": 1, \"models\": [{\"mesh\": {\"positions\": [[0,0,0],[1,0,0],[0,1,0]],"
                + " \"triangles\": [[0, 1, 3]]}}]}";
        String msg = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse(bad, "bad.json", null));
        assertTrue(msg.startsWith("bad.json") && msg.contains("out of range"), msg);
    }
}
