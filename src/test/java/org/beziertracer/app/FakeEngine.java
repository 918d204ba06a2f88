package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/** Records render requests (and exposure changes) instead of rendering. */
public final class FakeEngine implements PictureEngine {
    public final List<RenderRequest> requests = new ArrayList<>();
    /** The exposures {@link #exposure} was told, in order. */
    public final List<Double> exposures = new ArrayList<>();
    public boolean closed;

    @Override
    public void exposure(double stops) { exposures.add(stops); }

    @Override
    public void submit(RenderRequest request) { requests.add(request); }

    @Override
    public void onStatus(Consumer<RenderStatus> listener) {}

    @Override
    public boolean busy() { return false; }

    @Override
    public void close() { closed = true; }
}
