package org.beziertracer.render.bsdf;

/**
 * Lambertian reflection {@code f = albedo / π} (J. H. Lambert, "Photometria", 1760), sampled with
 * a cosine-weighted hemisphere (Malley's method: a uniform point on the unit disk lifted to the
 * hemisphere; pbrt-v4 §A.5.3). The caller turns the frame so that {@code wo.z > 0}; {@code wi}
 * below the surface gets 0. Stateless.
 */
public final class Diffuse implements Bsdf {
    public static final Diffuse INSTANCE = new Diffuse();

    private Diffuse() {}

    @Override
    public double eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] base,
                       double[] f) {
        if (woz <= 0 || wiz <= 0) {
            f[0] = 0; f[1] = 0; f[2] = 0;
            return 0;
        }
        f[0] = base[0] / Math.PI; f[1] = base[1] / Math.PI; f[2] = base[2] / Math.PI;
        return wiz / Math.PI;
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        return woz > 0 && wiz > 0 ? wiz / Math.PI : 0;
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, double[] base,
                          BsdfSample out) {
        if (woz <= 0) {
            return false;
        }
        double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double x = r * Math.cos(phi), y = r * Math.sin(phi), z = Math.sqrt(Math.max(0, 1 - u1));
        if (z <= 0) {
            return false;
        }
        out.set(x, y, z, base[0] / Math.PI, base[1] / Math.PI, base[2] / Math.PI, z / Math.PI, false, false);
        return true;
    }

    @Override
    public boolean isDelta() { return false; }
}
