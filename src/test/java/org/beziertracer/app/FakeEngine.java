package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/** Records render requests instead of rendering. */
public final class FakeEngine implements PictureEngine {
    public final List<RenderRequest> requests = new ArrayList<>();
    public boolean closed;

    @Override
    public void submit(RenderRequest request) { requests.add(request); }

    @Override
    public void onStatus(Consumer<RenderStatus> listener) {}

    @Override
    public boolean busy() { return false; }

    @Override
    public void close() { closed = true; }
}
