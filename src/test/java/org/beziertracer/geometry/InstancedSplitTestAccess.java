package org.beziertracer.geometry;

import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Placement;
import org.beziertracer.model.Scene;

/** The instanced scenes of {@link InstancedSplitTest}, for the tests of the layers above. */
public final class InstancedSplitTestAccess {
    private InstancedSplitTestAccess() {}

    /** Four uses: in place, shifted, turned and shrunk, mirrored and turned. */
    public static Placement[] uses() {
        return new Placement[] {InstancedSplitTest.Affine.shift(0, 0, 0), InstancedSplitTest.Affine.shift(7, 1, 0),
            new InstancedSplitTest.Affine(40, 15, new double[] {0.5, 0.5, 0.5}, new double[] {0, 6, 1}),
            new InstancedSplitTest.Affine(-75, 0, new double[] {-1, 1, 1}, new double[] {8, 7, -1})};
    }

    public static Scene scene(List<BezierPatch> model, Placement... uses) {
        return InstancedSplitTest.scene(model, uses);
    }
}
