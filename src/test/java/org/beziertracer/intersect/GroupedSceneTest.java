package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.accel.Bvh;
import org.beziertracer.accel.BvhOptions;
import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * A big scene, whose hierarchy is built in two levels ({@link BvhOptions#groupsPay}): 100 teapots
 * on a grid answer every ray as the nearest of the answers of one teapot to the ray moved to each
 * copy.
 */
class GroupedSceneTest {

    static final int COPIES = 100, SIDE = 10;

    @Test
    void aHundredTeapotsAnswerAsTheNearestOfTheirCopies() {
        List<BezierPatch> teapot = Models.teapot().patches();
        List<BezierPatch> all = new ArrayList<>();
        double[] shift = new double[2 * COPIES];
        for (int c = 0; c < COPIES; c++) {
            shift[2 * c] = 300.0 * (c % SIDE);
            shift[2 * c + 1] = 200.0 * (c / SIDE);
            for (BezierPatch p : teapot) {
                double[] net = p.copyNet();
                for (int i = 0; i < net.length; i += 3) {
                    net[i] += shift[2 * c];
                    net[i + 1] += shift[2 * c + 1];
                }
                all.add(new BezierPatch(p.degreeU(), p.degreeV(), net));
            }
        }
        Scene big = new Scene(all), one = new Scene(teapot);
        SceneIntersector sBig = SceneIntersector.build(big, IntersectOptions.defaults());
        SceneIntersector sOne = SceneIntersector.build(one, IntersectOptions.defaults());
        assertTrue(BvhOptions.groupsPay(sBig.leaves.count(), all.size()), "not a two-level scene: "
                + sBig.leaves.count() + " leaves");
        assertTrue(sBig.accel instanceof Bvh);
        double size = big.controlBounds().diagonal(), tol = 1e-9 * size;
        TraceContext cBig = sBig.newContext(), cOne = sOne.newContext();
        Hit hBig = new Hit(), hOne = new Hit();
        double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        Random rnd = new Random(41);
        int hits = 0;
        for (int r = 0; r < 400; r++) {
            // Aimed at a random point of a random patch of a random copy, from a random direction
            int c = rnd.nextInt(COPIES);
            BezierPatch p = teapot.get(rnd.nextInt(teapot.size()));
            DeCasteljau.evaluateWithDerivatives(p.copyNet(), 0, p.degreeU(), p.degreeV(), rnd.nextDouble(),
                    rnd.nextDouble(), e, scratch);
            double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
            double ox = e[0] + shift[2 * c] - 400 * dx, oy = e[1] + shift[2 * c + 1] - 400 * dy, oz = e[2] - 400 * dz;
            boolean got = sBig.closestHit(cBig, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hBig);
            double nearest = Double.POSITIVE_INFINITY;
            for (int k = 0; k < COPIES; k++) {
                if (sOne.closestHit(cOne, ox - shift[2 * k], oy - shift[2 * k + 1], oz, dx, dy, dz, 0, nearest, hOne)) {
                    nearest = hOne.t;
                }
            }
            String in = "ray " + r + " at copy " + c;
            assertEquals(nearest < Double.POSITIVE_INFINITY, got, in);
            if (got) {
                hits++;
                assertEquals(nearest, hBig.t, tol, in);
                assertTrue(sBig.occluded(cBig, ox, oy, oz, dx, dy, dz, 0, hBig.t * 1.001), in + ": not occluded before the hit");
            }
        }
        assertTrue(hits > 300, "only " + hits + " of 400 aimed rays hit");
    }
}
