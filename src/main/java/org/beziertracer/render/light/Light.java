package org.beziertracer.render.light;

/**
 * A source of light for the path tracer, in world space: sampled from a shaded point (next-event
 * estimation) and, unless it is a delta light, met by rays (for multiple importance sampling,
 * E. Veach, "Robust Monte Carlo methods for light transport simulation", PhD thesis, Stanford,
 * 1997, ch. 9). Area lights are not in the BVH in this first version: a ray asks each light for
 * its own hit ({@link #hit}), and they cast no shadows on one another.
 *
 * <p>Implementations are immutable and thread-safe; no method allocates.
 */
public interface Light {

    /** Samples the light as seen from {@code p} with {@code u1, u2} in [0,1); false when it sends nothing toward p. */
    boolean sample(double px, double py, double pz, double u1, double u2, LightSample out);

    /** The pdf (solid angle at p) with which {@link #sample} picks the unit direction {@code w}; 0 for delta lights. */
    double pdf(double px, double py, double pz, double wx, double wy, double wz);

    /**
     * The distance along the unit direction {@code w} from {@code o} at which the ray meets the
     * light's emitting side ({@code +∞}: never; the environment answers {@link Double#MAX_VALUE}, met
     * by every ray that escapes), and the radiance it sees there into {@code le[0..2]}.
     */
    double hit(double ox, double oy, double oz, double wx, double wy, double wz, double[] le);

    /** Point and spot sources: only next-event estimation can find them. */
    default boolean isDelta() { return false; }

    /** The environment: met by rays that leave the scene. */
    default boolean isEnvironment() { return false; }
}
