package org.beziertracer.intersect;

/**
 * Mutable record of the closest hit found so far; one per thread, reused for every ray.
 * A solver fills only {@code t, u, v} and the primitive; the surface point is evaluated
 * afterwards by {@link SceneIntersector#surfacePoint}.
 */
public final class Hit {
    /** Primitive kinds. */
    public static final int PATCH = 0, PLANE = 1, SPHERE = 2, TRIANGLE = 3;

    /** Ray parameter along the direction as given (not normalised). */
    public double t;
    /** Surface parameters: for a patch, its own [0,1]² domain; for planes and spheres, texture coordinates. */
    public double u, v;
    /** {@link #PATCH}, {@link #PLANE}, {@link #SPHERE} or {@link #TRIANGLE} (a triangle of one of the scene's meshes). */
    public int kind;
    /** Index of the patch, plane, sphere or mesh in the scene. */
    public int index;
    /**
     * Sub-patch (BVH leaf) that produced a patch hit; in tessellated mode the triangle; for a
     * mesh triangle the triangle among all the scene's mesh triangles; for a sphere the sphere;
     * -1 for planes.
     */
    public int subPatch;
    /**
     * Triangle hits (tessellated mode, {@link #TRIANGLE}): barycentric weights of the hit
     * triangle's second and third corner (the first is {@code 1 - b1 - b2}); {@code u, v} are
     * interpolated with them.
     */
    public double b1, b2;

    public void set(Hit o) {
        t = o.t; u = o.u; v = o.v; kind = o.kind; index = o.index; subPatch = o.subPatch; b1 = o.b1; b2 = o.b2;
    }

    @Override
    public String toString() {
        return "Hit[t=" + t + ", u=" + u + ", v=" + v + ", kind=" + kind + ", index=" + index + "]";
    }
}
