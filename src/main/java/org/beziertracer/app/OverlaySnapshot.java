package org.beziertracer.app;

import java.util.List;

/**
 * Everything the overlay painter reads, in one immutable value: the prepared geometry, the
 * hovered handle, the selected points, the rubber band being drawn and the light markers. The
 * painter draws it and never calls back.
 *
 * @param geometry the latest built overlay (maybe for the previous view for a few milliseconds)
 * @param hover    the handle under the cursor, or null
 * @param selected the selected points where they are now (a bounded number, projected on the UI
 *                 thread: the cost grows with that number, not with the model)
 * @param band     the rubber band {@code x0, y0, x1, y1} in picture pixels, or null
 * @param lights   the light markers ("Show light"), empty when off
 */
public record OverlaySnapshot(OverlayGeometry geometry, Handle hover, List<Handle> selected, double[] band,
                             List<LightMarker> lights) {

    public static final OverlaySnapshot EMPTY = new OverlaySnapshot(OverlayGeometry.EMPTY, null, List.of(), null,
            List.of());

    public OverlaySnapshot {
        selected = List.copyOf(selected);
        band = band == null ? null : band.clone();
        lights = List.copyOf(lights);
    }

    OverlaySnapshot withGeometry(OverlayGeometry g, Handle h) { return new OverlaySnapshot(g, h, selected, band, lights); }

    OverlaySnapshot withHover(Handle h) { return new OverlaySnapshot(geometry, h, selected, band, lights); }

    OverlaySnapshot withSelected(List<Handle> s) { return new OverlaySnapshot(geometry, hover, s, band, lights); }

    OverlaySnapshot withBand(double[] b) { return new OverlaySnapshot(geometry, hover, selected, b, lights); }

    OverlaySnapshot withLights(List<LightMarker> l) { return new OverlaySnapshot(geometry, hover, selected, band, l); }
}
