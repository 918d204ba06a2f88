package org.beziertracer.app;

import java.util.List;

/**
 * Everything the overlay painter reads, in one immutable value: the prepared geometry, the
 * hovered handle and the selected points. The painter draws it and never calls back.
 *
 * @param geometry the latest built overlay (maybe for the previous view for a few milliseconds)
 * @param hover    the handle under the cursor, or null
 * @param selected the selected points where they are now (projected on the UI thread: the cost
 *                 grows with the selection, not with the model)
 */
public record OverlaySnapshot(OverlayGeometry geometry, Handle hover, List<Handle> selected) {

    public static final OverlaySnapshot EMPTY = new OverlaySnapshot(OverlayGeometry.EMPTY, null, List.of());

    public OverlaySnapshot {
        selected = List.copyOf(selected);
    }
}
