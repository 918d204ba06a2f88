package org.beziertracer.render;

import java.util.Arrays;

import org.beziertracer.accel.RayPacket;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.SurfacePoint;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.math.Powers;
import org.beziertracer.model.RenderSettings;

/**
 * Radiance along one camera ray: Whitted ray tracing (T. Whitted, "An improved illumination model
 * for shaded display", CACM 23(6), 1980) with Phong local illumination (B. T. Phong, "Illumination
 * for computer generated pictures", CACM 18(6), 1975).
 *
 * <h2>Shading at a hit</h2>
 * {@code I = ka·C + Σ_lights Il·(kd·C·max(0, n·l) + ks·max(0, r·v)^shininess) + wr·I_reflected + wt·I_refracted}
 * with C the base or checker colour, n the unit normal flipped toward the viewer (two-sided
 * surfaces), l toward the light, r = l mirrored about n, v toward the eye. Lights have no distance
 * fall-off. A light counts only when its shadow ray (origin offset along n by {@code eps}) reaches it
 * unblocked; every surface blocks light, transparent ones included (as in Whitted 1980). A light at
 * the origin of a camera ray (the default light at the eye) needs no shadow ray for that ray's hit:
 * it sees exactly what the eye sees.
 *
 * <h2>Reflection and refraction</h2>
 * With kr, kt, ior from the material and the Fresnel factor F from Schlick's approximation
 * (C. Schlick, "An inexpensive BRDF model for physically-based rendering", Eurographics 1994):
 * {@code wr = kr + kt·F}, {@code wt = kt·(1 − F)}; on total internal reflection {@code wr = kr + kt},
 * {@code wt = 0}. A ray enters a material when it meets the geometric normal head-on
 * ({@code d·n < 0}), so closed transparent objects need outward normals (spheres have them).
 *
 * <h2>Adaptive depth control</h2>
 * Each pending ray carries the product of the weights along its path; it is not traced when that
 * product falls below {@code minAttenuation} (1/256 by default: it could not change an 8-bit pixel)
 * or at the hard maximum depth. The ray tree is walked depth-first with an explicit stack of
 * {@code maxDepth + 2} entries, so nothing is allocated per ray.
 *
 * <p>Not thread-safe: one per worker thread, with its own {@link TraceContext}, {@link Hit} and
 * {@link SurfacePoint}.
 */
public final class WhittedTracer {
    private static final int STACK = RenderSettings.MAX_DEPTH + 2;
    /** A shadow ray runs from its origin to just short of the light. */
    private static final double SHADOW_T_MAX = 1 - 1e-9;

    private final TraceContext ctx;
    private final Hit hit = new Hit();
    private final SurfacePoint sp = new SurfacePoint();
    // Pending rays: origin, direction, weight, depth
    private final double[] stackRay = new double[6 * STACK];
    private final double[] stackWeight = new double[STACK];
    private final int[] stackDepth = new int[STACK];
    private final double[] local = new double[3];
    /** A packet's camera ray's colour while it is shaded. */
    private final double[] colour = new double[3];
    // The hit being shaded: unit ray direction, unit normal facing the viewer, front or back face
    private double ux, uy, uz, nx, ny, nz;
    private boolean entering;
    /** The curvature at the hit, for the curvature views ({@link SceneIntersector#curvature}). */
    private final double[] bend = new double[org.beziertracer.geometry.SurfaceCurvature.LENGTH];
    private ShadingScene s;
    private SceneIntersector si;
    private ShadingEvents events = ShadingEvents.NONE;
    // The unit direction to the light, and n·l, of the last towardLight()
    private double lx, ly, lz, ndl;

    // A packet of camera rays (tracePacket): per ray its first hit, surface point and, per light,
    // its shadow ray's answer; the shadow rays toward one light (origin, direction, normal) and
    // the camera ray each belongs to
    private final RayPacket shadows = new RayPacket();
    private Hit[] hits = new Hit[0];
    private SurfacePoint[] points = new SurfacePoint[0];
    private boolean[] found = new boolean[0], blocked = new boolean[0];
    /** A packet's shadow rays: origin and direction, the normal on their side, the hit and point each leaves, the answer. */
    private double[] shadowRay = new double[0], shadowNormal = new double[0];
    private Hit[] shadowFrom = new Hit[0];
    private SurfacePoint[] shadowAt = new SurfacePoint[0];
    private boolean[] shadowBlocked = new boolean[0];
    private int[] shadowOwner = new int[0];
    /** The packet's camera ray whose first hit is being shaded, or -1. */
    private int packetRay = -1;

    /** Ray counters, cumulative; the worker reads and resets them. */
    long primaryRays, shadowRays, secondaryRays;

    WhittedTracer(SceneIntersector anyIntersector) {
        this.ctx = anyIntersector.newContext();
    }

    /** A tracer for one-off use (tests, the {@code --pixel} debug trace). */
    public static WhittedTracer forJob(RenderJob job) {
        WhittedTracer t = new WhittedTracer(job.intersector());
        t.bind(new ShadingScene(job));
        return t;
    }

    void bind(ShadingScene scene) {
        this.s = scene;
        this.si = scene.intersector;
    }

    /** Lets go of the bound scene (a pool thread between renders must not keep an old model alive). */
    void unbind() {
        this.s = null;
        this.si = null;
    }

    /** Sends a line per ray, hit and term to {@code log} (null: off, the default). */
    public void setLog(TraceLog log) { this.events = log == null ? ShadingEvents.NONE : new LoggedShading(log); }

    public long primaryRays() { return primaryRays; }

    /** The tracer's query context (tests read its work counters, {@link TraceContext#shortcutCounts}). */
    TraceContext context() { return ctx; }

    /**
     * Adds the rays traced and the intersector's work since the last call to {@code st}'s counters,
     * and starts counting again.
     */
    void addCounts(RenderState st) {
        st.addWork(primaryRays, shadowRays, secondaryRays, ctx);
        primaryRays = shadowRays = secondaryRays = 0;
    }

    public long shadowRays() { return shadowRays; }

    public long secondaryRays() { return secondaryRays; }

    /** Traces the camera ray {@code o + t d} and writes its linear RGB into {@code rgb[0..2]}. */
    public void trace(double ox, double oy, double oz, double dx, double dy, double dz, double[] rgb) {
        rgb[0] = 0; rgb[1] = 0; rgb[2] = 0;
        primaryRays++;
        finish(push(0, ox, oy, oz, dx, dy, dz, 1, 0), rgb);
    }

    /** Shades the pending rays on the stack below {@code top}, and those they spawn. */
    private void finish(int top, double[] rgb) {
        while (top > 0) {
            top--;
            int o = 6 * top;
            double w = stackWeight[top];
            int depth = stackDepth[top];
            top = shade(stackRay[o], stackRay[o + 1], stackRay[o + 2], stackRay[o + 3], stackRay[o + 4],
                    stackRay[o + 5], w, depth, top, rgb);
        }
    }

    /**
     * Traces the {@code n} camera rays at {@code rays[0 .. 6n-1]} (origin, direction each) as
     * {@link #trace(double, double, double, double, double, double, double[])} would one by one,
     * and writes ray i's colour into {@code rgb[3i .. 3i+2]}; the same colours, with the rays'
     * traversals shared ({@link RayPacket}). First every ray's first hit (from {@code primary}'s
     * leaves when it was gathered, see {@link #gather}), then per light the shadow rays of those
     * hits as one packet, then the shading of each hit and the rays it spawns, one at a time.
     */
    void tracePacket(RayPacket primary, double[] rays, int n, double[] rgb) {
        ensurePacket(n);
        primaryRays += n;
        si.closestHits(ctx, primary, rays, n, 0, Double.POSITIVE_INFINITY, hits, found, points);
        if (s.mode == ShadingMode.PHONG && s.shadows) {
            for (int k = 0; k < s.lightCount; k++) {
                shadowPacket(rays, n, k);
            }
        }
        for (int i = 0; i < n; i++) {
            int o = 6 * i;
            double ox = rays[o], oy = rays[o + 1], oz = rays[o + 2], dx = rays[o + 3], dy = rays[o + 4], dz = rays[o + 5];
            colour[0] = 0; colour[1] = 0; colour[2] = 0;
            events.ray(0, 1, ox, oy, oz, dx, dy, dz);
            int top = 0;
            if (found[i]) {
                hit.set(hits[i]);
                sp.set(points[i]);
                packetRay = i;
                top = shadeHit(ox, oy, oz, dx, dy, dz, 1, 0, 0, colour);
                packetRay = -1;
            } else {
                background(1, 0, colour);
            }
            finish(top, colour);
            rgb[3 * i] = colour[0]; rgb[3 * i + 1] = colour[1]; rgb[3 * i + 2] = colour[2];
        }
    }

    /**
     * The shadow rays toward light {@code k} of the packet's first hits, traced as one packet; their
     * answers go to {@link #blocked}. Each is made as {@link #phong} makes it for the ray alone.
     */
    private void shadowPacket(double[] rays, int n, int k) {
        int lo = 6 * k, count = 0;
        double[] lights = s.lights;
        shadows.clear();
        for (int i = 0; i < n; i++) {
            int o = 6 * i;
            if (!found[i] || atEye(lo, 0, rays[o], rays[o + 1], rays[o + 2])) {
                continue;   // the cheap test first: a light at the eye needs no shadow ray
            }
            sp.set(points[i]);
            faceViewer(rays[o + 3], rays[o + 4], rays[o + 5]);
            if (!towardLight(lo) || ndl <= 0) {
                continue;
            }
            double px = sp.px + s.eps * nx, py = sp.py + s.eps * ny, pz = sp.pz + s.eps * nz;
            int q = 6 * count;
            shadowRay[q] = px; shadowRay[q + 1] = py; shadowRay[q + 2] = pz;
            shadowRay[q + 3] = lights[lo] - px; shadowRay[q + 4] = lights[lo + 1] - py; shadowRay[q + 5] = lights[lo + 2] - pz;
            shadowNormal[3 * count] = nx; shadowNormal[3 * count + 1] = ny; shadowNormal[3 * count + 2] = nz;
            shadowFrom[count] = hits[i];
            shadowAt[count] = points[i];
            shadowOwner[count++] = i;
            shadows.add(px, py, pz, shadowRay[q + 3], shadowRay[q + 4], shadowRay[q + 5]);
        }
        RayPacket together = count > 1 && si.gather(ctx, shadows, 0, SHADOW_T_MAX) ? shadows : null;
        shadowRays += count;
        si.occludedLeaving(ctx, together, shadowRay, count, 0, SHADOW_T_MAX, shadowFrom, shadowAt, shadowNormal,
                shadowBlocked);
        for (int j = 0; j < count; j++) {
            blocked[s.lightCount * shadowOwner[j] + k] = shadowBlocked[j];
        }
    }

    /** Room for a packet of {@code n} rays (grown, never shrunk). */
    private void ensurePacket(int n) {
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
            shadowOwner = new int[size];
            shadowRay = new double[6 * size];
            shadowNormal = new double[3 * size];
            shadowFrom = new Hit[size];
            shadowAt = new SurfacePoint[size];
            shadowBlocked = new boolean[size];
        }
        if (blocked.length < n * s.lightCount) {
            blocked = new boolean[Math.max(n * s.lightCount, 2 * blocked.length)];
        }
    }

    /**
     * One traversal of the hierarchy for the camera rays added to {@code packet} (see {@link
     * SceneIntersector#gather}); false when they must go one at a time.
     */
    boolean gather(RayPacket packet) {
        return si.gather(ctx, packet, 0, Double.POSITIVE_INFINITY);
    }

    private int push(int top, double ox, double oy, double oz, double dx, double dy, double dz, double w, int depth) {
        int o = 6 * top;
        stackRay[o] = ox; stackRay[o + 1] = oy; stackRay[o + 2] = oz;
        stackRay[o + 3] = dx; stackRay[o + 4] = dy; stackRay[o + 5] = dz;
        stackWeight[top] = w;
        stackDepth[top] = depth;
        return top + 1;
    }

    /** Shades one ray, adds {@code w ×} its local colour to {@code rgb}, pushes its children; returns the new top. */
    private int shade(double ox, double oy, double oz, double dx, double dy, double dz, double w, int depth,
                      int top, double[] rgb) {
        events.ray(depth, w, ox, oy, oz, dx, dy, dz);
        if (!si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit)) {
            background(w, depth, rgb);
            return top;
        }
        si.surfacePoint(ctx, hit, sp);
        return shadeHit(ox, oy, oz, dx, dy, dz, w, depth, top, rgb);
    }

    private void background(double w, int depth, double[] rgb) {
        rgb[0] += w * ShadingScene.BG_R; rgb[1] += w * ShadingScene.BG_G; rgb[2] += w * ShadingScene.BG_B;
        events.miss(depth);
    }

    /** {@link #shade} once {@link #hit} and {@link #sp} hold the ray's hit. */
    private int shadeHit(double ox, double oy, double oz, double dx, double dy, double dz, double w, int depth,
                         int top, double[] rgb) {
        faceViewer(dx, dy, dz);
        int m = s.materialOffset(hit.kind, hit.index);
        baseColour(m, local);
        events.hit(depth, hit, sp, nx, ny, nz, entering, local);
        if (s.mode != ShadingMode.PHONG) {
            debugColour(nx, ny, nz);
        } else {
            phong(m, depth, ox, oy, oz, local);
        }
        rgb[0] += w * local[0]; rgb[1] += w * local[1]; rgb[2] += w * local[2];
        return s.mode != ShadingMode.PHONG ? top : spawn(m, w, depth, top);
    }

    /**
     * The unit ray direction {@code u} and the unit normal {@code n} at the hit, flipped toward
     * the viewer (two-sided surfaces; a degenerate normal faces the ray); {@code entering} when
     * the ray met the surface's own normal head-on.
     */
    private void faceViewer(double dx, double dy, double dz) {
        double dl = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        ux = dx * dl; uy = dy * dl; uz = dz * dl;
        nx = sp.nx; ny = sp.ny; nz = sp.nz;
        if (!(nx * nx + ny * ny + nz * nz > 0.5)) { // degenerate normal: face the ray
            nx = -ux; ny = -uy; nz = -uz;
        }
        entering = nx * ux + ny * uy + nz * uz < 0;
        if (!entering) {
            nx = -nx; ny = -ny; nz = -nz;
        }
    }

    /**
     * Local Phong illumination at the hit (material at {@code m}) with a shadow ray per light:
     * replaces the base colour in {@code c} by the local colour. {@code o} is the ray's origin.
     */
    private void phong(int m, int depth, double ox, double oy, double oz, double[] c) {
        double[] mat = s.materials;
        double cr = c[0], cg = c[1], cb = c[2];
        double ka = mat[m + ShadingScene.KA], kd = mat[m + ShadingScene.KD], ks = mat[m + ShadingScene.KS];
        double shin = mat[m + ShadingScene.SHININESS];
        double sumR = ka * cr, sumG = ka * cg, sumB = ka * cb;
        double[] lights = s.lights;
        for (int k = 0, lo = 0; k < s.lightCount; k++, lo += 6) {
            if (!towardLight(lo)) {
                continue;
            }
            double lx = this.lx, ly = this.ly, lz = this.lz, ndl = this.ndl;
            if (ndl <= 0) {
                events.lightBehind(depth, k, ndl);
                continue;
            }
            if (s.shadows && !atEye(lo, depth, ox, oy, oz) && shadowed(lo, k, depth)) {
                continue;
            }
            // Phong specular: reflect l about n, compare with the view direction v = -u
            double rdv = 2 * ndl * (nx * -ux + ny * -uy + nz * -uz) - (lx * -ux + ly * -uy + lz * -uz);
            double spec = rdv > 0 && ks > 0 ? ks * Powers.pow(rdv, shin) : 0;
            double diff = kd * ndl;
            sumR += lights[lo + 3] * (diff * cr + spec);
            sumG += lights[lo + 4] * (diff * cg + spec);
            sumB += lights[lo + 5] * (diff * cb + spec);
            events.lightTerms(depth, k, ndl, diff, rdv, spec);
        }
        events.localColour(depth, sumR, sumG, sumB, ka);
        c[0] = sumR; c[1] = sumG; c[2] = sumB;
    }

    /**
     * The unit direction {@code l} from the hit to the light at {@code lights[lo..]} into {@link
     * #lx}, {@link #ly}, {@link #lz}, and {@code n·l} into {@link #ndl}; false (nothing set) when
     * the light is at the point.
     */
    private boolean towardLight(int lo) {
        double[] lights = s.lights;
        double x = lights[lo] - sp.px, y = lights[lo + 1] - sp.py, z = lights[lo + 2] - sp.pz;
        double dist = Math.sqrt(x * x + y * y + z * z);
        if (!(dist > 0)) {
            return false;
        }
        lx = x / dist; ly = y / dist; lz = z / dist;
        ndl = nx * lx + ny * ly + nz * lz;
        return true;
    }

    /** A light at the origin of a camera ray sees everything that ray sees: no shadow ray needed. */
    private boolean atEye(int lo, int depth, double ox, double oy, double oz) {
        double[] lights = s.lights;
        return depth == 0 && lights[lo] == ox && lights[lo + 1] == oy && lights[lo + 2] == oz;
    }

    /**
     * True when the hit's shadow ray toward light {@code k} is blocked: the packet's answer for a
     * packet's camera ray ({@link #shadowPacket}), else {@link #blocked}.
     */
    private boolean shadowed(int lo, int k, int depth) {
        if (packetRay < 0) {
            return blocked(lo, k, depth);
        }
        boolean answer = blocked[s.lightCount * packetRay + k];
        events.shadowRay(depth, k, answer);
        return answer;
    }

    /** True when the shadow ray from the hit (offset along n) to the light at {@code lights[lo..]} is blocked. */
    private boolean blocked(int lo, int k, int depth) {
        double[] lights = s.lights;
        double px = sp.px + s.eps * nx, py = sp.py + s.eps * ny, pz = sp.pz + s.eps * nz;
        shadowRays++;
        boolean blocked = si.occludedLeaving(ctx, hit, sp, nx, ny, nz, px, py, pz, lights[lo] - px,
                lights[lo + 1] - py, lights[lo + 2] - pz, 0, SHADOW_T_MAX);
        events.shadowRay(depth, k, blocked);
        return blocked;
    }

    /** Pushes the reflected and refracted rays that pass the adaptive depth control. */
    private int spawn(int m, double w, int depth, int top) {
        double[] mat = s.materials;
        double kr = mat[m + ShadingScene.KR], kt = mat[m + ShadingScene.KT];
        if (kr <= 0 && kt <= 0 || depth >= s.maxDepth) {
            return top;
        }
        double cosI = -(nx * ux + ny * uy + nz * uz);
        double wr = kr, wt = 0;
        double tx = 0, ty = 0, tz = 0;
        if (kt > 0) {
            double ior = mat[m + ShadingScene.IOR];
            double eta = entering ? 1 / ior : ior;
            double k = 1 - eta * eta * (1 - cosI * cosI);
            if (k < 0) {
                wr += kt; // total internal reflection
                events.totalInternalReflection(depth);
            } else {
                double cosT = Math.sqrt(k);
                double r0 = (1 - ior) / (1 + ior);
                r0 *= r0;
                double c = 1 - (entering ? cosI : cosT);
                double f = r0 + (1 - r0) * c * c * c * c * c;
                wr += kt * f;
                wt = kt * (1 - f);
                double a = eta * cosI - cosT;
                tx = eta * ux + a * nx; ty = eta * uy + a * ny; tz = eta * uz + a * nz;
            }
        }
        events.secondaryWeights(depth, wr, wt, w, s.minAttenuation);
        if (wt > 0 && w * wt >= s.minAttenuation) {
            secondaryRays++;
            top = push(top, sp.px - s.eps * nx, sp.py - s.eps * ny, sp.pz - s.eps * nz, tx, ty, tz, w * wt, depth + 1);
        }
        if (wr > 0 && w * wr >= s.minAttenuation) {
            secondaryRays++;
            double two = 2 * cosI;
            top = push(top, sp.px + s.eps * nx, sp.py + s.eps * ny, sp.pz + s.eps * nz,
                    ux + two * nx, uy + two * ny, uz + two * nz, w * wr, depth + 1);
        }
        return top;
    }

    /** Material colour at the hit: the settings' patch checker, else its texture's, else its own or its checker's. */
    private void baseColour(int m, double[] out) {
        double[] mat = s.materials;
        boolean forced = hit.kind == Hit.PATCH && s.patchChecker > 0;
        SurfaceTexture texture = s.textures[m / ShadingScene.MAT_STRIDE];
        if (texture != null && !forced) {
            texture.lookup(hit.u, hit.v, out);
            return;
        }
        int squares = forced ? s.patchChecker : (int) mat[m + ShadingScene.CHECKER];
        boolean second = false;
        if (squares > 0) {
            long cu = (long) Math.floor(hit.u * squares), cv = (long) Math.floor(hit.v * squares);
            second = ((cu + cv) & 1) != 0;
        }
        int c = second ? ShadingScene.R2 : ShadingScene.R;
        out[0] = mat[m + c]; out[1] = mat[m + c + 1]; out[2] = mat[m + c + 2];
    }

    /** Colour of the non-Phong modes into {@link #local} (which holds the base colour on entry). */
    private void debugColour(double nx, double ny, double nz) {
        switch (s.mode) {
            case NORMALS -> {
                local[0] = 0.5 * (nx + 1); local[1] = 0.5 * (ny + 1); local[2] = 0.5 * (nz + 1);
            }
            case UV -> {
                local[0] = hit.u - Math.floor(hit.u); local[1] = hit.v - Math.floor(hit.v); local[2] = 0;
            }
            case PATCH_ID -> patchIdColour(hit.kind, hit.index, local);
            case ZEBRA -> AnalysisColours.zebra(s.analysis, ux, uy, uz, nx, ny, nz, local);
            case EMAP -> AnalysisColours.emap(s.analysis, ux, uy, uz, nx, ny, nz, local);
            case ISOPHOTES -> {
                double[] l = s.analysis.isophoteLight();
                if (l == null) {
                    AnalysisColours.isophotes(s.analysis, nx, ny, nz, -ux, -uy, -uz, local);
                } else {
                    AnalysisColours.isophotes(s.analysis, nx, ny, nz, l[0], l[1], l[2], local);
                }
            }
            case DRAFT -> AnalysisColours.draft(s.analysis, sp.nx, sp.ny, sp.nz, facing(nx, ny, nz), local);
            case GAUSSIAN, MEAN, MIN_RADIUS, MAX_RADIUS -> {
                si.curvature(ctx, hit, sp, bend);
                AnalysisColours.curvature(s.mode, AnalysisColours.value(s.mode, bend), s.rangeLow, s.rangeHigh,
                        facing(nx, ny, nz), local);
            }
            default -> { } // FLAT: the base colour as is
        }
    }

    /** |N·V| of the viewer-facing normal and the ray: 1 head-on, 0 at a silhouette. */
    private double facing(double nx, double ny, double nz) {
        return Math.abs(nx * ux + ny * uy + nz * uz);
    }

    /** A distinct, stable colour per patch (golden-ratio hues); planes dark grey, mesh triangles grey, spheres white. */
    static void patchIdColour(int kind, int index, double[] out) {
        if (kind != Hit.PATCH) {
            double g = kind == Hit.PLANE ? 0.3 : kind == Hit.TRIANGLE ? 0.6 : 0.9;
            out[0] = g; out[1] = g; out[2] = g;
            return;
        }
        double h = (index * 0.6180339887498949) % 1.0 * 6;
        int sector = (int) h;
        double f = h - sector, lo = 0.15, hi = 0.9, up = lo + (hi - lo) * f, down = hi - (hi - lo) * f;
        switch (sector) {
            case 0 -> { out[0] = hi; out[1] = up; out[2] = lo; }
            case 1 -> { out[0] = down; out[1] = hi; out[2] = lo; }
            case 2 -> { out[0] = lo; out[1] = hi; out[2] = up; }
            case 3 -> { out[0] = lo; out[1] = down; out[2] = hi; }
            case 4 -> { out[0] = up; out[1] = lo; out[2] = hi; }
            default -> { out[0] = hi; out[1] = lo; out[2] = down; }
        }
    }
}
