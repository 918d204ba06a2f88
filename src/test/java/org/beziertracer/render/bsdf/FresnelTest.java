package org.beziertracer.render.bsdf;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;

import org.beziertracer.model.MetalPresets;

import org.junit.jupiter.api.Test;

/** {@link Fresnel} against closed forms: normal incidence, Brewster's angle, total internal reflection, grazing. */
class FresnelTest {

    @Test
    void glassReflectsFourPercentHeadOn() {
        assertEquals(0.04, Fresnel.dielectric(1, 1.5), ROUNDING);
        assertEquals(0.04, Fresnel.dielectric(-1, 1.5), ROUNDING, "from inside, head-on: the same");
    }

    @Test
    void atBrewstersAngleOnlyTheSPolarisationIsReflected() {
        double n = 1.5, cos = Math.cos(Math.atan(n));
        double rs = Math.pow((n * n - 1) / (n * n + 1), 2);
        assertEquals(0.5 * rs, Fresnel.dielectric(cos, n), ROUNDING);
    }

    @Test
    void beyondTheCriticalAngleInsideEverythingIsReflected() {
        double critical = Math.sqrt(1 - 1 / (1.5 * 1.5));   // cos of the critical angle
        assertEquals(1, Fresnel.dielectric(-(critical - 1e-3), 1.5));
        assertEquals(true, Fresnel.dielectric(-(critical + 1e-3), 1.5) < 1);
    }

    @Test
    void grazingLightIsReflectedWhole() {
        assertEquals(1, Fresnel.dielectric(0, 1.5), ROUNDING);
        assertEquals(1, Fresnel.conductor(0, 0.143, 3.98), ROUNDING);
    }

    @Test
    void aConductorHeadOnReflectsItsNormalIncidenceValue() {
        for (MetalPresets metal : MetalPresets.values()) {
            for (int c = 0; c < 3; c++) {
                double n = metal.eta()[c], k = metal.k()[c];
                double expected = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
                assertEquals(expected, Fresnel.conductor(1, n, k), ROUNDING, metal + " channel " + c);
            }
        }
    }

    @Test
    void aConductorWithoutAbsorptionIsADielectric() {
        Random rnd = new Random(34);
        for (int i = 0; i < 1000; i++) {
            double cos = rnd.nextDouble(), n = 1.1 + 2 * rnd.nextDouble();
            assertEquals(Fresnel.dielectric(cos, n), Fresnel.conductor(cos, n, 0), 1e-9, "cos " + cos + " n " + n);
        }
    }

    @Test
    void goldReflectsRedMoreThanBlue() {
        double[] eta = MetalPresets.GOLD.eta(), k = MetalPresets.GOLD.k();
        double red = Fresnel.conductor(1, eta[0], k[0]), blue = Fresnel.conductor(1, eta[2], k[2]);
        assertEquals(true, red > 0.9 && blue < 0.5, "gold at normal incidence: red " + red + ", blue " + blue);
    }
}
