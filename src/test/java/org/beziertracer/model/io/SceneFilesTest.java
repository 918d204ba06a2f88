package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Material;
import org.beziertracer.model.Plane;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SceneFilesTest {

    @TempDir
    Path dir;

    private static SceneDocument parse(String json) {
        return SceneFiles.parse(json, "test.json", null);
    }

    @Test
    void theBuiltInNamesAreTheModelsThenTheScenes() {
        assertEquals(List.of("patch", "teapot", "teacup", "teaspoon", "sphere", "torus", "trimmed-plate", "wavy6",
                "wavy10", "curved", "teapot-room", "studio"), BuiltIns.names());
    }

    @Test
    void thePatchSceneIsTheDefaultPatchLitFromTheEye() {
        SceneDocument doc = SceneFiles.load("patch");
        Scene scene = doc.scene();
        assertEquals(List.of(Models.flatGrid(4, 4)), scene.patches());
        assertTrue(scene.lights().isEmpty(), "no lights: the renderer puts one at the eye");
        assertTrue(scene.camera().isEmpty(), "no camera: the renderer frames the patch");
        assertEquals(List.of(Material.DEFAULT), scene.materials());
        assertTrue(scene.planes().isEmpty() && scene.spheres().isEmpty());
        assertEquals(RenderSettings.defaults(), doc.settings());
    }

    @Test
    void theTeapotRoomHasTheTeapotACheckeredFloorAMirrorAGlassSphereALightAndACamera() {
        SceneDocument doc = SceneFiles.load("teapot-room");
        Scene scene = doc.scene();
        assertEquals(32, scene.patchCount());
        assertEquals(Models.teapot().patches(), scene.patches(), "the teapot, untransformed");
        Material teapot = scene.materials().get(scene.patchMaterial(0));
        assertNotEquals(Material.DEFAULT, teapot);

        assertEquals(1, scene.planes().size());
        Plane floor = scene.planes().get(0);
        assertEquals(new Vec3(0, 0, 1), floor.normal());
        assertEquals(0, floor.point().z());
        assertTrue(scene.materials().get(floor.material()).checkerSquares() > 0, "checkered floor");

        assertEquals(2, scene.spheres().size());
        long mirrors = scene.spheres().stream().map(s -> scene.materials().get(s.material()))
                .filter(m -> m.reflectivity() >= 0.5 && m.transparency() == 0).count();
        List<Material> glass = scene.spheres().stream().map(s -> scene.materials().get(s.material()))
                .filter(m -> m.transparency() >= 0.8).toList();
        assertEquals(1, mirrors, "one mirror sphere");
        assertEquals(1, glass.size(), "one glass sphere");
        assertEquals(1.5, glass.get(0).ior());
        for (Sphere s : scene.spheres()) {
            assertEquals(s.radius(), s.center().z(), 1e-9, "sphere " + s + " rests on the floor");
        }

        assertEquals(List.of(new PointLight(new Vec3(-200, -350, 450))), scene.lights());
        CameraSpec camera = scene.camera().orElseThrow();
        assertEquals(new CameraSpec(new Vec3(-150, -420, 260), new Vec3(10, 0, 55), Vec3.Z, 40, 1), camera);
        assertTrue(doc.settings().shadows());
        assertEquals(5, doc.settings().maxDepth());
    }

    @Test
    void builtInScenesWinOverModelsAndOtherNamesFallBackToModels() {
        assertEquals(SceneFiles.load("PATCH").scene().patches(), Models.patch().patches());
        SceneDocument teapot = SceneFiles.load("teapot");
        assertEquals(32, teapot.scene().patchCount());
        assertTrue(teapot.scene().lights().isEmpty());
        assertTrue(teapot.scene().camera().isEmpty());
        assertEquals(RenderSettings.defaults(), teapot.settings());
    }

    @Test
    void aBareModelFileLoadsWithDefaultSettings() throws IOException {
        Path bpt = dir.resolve("one.bpt");
        BptWriter.write(bpt, List.of(Models.flatGrid(3, 4)));
        SceneDocument doc = SceneFiles.load(bpt.toString());
        assertEquals(List.of(Models.flatGrid(3, 4)), doc.scene().patches());
        assertEquals(RenderSettings.defaults(), doc.settings());
    }

    @Test
    void relativeModelFilesResolveAgainstTheSceneFilesDirectory() throws IOException {
        Path sub = Files.createDirectories(dir.resolve("scenes/models"));
        BptWriter.write(sub.resolve("grid.bpt"), List.of(Models.flatGrid(2, 3)));
        Path scene = dir.resolve("scenes/room.json");
        Files.writeString(scene, "{\"version\": 1, \"models\": [{\"file\": \"models/grid.bpt\"}]}");
        SceneDocument doc = SceneFiles.load(scene.toString());
        assertEquals(List.of(Models.flatGrid(2, 3)), doc.scene().patches());
        assertEquals(List.of(Material.DEFAULT), doc.scene().materials());
    }

    @Test
    void aTransformScalesThenRotatesXYZThenTranslatesEveryControlPointExactly() {
        // P00 of flatGrid(2,2) is (-1.5,-1.5,0); scale (2,1,1) → (-3,-1.5,0);
        // rotate 90° about z → (1.5,-3,0); translate (10,20,30) → (11.5,17,30)
        SceneDocument doc = parse("""
                {"version": 1, "models": [{"patches": [{"degree": [1, 1],
                   "points": [[-1.5, -1.5, 0], [1.5, -1.5, 0], [-1.5, 1.5, 0], [1.5, 1.5, 0]]}],
                 "transform": {"scale": [2, 1, 1], "rotate": [0, 0, 90], "translate": [10, 20, 30]}}]}
                """);
        BezierPatch p = doc.scene().patches().get(0);
        assertPoint(11.5, 17, 30, p, 0, 0);
        assertPoint(11.5, 23, 30, p, 1, 0);
        assertPoint(8.5, 17, 30, p, 0, 1);
    }

    @Test
    void rotationsAboutXThenYFollowTheRightHandRule() {
        SceneDocument doc = parse("""
                {"version": 1, "models": [{"patches": [{"degree": [1, 1],
                   "points": [[0, 1, 0], [0, 0, 1], [1, 0, 0], [2, 3, 4]]}],
                 "transform": {"rotate": [90, 0, 0], "scale": 2}}]}
                """);
        BezierPatch p = doc.scene().patches().get(0);
        assertPoint(0, 0, 2, p, 0, 0);  // y → z about x
        assertPoint(0, -2, 0, p, 1, 0); // z → -y about x
        assertPoint(2, 0, 0, p, 0, 1);
        assertPoint(4, -8, 6, p, 1, 1);

        SceneDocument aboutY = parse("""
                {"version": 1, "models": [{"builtin": "patch", "transform": {"rotate": [0, 90, 0]}}]}
                """);
        // about y: x → -z; P00 (-1.5,-1.5,0) → (0,-1.5,1.5)
        assertPoint(0, -1.5, 1.5, aboutY.scene().patches().get(0), 0, 0);
    }

    @Test
    void aGeneralTransformIsAnAffineMapOfTheSurface() {
        SceneDocument doc = parse("""
                {"version": 1, "models": [{"builtin": "teapot",
                 "transform": {"scale": 0.5, "rotate": [10, 20, 30], "translate": [1, 2, 3]}}]}
                """);
        ModelTransform t = new ModelTransform(new double[] {1, 2, 3}, new double[] {.5, .5, .5},
                new double[] {10, 20, 30});
        for (int k = 0; k < 32; k++) {
            assertEquals(t.apply(Models.teapot().patches().get(k), k + 1), doc.scene().patches().get(k), "patch " + k);
        }
        BezierPatch first = doc.scene().patches().get(0);
        double[] p = {Models.teapot().patches().get(0).get(0, 0, 0), Models.teapot().patches().get(0).get(0, 0, 1),
            Models.teapot().patches().get(0).get(0, 0, 2)};
        double len = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        double dx = first.get(0, 0, 0) - 1, dy = first.get(0, 0, 1) - 2, dz = first.get(0, 0, 2) - 3;
        assertEquals(0.5 * len, Math.sqrt(dx * dx + dy * dy + dz * dz), 1e-9, "rotation keeps lengths");
    }

    @Test
    void materialsAreNamedInlineOrDefaultAndShareIndicesWhenEqual() {
        SceneDocument doc = parse("""
                {"version": 1,
                 "materials": {"red": {"color": [1, 0, 0]}, "tiles": {"checker": 4}},
                 "planes": [{"point": [0, 0, 0], "normal": [0, 0, 2], "material": "tiles"}],
                 "spheres": [{"center": [0, 0, 1], "radius": 1, "material": "red"},
                             {"center": [3, 0, 1], "radius": 1},
                             {"center": [6, 0, 1], "radius": 1, "material": {"reflectivity": 1}},
                             {"center": [9, 0, 1], "radius": 1, "material": {"color": [1, 0, 0]}}]}
                """);
        Scene s = doc.scene();
        Material red = s.materials().get(0);
        assertEquals(1, red.r());
        assertEquals(Material.DEFAULT.specular(), red.specular());
        Material tiles = s.materials().get(1);
        assertEquals(4, tiles.checkerSquares());
        assertEquals(0.95, tiles.r2(), "second checker colour defaults to light grey");
        assertEquals(new Vec3(0, 0, 1), s.planes().get(0).normal());
        assertEquals(1, s.planes().get(0).material());
        assertEquals(List.of(0, 2, 3, 0), s.spheres().stream().map(Sphere::material).toList());
        assertEquals(Material.DEFAULT, s.materials().get(2));
        assertEquals(Material.DEFAULT.withReflection(1), s.materials().get(3));
    }

    @Test
    void writeThenReadGivesBackTheSameSceneAndSettings() throws IOException {
        Scene scene = Scene.builder()
                .addMaterial(Material.DEFAULT)
                .addMaterial(Material.diffuse(0.1, 0.2, 0.3).withChecker(8).withReflection(0.25))
                .addMaterial(Material.diffuse(1, 1, 1).withRefraction(0.9, 1.33))
                .addPatches(Models.teapot().patches().subList(0, 3), 1)
                .addPatches(List.of(Models.flatGrid(3, 5).withPoint(0, 0, -0.0, 1e-300, 1.0 / 3)), 2)
                .addPatches(List.of(Models.flatGrid(2, 2)), 1)
                .addPlane(new Plane(new Vec3(0, 0, -1), new Vec3(0, 0, 1), 1, 0.125))
                .addSphere(new Sphere(new Vec3(0.1, 0.2, 0.3), 7e-3, 2))
                .addLight(new PointLight(new Vec3(1, 2, 3), 0.5, 0.25, 1))
                .addLight(new PointLight(new Vec3(-1, -2, 1e6)))
                .camera(new CameraSpec(new Vec3(0, -5, 0), Vec3.ZERO, Vec3.Z, 0, 12.5))
                .build();
        RenderSettings settings = new RenderSettings(320, 240, 9, "adaptive", "newton", false, "normals", 6, false, 3);
        SceneDocument doc = new SceneDocument(scene, settings);
        Path file = dir.resolve("round.json");
        FileFormats.SCENE.write(file, doc);
        SceneDocument back = FileFormats.SCENE.read(file);
        assertSameContent(doc, back);
        assertEquals(SceneFiles.toJson(doc), Files.readString(file), "the file holds exactly toJson");
        assertEquals(SceneFiles.toJson(doc), SceneFiles.toJson(back), "a second round changes nothing");
        try (var files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList(), "no temporary file left behind");
        }
    }

    @Test
    void builtInScenesSurviveARoundTrip() throws IOException {
        for (String name : BuiltIns.names()) {
            SceneDocument doc = SceneFiles.load(name);
            Path file = dir.resolve(name + ".json");
            FileFormats.SCENE.write(file, doc);
            assertSameContent(doc, SceneFiles.load(file.toString()));
        }
    }

    private static void assertSameContent(SceneDocument expected, SceneDocument actual) {
        Scene a = expected.scene();
        Scene b = actual.scene();
        assertEquals(a.patches(), b.patches());
        for (int k = 0; k < a.patchCount(); k++) {
            assertEquals(a.patchMaterial(k), b.patchMaterial(k), "material of patch " + k);
        }
        assertEquals(a.planes(), b.planes());
        assertEquals(a.spheres(), b.spheres());
        assertEquals(a.materials(), b.materials());
        assertEquals(a.lights(), b.lights());
        assertEquals(a.camera(), b.camera());
        assertEquals(expected.settings(), actual.settings());
    }

    private static void assertPoint(double x, double y, double z, BezierPatch p, int i, int j) {
        String where = "P(" + i + "," + j + ") of " + p;
        assertEquals(x, p.get(i, j, 0), where + " x");
        assertEquals(y, p.get(i, j, 1), where + " y");
        assertEquals(z, p.get(i, j, 2), where + " z");
    }
}
