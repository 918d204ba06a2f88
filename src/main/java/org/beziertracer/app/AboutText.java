package org.beziertracer.app;

import org.beziertracer.math.Kernels;

/** The text of Help → About: what the app is, how to use it, and which Java and kernel run it. */
public final class AboutText {
    private AboutText() {}

    /** A few lines for the About dialog; the last names the Java version and the evaluation kernel. */
    public static String text() {
        return "Bézier Tracer — ray tracing Bézier surfaces directly.\n"
                + "Drag control points, drag empty space to rotate, wheel to zoom.\n\n"
                + "Java " + System.getProperty("java.version") + "; kernel: " + Kernels.best().description();
    }
}
