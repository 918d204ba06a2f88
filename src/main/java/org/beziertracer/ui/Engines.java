package org.beziertracer.ui;

import java.util.function.Consumer;

/** Creates the picture engine; a placeholder that renders nothing until the renderer is wired. */
final class Engines {
    private Engines() {}

    static PictureEngine create() {
        return new PictureEngine() {
            @Override
            public void submit(RenderRequest request) {
                request.target().requestRepaint();
            }

            @Override
            public void onStatus(Consumer<RenderStatus> listener) {}

            @Override
            public boolean busy() { return false; }

            @Override
            public void close() {}
        };
    }
}
