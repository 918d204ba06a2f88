package org.beziertracer.render;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SurfacePoint;

/**
 * What {@link WhittedTracer} reports while it shades one ray: every ray, hit and shading term.
 * The renderer uses {@link #NONE}, whose methods do nothing (the calls compile away); the
 * {@code render --pixel} debug trace uses {@link LoggedShading}, which writes a line per event.
 * Keeping the reporting behind this interface keeps the tracer's hot path free of logging
 * branches and formatting.
 */
interface ShadingEvents {

    /** Reports nothing. */
    ShadingEvents NONE = new ShadingEvents() { };

    /** A ray of the ray tree at {@code depth}, with path weight {@code w}. */
    default void ray(int depth, double w, double ox, double oy, double oz, double dx, double dy, double dz) {}

    /** The ray hit nothing. */
    default void miss(int depth) {}

    /** The ray hit {@code hit} at {@code sp}; {@code n} faces the viewer; {@code base} is the colour there. */
    default void hit(int depth, Hit hit, SurfacePoint sp, double nx, double ny, double nz, boolean entering,
                     double[] base) {}

    /** Light {@code k} lies behind the surface. */
    default void lightBehind(int depth, int k, double ndl) {}

    /** The shadow ray toward light {@code k}. */
    default void shadowRay(int depth, int k, boolean blocked) {}

    /** Light {@code k}'s diffuse and specular terms. */
    default void lightTerms(int depth, int k, double ndl, double diffuse, double rdv, double specular) {}

    /** The local (Phong) colour and the ambient factor. */
    default void localColour(int depth, double r, double g, double b, double ka) {}

    /** The refracted ray is totally reflected. */
    default void totalInternalReflection(int depth) {}

    /** Weights of the reflected and refracted rays, the path weight and the cut-off. */
    default void secondaryWeights(int depth, double wr, double wt, double w, double minAttenuation) {}
}
