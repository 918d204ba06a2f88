package org.beziertracer.model;

import java.util.List;

/**
 * The trimmed part of a surface's parameter domain: a parameter point is kept when it lies
 * inside at least one {@code outer} loop (or there is none) and inside no {@code holes} loop,
 * whatever the loops' orientation (OBJ {@code trim} and {@code hole} statements). Immutable;
 * shared by every Bézier piece of the surface. Equal when the loops are equal.
 */
public record TrimRegion(List<TrimLoop> outer, List<TrimLoop> holes) {
    public TrimRegion {
        outer = List.copyOf(outer);
        holes = List.copyOf(holes);
        if (outer.isEmpty() && holes.isEmpty()) {
            throw new IllegalArgumentException("a trim region needs at least one loop");
        }
    }

    /** Number of loops, outer and holes. */
    public int loopCount() { return outer.size() + holes.size(); }
}
