package org.beziertracer.geometry;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

class PatchesTest {


    private static void assertVec(double[] expected, Vec3 actual, String what) {
        assertEquals(expected[0], actual.x(), ROUNDING, what + " x");
        assertEquals(expected[1], actual.y(), ROUNDING, what + " y");
        assertEquals(expected[2], actual.z(), ROUNDING, what + " z");
    }

    @Test
    void objectLevelHelpersAgreeWithTheFlatArrayKernel() {
        Random rnd = new Random(51);
        int n = 3, m = 4;
        double[] net = TestNets.randomNet(rnd, n, m, 3, 2);
        BezierPatch p = new BezierPatch(n, m, net);
        double[] d = new double[9], nrm = new double[3], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        DeCasteljau.evaluateWithDerivatives(net, 0, n, m, 0.3, 0.7, d, scratch);
        PatchNormals.unitNormal(net, 0, n, m, 0.3, 0.7, nrm, 0, scratch);
        assertVec(new double[] {d[0], d[1], d[2]}, Patches.evaluate(p, 0.3, 0.7), "evaluate");
        assertVec(new double[] {d[3], d[4], d[5]}, Patches.dpdu(p, 0.3, 0.7), "dpdu");
        assertVec(new double[] {d[6], d[7], d[8]}, Patches.dpdv(p, 0.3, 0.7), "dpdv");
        assertVec(nrm, Patches.normal(p, 0.3, 0.7), "normal");
        assertEquals(NetMeasures.flatness(net, 0, n, m), Patches.flatness(p), 0);
    }

    @Test
    void splitsAndSubPatchesReproduceTheParent() {
        Random rnd = new Random(52);
        BezierPatch p = new BezierPatch(2, 5, TestNets.randomNet(rnd, 2, 5, 3, 2));
        BezierPatch[] u = Patches.splitU(p, 0.4), v = Patches.splitV(p, 0.4);
        BezierPatch sub = Patches.subPatch(p, 0.1, 0.6, 0.5, 0.9);
        Vec3 a = Patches.evaluate(p, 0.2, 0.3);
        assertVec(new double[] {a.x(), a.y(), a.z()}, Patches.evaluate(u[0], 0.5, 0.3), "splitU low");
        assertVec(new double[] {a.x(), a.y(), a.z()}, Patches.evaluate(v[0], 0.2, 0.75), "splitV low");
        Vec3 b = Patches.evaluate(p, 0.7, 0.85);
        assertVec(new double[] {b.x(), b.y(), b.z()}, Patches.evaluate(u[1], 0.5, 0.85), "splitU high");
        assertVec(new double[] {b.x(), b.y(), b.z()}, Patches.evaluate(v[1], 0.7, 0.75), "splitV high");
        Vec3 c = Patches.evaluate(p, 0.35, 0.7);
        assertVec(new double[] {c.x(), c.y(), c.z()}, Patches.evaluate(sub, 0.5, 0.5), "subPatch");
    }
}
