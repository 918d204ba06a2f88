package org.beziertracer.render;

import java.util.Locale;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SurfacePoint;

/** {@link ShadingEvents} written as indented, human-readable lines to a {@link TraceLog}. */
final class LoggedShading implements ShadingEvents {
    private final TraceLog log;

    LoggedShading(TraceLog log) {
        this.log = log;
    }

    @Override
    public void ray(int depth, double w, double ox, double oy, double oz, double dx, double dy, double dz) {
        log.line(String.format(Locale.ROOT, "%sray depth=%d weight=%.4f o=(%.6g, %.6g, %.6g) d=(%.6g, %.6g, %.6g)",
                indent(depth), depth, w, ox, oy, oz, dx, dy, dz));
    }

    @Override
    public void miss(int depth) {
        log.line(indent(depth) + "  miss -> background");
    }

    @Override
    public void hit(int depth, Hit hit, SurfacePoint sp, double nx, double ny, double nz, boolean entering,
                    double[] base) {
        log.line(String.format(Locale.ROOT, "%s  hit %s %d t=%.9g u=%.6f v=%.6f p=(%.6g, %.6g, %.6g) n=(%.5f, %.5f, %.5f)%s"
                        + " base=(%.4f, %.4f, %.4f)", indent(depth), kindName(hit.kind), hit.index, hit.t, hit.u, hit.v,
                sp.px, sp.py, sp.pz, nx, ny, nz, entering ? "" : " (back face, normal flipped)",
                base[0], base[1], base[2]));
    }

    @Override
    public void lightBehind(int depth, int k, double ndl) {
        log.line(String.format(Locale.ROOT, "%s  light %d behind the surface (n.l=%.4f)", indent(depth), k, ndl));
    }

    @Override
    public void shadowRay(int depth, int k, boolean blocked) {
        log.line(String.format(Locale.ROOT, "%s  shadow ray to light %d: %s", indent(depth), k,
                blocked ? "blocked" : "clear"));
    }

    @Override
    public void lightTerms(int depth, int k, double ndl, double diffuse, double rdv, double specular) {
        log.line(String.format(Locale.ROOT, "%s  light %d: n.l=%.4f diffuse=%.4f r.v=%.4f specular=%.4f",
                indent(depth), k, ndl, diffuse, rdv, specular));
    }

    @Override
    public void localColour(int depth, double r, double g, double b, double ka) {
        log.line(String.format(Locale.ROOT, "%s  local=(%.4f, %.4f, %.4f) ambient=%.3f x base", indent(depth),
                r, g, b, ka));
    }

    @Override
    public void totalInternalReflection(int depth) {
        log.line(indent(depth) + "  total internal reflection");
    }

    @Override
    public void secondaryWeights(int depth, double wr, double wt, double w, double minAttenuation) {
        log.line(String.format(Locale.ROOT, "%s  reflect weight=%.4f refract weight=%.4f (path %.4f, cut-off %.5f)",
                indent(depth), wr, wt, w, minAttenuation));
    }

    private static String kindName(int kind) {
        return kind == Hit.PATCH ? "patch" : kind == Hit.PLANE ? "plane" : kind == Hit.TRIANGLE ? "triangle" : "sphere";
    }

    private static String indent(int depth) {
        return "  ".repeat(depth);
    }
}
