package org.beziertracer.render;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.intersect.Hit;
import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.AreaLight;
import org.beziertracer.model.Environment;
import org.beziertracer.model.Material;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;
import org.beziertracer.model.SpotLight;
import org.beziertracer.render.bsdf.Bsdf;
import org.beziertracer.render.bsdf.Conductor;
import org.beziertracer.render.bsdf.Dielectric;
import org.beziertracer.render.bsdf.Diffuse;
import org.beziertracer.render.bsdf.Plastic;
import org.beziertracer.render.light.ConstantEnvironment;
import org.beziertracer.render.light.ImageEnvironment;
import org.beziertracer.render.light.Light;
import org.beziertracer.render.light.PointSource;
import org.beziertracer.render.light.RectLight;
import org.beziertracer.render.light.SphereLight;
import org.beziertracer.render.light.SpotSource;

/**
 * A job's data for the path tracer, built once per render and shared read-only by the workers:
 * one {@link Bsdf} per material ({@link Scene#surfaceOrPhong}), its colours (base, and the second
 * colour of its checker) in {@code colours[6k ..]}, its checker squares, its texture, and the lights.
 *
 * <p>Lights: the scene's area lights and environment; its point lights (or the job's, or with no
 * light at all one at the eye, as the Whitted renderer does) become inverse-square sources whose
 * intensity is {@code colour · d²}, d the distance from the light to the centre of the scene's
 * bounds (spot lights likewise): the centre is lit as brightly as the Whitted renderer (which has no fall-off) lights it.
 */
final class PathScene {
    final Bsdf[] bsdfs;
    final double[] colours;
    final int[] checker;
    /** Per material, its texture or null ({@link ShadingScene#textures}). */
    final SurfaceTexture[] textures;
    final Light[] lights;
    /** The environment among {@link #lights}, or null. */
    final Light environment;
    /** The area lights among {@link #lights} (rays may meet them). */
    final Light[] areaLights;
    final PathOptions options;

    PathScene(RenderJob job, ShadingScene shading) {
        Scene scene = job.scene();
        List<Material> mats = scene.materials();
        int n = mats.size();
        bsdfs = new Bsdf[n];
        colours = new double[6 * n];
        checker = new int[n];
        textures = shading.textures;
        for (int k = 0; k < n; k++) {
            Surface s = scene.surfaceOrPhong(k);
            bsdfs[k] = bsdf(s);
            double[] row = {s.r(), s.g(), s.b()};
            System.arraycopy(row, 0, colours, 6 * k, 3);
            Material m = mats.get(k);
            checker[k] = m.checkerSquares();
            boolean noSecond = m.r2() == 0 && m.g2() == 0 && m.b2() == 0;
            colours[6 * k + 3] = noSecond ? ShadingScene.CHECKER_LIGHT : Math.min(1, m.r2());
            colours[6 * k + 4] = noSecond ? ShadingScene.CHECKER_LIGHT : Math.min(1, m.g2());
            colours[6 * k + 5] = noSecond ? ShadingScene.CHECKER_LIGHT : Math.min(1, m.b2());
        }
        List<Light> all = new ArrayList<>(), area = new ArrayList<>();
        for (AreaLight a : scene.areaLights()) {
            double[] l = a.radiance();
            Light light = a.shape() == AreaLight.Shape.SPHERE
                    ? new SphereLight(a.center().x(), a.center().y(), a.center().z(), a.radius(), l[0], l[1], l[2])
                    : new RectLight(xyz(a.corner()), xyz(a.edge1()), xyz(a.edge2()), l[0], l[1], l[2]);
            all.add(light);
            area.add(light);
        }
        Light env = null;
        if (scene.environment().isPresent()) {
            Environment e = scene.environment().get();
            env = e.picture() != null ? new ImageEnvironment(e.picture(), e.intensity(), e.rotate())
                    : new ConstantEnvironment(e.r() * e.intensity(), e.g() * e.intensity(), e.b() * e.intensity());
            all.add(env);
        }
        List<PointLight> points = job.lights() != null ? job.lights() : scene.lights();
        if (points.isEmpty() && all.isEmpty() && scene.spotLights().isEmpty()) {
            points = List.of(new PointLight(job.camera().eye()));
        }
        Aabb box = RenderJob.bounds(scene);
        Vec3 centre = box.isEmpty() ? job.camera().eye() : box.min().add(box.max()).scale(0.5);
        for (PointLight p : points) {
            double d2 = p.position().sub(centre).dot(p.position().sub(centre));
            double s = d2 > 0 ? d2 : 1;
            all.add(new PointSource(p.position().x(), p.position().y(), p.position().z(), p.r() * s, p.g() * s, p.b() * s));
        }
        for (SpotLight l : scene.spotLights()) {
            Vec3 p = l.position();
            double d2 = p.sub(centre).dot(p.sub(centre)), s = d2 > 0 ? d2 : 1;
            all.add(new SpotSource(p.x(), p.y(), p.z(), xyz(l.direction()), l.angle(), l.falloff(), l.r() * s,
                    l.g() * s, l.b() * s));
        }
        lights = all.toArray(new Light[0]);
        areaLights = area.toArray(new Light[0]);
        environment = env;
        options = job.options().path();
    }

    private static double[] xyz(Vec3 v) { return new double[] {v.x(), v.y(), v.z()}; }

    /** The BSDF of a surface. */
    static Bsdf bsdf(Surface s) {
        return switch (s.kind()) {
            case DIFFUSE -> Diffuse.INSTANCE;
            case CONDUCTOR -> new Conductor(s.eta().toArray(), s.k().toArray(), s.roughness());
            case DIELECTRIC -> new Dielectric(s.ior(), s.roughness());
            case PLASTIC -> new Plastic(s.ior(), s.roughness());
        };
    }

    /**
     * The material colour at a hit into {@code out[0..2]}: with a forced patch checker (settings) its
     * colours, else the material's texture at the hit's (u,v), else its colour or its checker's second.
     */
    void baseColour(int material, Hit hit, int forcedChecker, double[] out) {
        boolean forced = hit.kind == Hit.PATCH && forcedChecker > 0;
        if (textures[material] != null && !forced) {
            textures[material].lookup(hit.u, hit.v, out);
            return;
        }
        int squares = forced ? forcedChecker : checker[material];
        int o = 6 * material;
        if (squares > 0) {
            long cu = (long) Math.floor(hit.u * squares), cv = (long) Math.floor(hit.v * squares);
            if (((cu + cv) & 1) != 0) {
                o += 3;
            }
        }
        out[0] = colours[o]; out[1] = colours[o + 1]; out[2] = colours[o + 2];
    }
}
