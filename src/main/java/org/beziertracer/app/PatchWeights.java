package org.beziertracer.app;

import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The weights of rational patches, for the inspector: the one place that knows how a patch holds
 * them. Patches without weights (polynomial patches, all of today's models) have none to show or
 * set. Stateless.
 */
final class PatchWeights {
    private PatchWeights() {}

    /** The weight of {@code P_ij}, or NaN when {@code patch} is not rational. */
    static double weight(BezierPatch patch, int i, int j) {
        return Double.NaN;
    }

    /**
     * {@code scene} with the weight of each point of {@code copies} set to {@code w}.
     *
     * @throws IllegalArgumentException when a patch has no weights
     */
    static Scene withWeight(Scene scene, List<PointRef> copies, double w) {
        throw new IllegalArgumentException("this patch has no weights (it is not rational)");
    }
}
