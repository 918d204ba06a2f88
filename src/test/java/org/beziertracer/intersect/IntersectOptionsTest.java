package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.UserMessages;
import org.beziertracer.accel.BvhOptions;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.Tessellator;
import org.junit.jupiter.api.Test;

/** {@link IntersectOptions} and {@link Method}: the range of the tessellation, the copies, parsing and labels. */
class IntersectOptionsTest {

    @Test
    void theTessellationRangesFromExactToTheTessellatorsLimit() {
        IntersectOptions o = IntersectOptions.defaults();
        assertFalse(o.tessellated());
        assertTrue(o.withTessellate(1).tessellated());
        assertEquals(Tessellator.MAX_SEGMENTS, o.withTessellate(Tessellator.MAX_SEGMENTS).tessellate());
        String message = UserMessages.of(IllegalArgumentException.class, () -> o.withTessellate(Tessellator.MAX_SEGMENTS + 1));
        assertEquals("tessellate must be 0 (exact) or 1..1024, got 1025", message);
    }

    @Test
    void eachCopyChangesOneThing() {
        IntersectOptions o = IntersectOptions.defaults().withTessellate(3);
        BvhOptions bvh = new BvhOptions(2, 8);
        IntersectOptions b = o.withBvhOptions(bvh);
        assertSame(bvh, b.bvhOptions());
        assertEquals(new IntersectOptions(o.method(), o.bvh(), o.split(), bvh, 3), b);
        SplitOptions split = new SplitOptions(true, 0.2, 3);
        assertEquals(new IntersectOptions(o.method(), o.bvh(), split, o.bvhOptions(), 3), o.withSplit(split));
        assertEquals(SplitOptions.wholePatches(), o.withBvh(false).effectiveSplit());
        assertEquals(o.split(), o.effectiveSplit());
        // a method's default split follows the method; a chosen one stays
        assertEquals(Method.NEWTON.defaultSplit(), o.withMethod(Method.NEWTON).split());
        assertEquals(split, o.withSplit(split).withMethod(Method.NEWTON).split());
    }

    @Test
    void methodsParseCaseInsensitivelyAndHaveLowerCaseLabels() {
        for (Method m : Method.values()) {
            assertSame(m, Method.parse(m.label()));
            assertSame(m, Method.parse(" " + m.name() + " "));
            assertEquals(m.name().toLowerCase(java.util.Locale.ROOT), m.label());
        }
        assertEquals("clipping", Method.CLIPPING.label());
        assertEquals("unknown method 'clip': expected clipping, newton or subdivision",
                UserMessages.of(IllegalArgumentException.class, () -> Method.parse("clip")));
    }

    @Test
    void aHitDescribesItsParameterAndPrimitive() {
        Hit hit = new Hit();
        hit.t = 2.5;
        hit.u = 0.25;
        hit.v = 0.75;
        hit.kind = Hit.SPHERE;
        hit.index = 4;
        assertEquals("Hit[t=2.5, u=0.25, v=0.75, kind=2, index=4]", hit.toString());
    }
}
