package org.beziertracer.render.bsdf;

/**
 * Fresnel reflectance of unpolarised light (the average of the s and p polarisations), exact forms:
 * a dielectric interface (E. Hecht, "Optics", 5th ed., 2017, §4.6.2; pbrt-v4 §9.3.2) and an
 * absorbing conductor of complex index {@code η + iκ} seen from a medium of index 1 (the closed
 * form of M. Born, E. Wolf, "Principles of Optics", 7th ed., §14.2, as written by S. Lagarde,
 * "Memo on Fresnel equations", 2013). Static and allocation-free.
 */
public final class Fresnel {
    private Fresnel() {}

    /**
     * Reflectance at a dielectric boundary; {@code cosI} is the cosine of incidence on the side of
     * the normal ({@code < 0}: from inside), {@code eta} the relative index inside / outside. 1 on
     * total internal reflection.
     */
    public static double dielectric(double cosI, double eta) {
        cosI = Math.max(-1, Math.min(1, cosI));
        if (cosI < 0) {
            eta = 1 / eta;
            cosI = -cosI;
        }
        double sin2I = 1 - cosI * cosI;
        double sin2T = sin2I / (eta * eta);
        if (sin2T >= 1) {
            return 1;
        }
        double cosT = Math.sqrt(1 - sin2T);
        double rParallel = (eta * cosI - cosT) / (eta * cosI + cosT);
        double rPerpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
        return 0.5 * (rParallel * rParallel + rPerpendicular * rPerpendicular);
    }

    /** Reflectance of a conductor of complex index {@code eta + i k} at incidence cosine {@code |cosI|}. */
    public static double conductor(double cosI, double eta, double k) {
        double c = Math.min(1, Math.abs(cosI));
        double c2 = c * c, s2 = 1 - c2;
        double n2k2 = eta * eta - k * k - s2;
        double a2b2 = Math.sqrt(n2k2 * n2k2 + 4 * eta * eta * k * k);
        double a = Math.sqrt(Math.max(0, 0.5 * (a2b2 + n2k2)));
        double rs = (a2b2 - 2 * a * c + c2) / (a2b2 + 2 * a * c + c2);
        double rp = rs * (c2 * a2b2 - 2 * a * c * s2 + s2 * s2) / (c2 * a2b2 + 2 * a * c * s2 + s2 * s2);
        return 0.5 * (rs + rp);
    }
}
