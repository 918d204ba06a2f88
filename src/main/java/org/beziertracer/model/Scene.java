package org.beziertracer.model;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.beziertracer.math.Aabb;

/**
 * An immutable scene: Bézier patches (each with a material index), triangle meshes (each with a
 * material index; an OBJ file's polygon faces), analytic planes and spheres, materials, point
 * lights and an optional camera.
 *
 * <p>All lists are copied and unmodifiable, so a {@code Scene} is a snapshot that render threads
 * may share. An edit builds a new {@code Scene} ({@link #withPatch}, {@link #toBuilder}).
 *
 * <p>Defaults: with no materials, every primitive uses {@link Material#DEFAULT}; with no lights
 * the renderer puts one white light at the eye (the memoir's light at the centre of projection);
 * with no camera the renderer frames the whole model.
 */
public final class Scene {

    private final List<BezierPatch> patches;
    private final int[] patchMaterial;
    private final List<Mesh> meshes;
    private final int[] meshMaterial;
    private final List<Plane> planes;
    private final List<Sphere> spheres;
    private final List<Material> materials;
    private final List<PointLight> lights;
    private final CameraSpec camera;
    private final List<Instance> instances;
    /** Per material, its physically based surface when the scene file gave one, else null. */
    private final Surface[] surfaces;
    private final List<AreaLight> areaLights;
    private final List<SpotLight> spotLights;
    private final Environment environment;

    /** A scene of Bézier patches only (at least one). */
    public Scene(List<BezierPatch> patches) {
        this(builder().patches(patches).requirePatches());
    }

    /** A scene of patches, planes and spheres; at least one primitive in all. */
    public Scene(List<BezierPatch> patches, List<Plane> planes, List<Sphere> spheres) {
        this(builder().patches(patches).planes(planes).spheres(spheres));
    }

    private Scene(Builder b) {
        this.patches = List.copyOf(b.patches);
        this.meshes = List.copyOf(b.meshes);
        this.planes = List.copyOf(b.planes);
        this.spheres = List.copyOf(b.spheres);
        this.materials = List.copyOf(b.materials.isEmpty() ? List.of(Material.DEFAULT) : b.materials);
        this.lights = List.copyOf(b.lights);
        this.camera = b.camera;
        this.instances = List.copyOf(b.instances);
        this.areaLights = List.copyOf(b.areaLights);
        this.spotLights = List.copyOf(b.spotLights);
        this.environment = b.environment;
        this.surfaces = new Surface[materials.size()];
        for (var e : b.surfaces.entrySet()) {
            checkMaterial("surface", e.getKey());
            surfaces[e.getKey()] = e.getValue();
        }
        if (b.requirePatches && patches.isEmpty()) {
            throw new IllegalArgumentException("a model needs at least one patch");
        }
        if (patches.isEmpty() && planes.isEmpty() && spheres.isEmpty() && meshes.isEmpty()) {
            throw new IllegalArgumentException("a scene needs at least one patch, mesh, plane or sphere");
        }
        patchMaterial = new int[patches.size()];
        for (int k = 0; k < patchMaterial.length; k++) {
            patchMaterial[k] = k < b.patchMaterial.size() ? b.patchMaterial.get(k) : 0;
            checkMaterial("patch ", k, patchMaterial[k]);
        }
        meshMaterial = new int[meshes.size()];
        for (int k = 0; k < meshMaterial.length; k++) {
            meshMaterial[k] = b.meshMaterial.get(k);
            checkMaterial("mesh ", k, meshMaterial[k]);
        }
        checkInstances();
        for (int k = 0; k < planes.size(); k++) {
            checkMaterial("plane ", k, planes.get(k).material());
        }
        for (int k = 0; k < spheres.size(); k++) {
            checkMaterial("sphere ", k, spheres.get(k).material());
        }
    }

    /** {@link #checkMaterial(String, int)} of item {@code what + k}, its name made only for the message. */
    private void checkMaterial(String what, int k, int index) {
        if (index < 0 || index >= materials.size()) {
            checkMaterial(what + k, index);
        }
    }

    private void checkMaterial(String what, int index) {
        if (index < 0 || index >= materials.size()) {
            throw new IllegalArgumentException(what + " uses material " + index + " but the scene has "
                    + materials.size() + " material(s)");
        }
    }

    /**
     * An instance's placed patches must be its model's, one for one: the same degrees, kind and
     * trim region (the values are the caller's {@link Placement} of the model's, not compared).
     */
    private void checkInstances() {
        int end = 0;
        for (Instance in : instances) {
            if (in.first() < end || in.first() + in.count() > patches.size()) {
                throw new IllegalArgumentException("instance of patches " + in.first() + ".." + (in.first() + in.count() - 1)
                        + " overlaps another or lies outside the scene's " + patches.size() + " patches");
            }
            for (int j = 0; j < in.count(); j++) {
                BezierPatch m = in.model().get(j), p = patches.get(in.first() + j);
                if (m.degreeU() != p.degreeU() || m.degreeV() != p.degreeV() || m.isRational() != p.isRational()
                        || m.trim() != p.trim()) {
                    throw new IllegalArgumentException("patch " + (in.first() + j) + " is not a placement of its model's patch " + j);
                }
            }
            end = in.first() + in.count();
        }
    }

    public List<BezierPatch> patches() { return patches; }

    /**
     * The uses of models in this scene, in patch order, not overlapping ({@link Instance}); patches
     * outside every instance are the scene's own. Empty unless the scene was built with
     * {@link Builder#addInstance}; an edit of a patch drops the instance that held it.
     */
    public List<Instance> instances() { return instances; }

    /** Triangle meshes (an OBJ file's polygon faces), beside the patches. */
    public List<Mesh> meshes() { return meshes; }

    /** Material index of mesh {@code k}. */
    public int meshMaterial(int k) { return meshMaterial[k]; }

    /** Triangles of every mesh. */
    public long triangleCount() {
        long n = 0;
        for (Mesh m : meshes) {
            n += m.triangleCount();
        }
        return n;
    }

    public List<Plane> planes() { return planes; }

    public List<Sphere> spheres() { return spheres; }

    /** Never empty: at least {@link Material#DEFAULT}. */
    public List<Material> materials() { return materials; }

    /** Material index of patch {@code k}. */
    public int patchMaterial(int k) { return patchMaterial[k]; }

    public List<PointLight> lights() { return lights; }

    /** The area lights (sphere and rect), for the path tracer. */
    public List<AreaLight> areaLights() { return areaLights; }

    /** The spot lights, for the path tracer. */
    public List<SpotLight> spotLights() { return spotLights; }

    /** The environment light, if the scene has one. */
    public Optional<Environment> environment() { return Optional.ofNullable(environment); }

    /** The physically based surface given for material {@code k}, or null (then {@link Surface#fromPhong}). */
    public Surface surface(int k) { return surfaces[k]; }

    /** Material {@code k}'s surface for the path tracer: the one given, else read from its Phong material. */
    public Surface surfaceOrPhong(int k) {
        return surfaces[k] != null ? surfaces[k] : Surface.fromPhong(materials.get(k));
    }

    public Optional<CameraSpec> camera() { return Optional.ofNullable(camera); }

    public int patchCount() { return patches.size(); }

    /** A copy of this scene with patch {@code index} replaced (same material). */
    public Scene withPatch(int index, BezierPatch patch) {
        var copy = new ArrayList<>(patches);
        copy.set(index, patch);
        Builder b = toBuilder().patches(copy);
        for (Instance in : instances) {
            if (!in.covers(index)) {
                b.instances.add(in);
            }
        }
        return b.build();
    }

    /**
     * Union of the control-point boxes of every patch (empty when there are none). Computed once
     * and kept (the patches never change): the read's finiteness check, {@code info} and the
     * intersector's scale all ask for it. The race of two first callers is benign: both compute
     * the same immutable record.
     */
    public Aabb controlBounds() {
        Aabb box = controlBounds;
        if (box == null) { // the union of the patches' control boxes, without a box object a patch
            double[] b = new double[6], u = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                    Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (BezierPatch p : patches) {
                p.controlBoundsInto(b);
                for (int c = 0; c < 3; c++) {
                    u[c] = Math.min(u[c], b[c]);
                    u[c + 3] = Math.max(u[c + 3], b[c + 3]);
                }
            }
            box = patches.isEmpty() ? Aabb.EMPTY : new Aabb(u[0], u[1], u[2], u[3], u[4], u[5]);
            controlBounds = box;
        }
        return box;
    }

    /** {@link #controlBounds()} once computed, else null. */
    private Aabb controlBounds;

    /**
     * The finite part of the model: the patches' control boxes and the meshes' vertex boxes
     * (empty when there are neither). Framing and extents use it; the patch solvers' scale
     * ({@link #controlBounds()}) does not count the meshes.
     */
    public Aabb bounds() {
        Aabb box = controlBounds();
        for (Mesh m : meshes) {
            box = box.union(m.bounds());
        }
        return box;
    }

    public Builder toBuilder() {
        Builder b = builder().patches(patches).planes(planes).spheres(spheres).lights(lights).camera(camera);
        b.materials.addAll(materials);
        for (int m : patchMaterial) {
            b.patchMaterial.add(m);
        }
        for (int k = 0; k < meshes.size(); k++) {
            b.addMesh(meshes.get(k), meshMaterial[k]);
        }
        b.instances.addAll(instances);
        b.areaLights.addAll(areaLights);
        b.spotLights.addAll(spotLights);
        b.environment = environment;
        for (int k = 0; k < surfaces.length; k++) {
            if (surfaces[k] != null) {
                b.surfaces.put(k, surfaces[k]);
            }
        }
        return b;
    }

    public static Builder builder() { return new Builder(); }

    /** Mutable builder; {@link #build()} validates. */
    public static final class Builder {
        private final List<BezierPatch> patches = new ArrayList<>();
        private final List<Integer> patchMaterial = new ArrayList<>();
        private final List<Mesh> meshes = new ArrayList<>();
        private final List<Integer> meshMaterial = new ArrayList<>();
        private final List<Plane> planes = new ArrayList<>();
        private final List<Sphere> spheres = new ArrayList<>();
        private final List<Material> materials = new ArrayList<>();
        private final List<PointLight> lights = new ArrayList<>();
        private final List<Instance> instances = new ArrayList<>();
        private CameraSpec camera;
        private boolean requirePatches;
        private final List<AreaLight> areaLights = new ArrayList<>();
        private final List<SpotLight> spotLights = new ArrayList<>();
        private final java.util.Map<Integer, Surface> surfaces = new java.util.HashMap<>();
        private Environment environment;

        /**
         * Replaces the patch list (materials of the patches are kept by index, default 0); the
         * instances are forgotten (the patches are the scene's own).
         */
        public Builder patches(List<BezierPatch> list) {
            patches.clear();
            patches.addAll(list);
            instances.clear();
            return this;
        }

        /**
         * Adds a use of {@code model}: its patches mapped by {@code placement}, given as
         * {@code placed} (made by the caller, who reports their errors), all with material
         * {@code material}. Every use of one model should pass the same unmodifiable
         * {@code model} list ({@code List.copyOf} keeps such a list as it is): the uses of one list
         * are split once.
         */
        public Builder addInstance(List<BezierPatch> model, List<BezierPatch> placed, Placement placement, int material) {
            if (placed.size() != model.size()) {
                throw new IllegalArgumentException(placed.size() + " placed patches for a model of " + model.size());
            }
            int first = patches.size();
            addPatches(placed, material);
            if (!placed.isEmpty()) {
                instances.add(new Instance(first, List.copyOf(model), placement));
            }
            return this;
        }

        /** Adds patches, all with material {@code material}. */
        public Builder addPatches(List<BezierPatch> list, int material) {
            while (patchMaterial.size() < patches.size()) {
                patchMaterial.add(0);
            }
            for (BezierPatch p : list) {
                patches.add(p);
                patchMaterial.add(material);
            }
            return this;
        }

        /** Adds a triangle mesh with material {@code material}. */
        public Builder addMesh(Mesh mesh, int material) {
            meshes.add(java.util.Objects.requireNonNull(mesh, "mesh"));
            meshMaterial.add(material);
            return this;
        }

        /** Removes every mesh. */
        public Builder clearMeshes() {
            meshes.clear();
            meshMaterial.clear();
            return this;
        }

        public Builder planes(List<Plane> list) { planes.clear(); planes.addAll(list); return this; }

        public Builder spheres(List<Sphere> list) { spheres.clear(); spheres.addAll(list); return this; }

        public Builder lights(List<PointLight> list) { lights.clear(); lights.addAll(list); return this; }

        public Builder addPlane(Plane p) { planes.add(p); return this; }

        public Builder addSphere(Sphere s) { spheres.add(s); return this; }

        public Builder addLight(PointLight l) { lights.add(l); return this; }

        public Builder addSpotLight(SpotLight l) { spotLights.add(java.util.Objects.requireNonNull(l)); return this; }

        public Builder addAreaLight(AreaLight l) { areaLights.add(java.util.Objects.requireNonNull(l)); return this; }

        /** The environment light (null: none). */
        public Builder environment(Environment e) { environment = e; return this; }

        /** Gives material {@code material} (an index) the physically based surface {@code s}. */
        public Builder surface(int material, Surface s) { surfaces.put(material, java.util.Objects.requireNonNull(s)); return this; }

        /** Adds a material and returns the builder; its index is the number of materials before. */
        public Builder addMaterial(Material m) { materials.add(m); return this; }

        public int materialCount() { return materials.size(); }

        public Builder camera(CameraSpec c) { camera = c; return this; }

        Builder requirePatches() { requirePatches = true; return this; }

        public Scene build() { return new Scene(this); }
    }
}
