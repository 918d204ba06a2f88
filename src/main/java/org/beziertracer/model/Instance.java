package org.beziertracer.model;

import java.util.List;
import java.util.Objects;

/**
 * A model used in a scene: the scene's patches {@code first .. first+count-1} are the model's
 * patches mapped by {@code placement}, in order. Scenes that list one model several times (the
 * same built-in or file with other transforms) hold one {@code Instance} per use, all with the
 * same {@code model} list, so the acceleration build can split each distinct model once
 * (pbrt-v4 and Embree build one bottom level per distinct shape the same way).
 *
 * @param first     the scene's index of the first placed patch
 * @param model     the model's patches, in model space; shared by every use of the model
 * @param placement the map from model to scene space
 */
public record Instance(int first, List<BezierPatch> model, Placement placement) {

    public Instance {
        Objects.requireNonNull(model, "model");
        Objects.requireNonNull(placement, "placement");
        if (first < 0) {
            throw new IllegalArgumentException("first patch must be ≥ 0, got " + first);
        }
    }

    /** Number of placed patches. */
    public int count() { return model.size(); }

    /** True when scene patch {@code k} is one of this instance's. */
    public boolean covers(int k) { return k >= first && k < first + model.size(); }
}
