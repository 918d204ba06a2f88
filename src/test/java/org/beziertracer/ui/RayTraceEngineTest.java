package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

class RayTraceEngineTest {

    @Test
    void snapshotsAreReusedPatchedOrRebuilt() {
        IntersectOptions io = IntersectOptions.defaults();
        Scene a = Models.teapot();
        SceneIntersector s0 = RayTraceEngine.update(null, a, io);
        assertSame(s0, RayTraceEngine.update(s0, a, io), "same scene: same snapshot");
        Scene b = NetEdits.movePoint(a, new PointRef(5, 1, 1), 1, 2, 3);
        SceneIntersector s1 = RayTraceEngine.update(s0, b, io);
        assertEquals(b.patches(), s1.scene().patches());
        assertSame(s1, RayTraceEngine.update(s1, b, io), "equal scene after a patch edit: reused");
        SceneIntersector s2 = RayTraceEngine.update(s1, b, io.withMethod(Method.NEWTON));
        assertNotSame(s1, s2);
        assertEquals(Method.NEWTON, s2.options().method());
    }
}
