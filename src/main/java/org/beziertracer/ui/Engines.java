package org.beziertracer.ui;

/** Creates the picture engine of the app. */
final class Engines {
    private Engines() {}

    static PictureEngine create() {
        return new RayTraceEngine();
    }
}
