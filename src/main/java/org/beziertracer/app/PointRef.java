package org.beziertracer.app;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/** A control point {@code P_ij} of patch {@code patch} of the current scene. */
public record PointRef(int patch, int i, int j) {

    /** True when {@code scene} has this point (a selection may outlive an edit that changed the patches). */
    public boolean in(Scene scene) {
        if (patch < 0 || patch >= scene.patchCount() || i < 0 || j < 0) {
            return false;
        }
        BezierPatch p = scene.patches().get(patch);
        return i <= p.degreeU() && j <= p.degreeV();
    }
}
