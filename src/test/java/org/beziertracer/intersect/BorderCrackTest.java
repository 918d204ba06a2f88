package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The dense border ("crack") test ({@link BorderRays}) for every method, each on its own default
 * leaves: no ray aimed at a border two patches share falls through or hits beyond it, on the
 * teapot and on a quilt whose centre patch is of degree 6 between bicubic neighbours.
 */
class BorderCrackTest {

    static final Scene TEAPOT = Models.load("teapot");
    static final Scene QUILT = RandomPatches.mixedDegreeQuilt(new Random(6));

    @ParameterizedTest
    @EnumSource(Method.class)
    void noRayFallsThroughATeapotBorder(Method method) {
        BorderRays.Result r = BorderRays.shoot(TEAPOT, IntersectOptions.defaults().withMethod(method), 3, 4);
        assertTrue(r.sharedBorders >= 100, "shared borders found: " + r.sharedBorders);
        assertEquals(0, r.misses + r.beyond, method + ": " + r);
        assertTrue(r.onBorder > r.rays / 2, "most rays should reach the border point itself: " + r.onBorder + " of " + r.rays);
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void noRayFallsThroughTheBordersOfADegree6Neighbour(Method method) {
        assertEquals(6, QUILT.patches().get(4).degreeU(), "the centre patch is the degree-6 one");
        BorderRays.Result r = BorderRays.shoot(QUILT, IntersectOptions.defaults().withMethod(method), 20, 6);
        assertEquals(24, r.sharedBorders, "a 3x3 quilt has 12 inner borders, each seen from both sides");
        assertEquals(0, r.misses + r.beyond, method + ": " + r);
        assertTrue(r.onBorder > r.rays / 2, "most rays should reach the border point itself: " + r.onBorder + " of " + r.rays);
    }
}
