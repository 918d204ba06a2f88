package org.beziertracer.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/** Records render requests instead of rendering. */
final class FakeEngine implements PictureEngine {
    final List<RenderRequest> requests = new ArrayList<>();
    boolean closed;

    @Override
    public void submit(RenderRequest request) { requests.add(request); }

    @Override
    public void onStatus(Consumer<RenderStatus> listener) {}

    @Override
    public boolean busy() { return false; }

    @Override
    public void close() { closed = true; }
}
