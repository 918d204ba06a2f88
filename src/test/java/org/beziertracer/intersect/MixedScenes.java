package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.Material;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Plane;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.beziertracer.model.io.SceneFiles;

/** Scenes that mix the kinds of leaves: patches, triangle meshes and spheres (and a plane). */
public final class MixedScenes {
    private MixedScenes() {}

    /**
     * The teapot (z up) over a floor mesh of {@code 2·n²} triangles with normals and uvs, beside a
     * pyramid mesh without normals or uvs, with two spheres; with {@code plane}, a plane far below.
     */
    public static Scene teapotOnFloor(int n, boolean plane) {
        Scene teapot = SceneFiles.load("teapot").scene();
        Aabb box = teapot.controlBounds();
        double size = box.diagonal();
        double z = box.minZ() - 0.02 * size;
        double x0 = box.minX() - size, x1 = box.maxX() + size, y0 = box.minY() - size, y1 = box.maxY() + size;
        Scene.Builder b = teapot.toBuilder();
        b.addMaterial(Material.DEFAULT);
        b.addMaterial(Material.DEFAULT.withChecker(4));
        b.addMaterial(Material.diffuse(0.2, 0.4, 0.9));
        b.addMesh(grid(n, x0, x1, y0, y1, z), 1);
        b.addMesh(pyramid(box.maxX() + 0.3 * size, box.minY(), z + 0.01 * size, 0.3 * size), 2); // not on the floor: no ties
        b.addSphere(new Sphere(new Vec3(box.minX() - 0.2 * size, box.maxY() + 0.1 * size, z + 0.15 * size),
                0.15 * size, 2));
        b.addSphere(new Sphere(new Vec3(box.maxX() + 0.1 * size, box.maxY() + 0.3 * size, z + 0.1 * size),
                0.1 * size, 0));
        if (plane) {
            b.addPlane(new Plane(new Vec3(0, 0, z - size), new Vec3(0, 0.1, 1)));
        }
        return b.build();
    }

    /** A flat {@code n×n}-quad grid at height {@code z}, each quad two triangles, normals up, uvs 0..1. */
    public static Mesh grid(int n, double x0, double x1, double y0, double y1, double z) {
        int side = n + 1;
        double[] positions = new double[3 * side * side], normals = new double[3 * side * side],
                uvs = new double[2 * side * side];
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                int v = j * side + i;
                positions[3 * v] = x0 + (x1 - x0) * i / n;
                positions[3 * v + 1] = y0 + (y1 - y0) * j / n;
                positions[3 * v + 2] = z;
                normals[3 * v + 2] = 1;
                uvs[2 * v] = (double) i / n;
                uvs[2 * v + 1] = (double) j / n;
            }
        }
        int[] tris = new int[6 * n * n];
        int t = 0;
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * side + i, bb = a + 1, c = a + side + 1, d = a + side;
                tris[t++] = a; tris[t++] = bb; tris[t++] = c;
                tris[t++] = a; tris[t++] = c; tris[t++] = d;
            }
        }
        return Mesh.faces(positions, normals, uvs, tris);
    }

    /** A square pyramid standing on {@code (x, y, z)}, edge {@code s}; no normals, no uvs. */
    public static Mesh pyramid(double x, double y, double z, double s) {
        double[] p = {x, y, z, x + s, y, z, x + s, y + s, z, x, y + s, z, x + s / 2, y + s / 2, z + s};
        int[] t = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4, 0, 3, 2, 0, 2, 1};
        return Mesh.faces(p, null, null, t);
    }

    /** The parts of {@code scene} as scenes of their own: patches only, meshes only, spheres only, planes only. */
    static List<Scene> parts(Scene scene) {
        Scene patches = scene.toBuilder().clearMeshes().spheres(List.of()).planes(List.of()).build();
        Scene meshes = scene.toBuilder().patches(List.of()).spheres(List.of()).planes(List.of()).build();
        Scene spheres = scene.toBuilder().patches(List.of()).clearMeshes().planes(List.of()).build();
        if (scene.planes().isEmpty()) {
            return List.of(patches, meshes, spheres);
        }
        Scene planes = scene.toBuilder().patches(List.of()).clearMeshes().spheres(List.of()).build();
        return List.of(patches, meshes, spheres, planes);
    }
}
