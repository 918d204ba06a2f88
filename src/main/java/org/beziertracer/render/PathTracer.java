package org.beziertracer.render;

import java.util.Arrays;

import org.beziertracer.accel.RayPacket;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.SurfacePoint;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.render.bsdf.Bsdf;
import org.beziertracer.render.bsdf.BsdfSample;
import org.beziertracer.render.light.Light;
import org.beziertracer.render.light.LightSample;

/**
 * Unidirectional path tracing (J. T. Kajiya, "The rendering equation", SIGGRAPH 1986) with
 * next-event estimation and multiple importance sampling of one light sample and one BSDF sample
 * per bounce, weighted by the power heuristic with β = 2 (E. Veach, L. J. Guibas, "Optimally
 * combining sampling techniques for Monte Carlo rendering", SIGGRAPH 1995; Veach's thesis 1997,
 * ch. 9), Russian roulette after {@link PathOptions#rouletteDepth()} bounces (J. Arvo, D. Kirk,
 * "Particle transport and image synthesis", SIGGRAPH 1990), a maximum depth and an optional clamp.
 *
 * <p>A light is chosen uniformly for each next-event estimate. The camera rays of a packet find
 * their first hits together ({@link SceneIntersector#closestHits}); each path then goes on alone
 * through {@link SceneIntersector#closestHit} and {@link SceneIntersector#occludedLeaving}. Area
 * lights are not in the BVH: a bounce asks each of them for its own hit.
 *
 * <p>Frames: z along the unit normal, turned toward the outgoing direction for opaque surfaces
 * (two-sided), kept as the surface's own for glass (so {@code wo.z > 0} is outside). The random
 * numbers of a path come from {@link PathRandom} by pixel, sample and dimension: per bounce the
 * light choice, the light's 2-D sample, the BSDF's lobe choice, its 2-D direction sample and the
 * roulette, five dimensions whether used or not.
 *
 * <p>Not thread-safe: one per worker, with flat scratch; nothing is allocated per path.
 */
final class PathTracer {
    private final TraceContext ctx;
    private final Hit hit = new Hit();
    private final SurfacePoint sp = new SurfacePoint();
    private final BsdfSample bs = new BsdfSample();
    private final LightSample ls = new LightSample();
    private final PathRandom rnd = new PathRandom();
    private final double[] base = new double[3], f = new double[3], le = new double[3], radiance = new double[3],
            blocked = new double[3];
    private Hit[] hits = new Hit[0];
    private SurfacePoint[] points = new SurfacePoint[0];
    private boolean[] found = new boolean[0];
    private ShadingScene s;
    private PathScene p;
    private SceneIntersector si;
    // The shading frame at the current hit: tangents t, b and normal n
    private double tx, ty, tz, bx, by, bz, nx, ny, nz;

    long primaryRays, shadowRays, secondaryRays;

    PathTracer(SceneIntersector anyIntersector) {
        this.ctx = anyIntersector.newContext();
    }

    void bind(ShadingScene shading, PathScene path) {
        this.s = shading;
        this.p = path;
        this.si = shading.intersector;
    }

    void unbind() {
        s = null;
        p = null;
        si = null;
    }

    TraceContext context() { return ctx; }

    /** As {@link WhittedTracer#addCounts}. */
    void addCounts(RenderState st) {
        st.addWork(primaryRays, shadowRays, secondaryRays, ctx);
        primaryRays = shadowRays = secondaryRays = 0;
    }

    /**
     * Traces the {@code n} camera rays at {@code rays[6i ..]}, ray i being sample {@code
     * samples[i]} of pixel {@code (pixels[2i], pixels[2i+1])}, and writes each path's radiance
     * into {@code rgb[3i ..]}.
     */
    void tracePacket(RayPacket primary, double[] rays, int[] pixels, int[] samples, int n, long seed, double[] rgb) {
        ensure(n);
        primaryRays += n;
        si.closestHits(ctx, primary, rays, n, 0, Double.POSITIVE_INFINITY, hits, found, points);
        for (int i = 0; i < n; i++) {
            rnd.start(seed, pixels[2 * i], pixels[2 * i + 1], samples[i]);
            int o = 6 * i;
            path(rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5], found[i], hits[i], points[i]);
            clamp();
            rgb[3 * i] = radiance[0]; rgb[3 * i + 1] = radiance[1]; rgb[3 * i + 2] = radiance[2];
        }
    }

    private void clamp() {
        double limit = p.options.clamp();
        double max = Math.max(radiance[0], Math.max(radiance[1], radiance[2]));
        if (limit > 0 && max > limit) {
            double k = limit / max;
            radiance[0] *= k; radiance[1] *= k; radiance[2] *= k;
        }
        if (!(radiance[0] + radiance[1] + radiance[2] < Double.POSITIVE_INFINITY)) {
            radiance[0] = 0; radiance[1] = 0; radiance[2] = 0; // a NaN or ∞ sample is dropped, not smeared
        }
    }

    /** The radiance along one camera ray into {@link #radiance}, its first hit given. */
    private void path(double ox, double oy, double oz, double dx, double dy, double dz, boolean hitFirst, Hit first,
                      SurfacePoint firstPoint) {
        double lr = 0, lg = 0, lb = 0;
        double wr = 1, wg = 1, wb = 1; // throughput β
        PathOptions opt = p.options;
        int lightCount = p.lights.length;
        double pickPdf = lightCount > 0 ? 1.0 / lightCount : 0;
        boolean specular = true;
        double bsdfPdf = 0, px = ox, py = oy, pz = oz;
        double dl = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx *= dl; dy *= dl; dz *= dl;
        boolean isHit = hitFirst;
        if (isHit) {
            hit.set(first);
            sp.set(firstPoint);
        }
        for (int depth = 0; ; depth++) {
            // Emission of an area light met before the surface, or of the environment on escape
            double tSurface = isHit ? hit.t / dl : Double.POSITIVE_INFINITY;
            double tLight = Double.POSITIVE_INFINITY;
            Light met = null;
            for (Light a : p.areaLights) {
                double t = a.hit(ox, oy, oz, dx, dy, dz, le);
                if (t < tLight) {
                    tLight = t;
                    met = a;
                }
            }
            if (met != null && tLight < tSurface) {
                met.hit(ox, oy, oz, dx, dy, dz, le);
            } else if (!isHit && p.environment != null) {
                met = p.environment;
                met.hit(ox, oy, oz, dx, dy, dz, le);
            } else {
                met = null;
            }
            if (met != null) {
                double w = 1;
                if (!specular) {
                    if (!opt.mis()) {
                        w = 0;
                    } else {
                        double lightPdf = pickPdf * met.pdf(px, py, pz, dx, dy, dz);
                        w = powerHeuristic(bsdfPdf, lightPdf);
                    }
                }
                lr += wr * w * le[0]; lg += wg * w * le[1]; lb += wb * w * le[2];
                break;
            }
            if (!isHit) {
                break;
            }
            // The hit: material, colour, frame
            int m = s.materialOffset(hit.kind, hit.index) / ShadingScene.MAT_STRIDE;
            Bsdf bsdf = p.bsdfs[m];
            p.baseColour(m, hit, s.patchChecker, base);
            double hx = sp.px, hy = sp.py, hz = sp.pz;
            frame(dx, dy, dz, bsdf.transmits());
            double wox = -(dx * tx + dy * ty + dz * tz), woy = -(dx * bx + dy * by + dz * bz),
                    woz = -(dx * nx + dy * ny + dz * nz);
            // Next-event estimation: one light, chosen uniformly
            if (!bsdf.isDelta() && lightCount > 0) {
                double u0 = rnd.next(), u1 = rnd.next2(), u2 = rnd.second();
                Light light = p.lights[Math.min(lightCount - 1, (int) (u0 * lightCount))];
                if (light.sample(hx, hy, hz, u1, u2, ls) && ls.pdf > 0 && ls.r + ls.g + ls.b > 0) {
                    double wix = ls.wx * tx + ls.wy * ty + ls.wz * tz, wiy = ls.wx * bx + ls.wy * by + ls.wz * bz,
                            wiz = ls.wx * nx + ls.wy * ny + ls.wz * nz;
                    double pdfB = bsdf.eval(wox, woy, woz, wix, wiy, wiz, base, f);
                    if (f[0] + f[1] + f[2] > 0 && !shadowed(hx, hy, hz, wiz, light, ls)) {
                        double lightPdf = pickPdf * ls.pdf;
                        // at the last bounce no BSDF sample follows to take its share: the light sample counts whole
                        boolean last = depth + 1 >= opt.maxDepth();
                        double w = ls.delta || !opt.mis() || last ? 1 : powerHeuristic(lightPdf, pdfB);
                        double k = Math.abs(wiz) * w / lightPdf;
                        lr += wr * f[0] * ls.r * k; lg += wg * f[1] * ls.g * k; lb += wb * f[2] * ls.b * k;
                    }
                }
            } else if (lightCount > 0) {
                rnd.skip(2); // keep the dimensions' layout the same at every bounce
            }
            if (depth + 1 >= opt.maxDepth()) {
                break;
            }
            // The BSDF sample: the next direction
            double uc = rnd.next(), v1 = rnd.next2(), v2 = rnd.second();
            if (!bsdf.sample(wox, woy, woz, uc, v1, v2, base, bs) || !(bs.pdf > 0)) {
                break;
            }
            double k = Math.abs(bs.wz) / bs.pdf;
            wr *= bs.fr * k; wg *= bs.fg * k; wb *= bs.fb * k;
            specular = bs.delta;
            bsdfPdf = bs.pdf;
            // Russian roulette
            double u = rnd.next();
            if (depth + 1 >= opt.rouletteDepth()) {
                double q = Math.max(0.05, 1 - Math.max(wr, Math.max(wg, wb)));
                if (u < q) {
                    break;
                }
                wr /= 1 - q; wg /= 1 - q; wb /= 1 - q;
            }
            if (!(wr + wg + wb > 0)) {
                break;
            }
            // The next ray, from just off the surface on the side it leaves
            dx = bs.wx * tx + bs.wy * bx + bs.wz * nx;
            dy = bs.wx * ty + bs.wy * by + bs.wz * ny;
            dz = bs.wx * tz + bs.wy * bz + bs.wz * nz;
            double side = bs.wz >= 0 ? s.eps : -s.eps;
            px = hx; py = hy; pz = hz;
            ox = hx + side * nx; oy = hy + side * ny; oz = hz + side * nz;
            dl = 1;
            secondaryRays++;
            isHit = si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit);
            if (isHit) {
                si.surfacePoint(ctx, hit, sp);
            }
        }
        radiance[0] = lr; radiance[1] = lg; radiance[2] = lb;
    }

    /** True when something blocks the light sample {@code ls} (local {@code wi.z} tells the side) from the hit. */
    /**
     * True when something stands between the hit and the light sample {@code l} of {@code light}:
     * the scene's surfaces, or the emitting side of another area light. A path that meets an area
     * light's front stops there ({@link #path}), so the light hides what is behind it from light
     * samples too: the environment behind a rect light, one light behind another. Without that, a
     * light sample counted radiance a BSDF sample in the same direction could never see, and the
     * estimate with MIS differed from the one without.
     */
    private boolean shadowed(double hx, double hy, double hz, double wiz, Light light, LightSample l) {
        double sign = wiz >= 0 ? 1 : -1;
        double snx = sign * nx, sny = sign * ny, snz = sign * nz;
        double ox = hx + s.eps * snx, oy = hy + s.eps * sny, oz = hz + s.eps * snz;
        double tMax = l.distance < Double.POSITIVE_INFINITY ? l.distance * (1 - 1e-7) - s.eps : Double.POSITIVE_INFINITY;
        if (!(tMax > 0)) {
            return false;
        }
        for (Light a : p.areaLights) {
            if (a != light && a.hit(ox, oy, oz, l.wx, l.wy, l.wz, blocked) < tMax) {
                return true;
            }
        }
        shadowRays++;
        return si.occludedLeaving(ctx, hit, sp, snx, sny, snz, ox, oy, oz, l.wx, l.wy, l.wz, 0, tMax);
    }

    /**
     * The shading frame at the hit into {@link #tx} … {@link #nz}: the unit normal (turned toward
     * the viewer unless {@code keepSide}) and two tangents (T. Duff et al., "Building an
     * orthonormal basis, revisited", JCGT 6(1), 2017).
     */
    private void frame(double dx, double dy, double dz, boolean keepSide) {
        double x = sp.nx, y = sp.ny, z = sp.nz;
        if (!(x * x + y * y + z * z > 0.5)) {
            x = -dx; y = -dy; z = -dz;
        } else if (!keepSide && x * dx + y * dy + z * dz > 0) {
            x = -x; y = -y; z = -z;
        }
        nx = x; ny = y; nz = z;
        double sign = Math.copySign(1, z), a = -1 / (sign + z), b = x * y * a;
        tx = 1 + sign * x * x * a; ty = sign * b; tz = -sign * x;
        bx = b; by = sign + y * y * a; bz = -y;
    }

    private static double powerHeuristic(double a, double b) {
        double a2 = a * a, b2 = b * b;
        return a2 + b2 > 0 ? a2 / (a2 + b2) : 0;
    }

    private void ensure(int n) {
        if (hits.length < n) {
            int size = Math.max(n, 2 * hits.length);
            hits = Arrays.copyOf(hits, size);
            points = Arrays.copyOf(points, size);
            for (int i = 0; i < size; i++) {
                if (hits[i] == null) {
                    hits[i] = new Hit();
                    points[i] = new SurfacePoint();
                }
            }
            found = new boolean[size];
        }
    }
}
