package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The weights of rational patches, for the inspector: the one place that knows how a patch holds
 * them. A polynomial patch has no weight to show; a weight typed for a handle whose copies lie on
 * rational patches sets it on every copy (a polynomial copy becomes rational, its other weights
 * 1, so the welded copies stay one surface). Stateless.
 */
final class PatchWeights {
    private PatchWeights() {}

    /** The weight of {@code P_ij}, or NaN when {@code patch} is not rational. */
    static double weight(BezierPatch patch, int i, int j) {
        return patch.isRational() ? patch.weight(i, j) : Double.NaN;
    }

    /**
     * {@code scene} with the weight of each point of {@code copies} set to {@code w} (positive and
     * finite: the inspector checks it).
     *
     * @throws IllegalArgumentException when no copy lies on a rational patch
     */
    static Scene withWeight(Scene scene, List<PointRef> copies, double w) {
        if (copies.stream().noneMatch(r -> scene.patches().get(r.patch()).isRational())) {
            throw new IllegalArgumentException("this patch has no weights (it is not rational)");
        }
        List<BezierPatch> patches = new ArrayList<>(scene.patches());
        for (PointRef r : copies) {
            BezierPatch p = patches.get(r.patch());
            int n = p.degreeU();
            double[] weights = p.isRational() ? p.weights() : ones(p.pointCount());
            weights[r.j() * (n + 1) + r.i()] = w;
            // an edited piece is no longer its free-form surface's (no origin to write back)
            patches.set(r.patch(), new BezierPatch(n, p.degreeV(), p.copyNet(), weights, p.domain(), null));
        }
        return scene.toBuilder().patches(patches).build();
    }

    private static double[] ones(int count) {
        double[] w = new double[count];
        java.util.Arrays.fill(w, 1);
        return w;
    }
}
