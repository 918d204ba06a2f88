package org.beziertracer.cli;

import java.awt.GraphicsEnvironment;

/**
 * Whether the desktop app can open a window here: not when Java runs headless, and not when the
 * display it names cannot be reached ({@code DISPLAY} pointing nowhere), which AWT would report
 * with an error and a stack trace. Asked once, before anything else touches AWT.
 */
final class DisplayCheck {
    private DisplayCheck() {}

    /** What the command line prints when there is no display (one line, exit code 3). */
    static final String NO_DISPLAY = "beziertracer: no display available; set DISPLAY, or use the render, trace "
            + "and info commands (java -jar target/beziertracer.jar --help)";

    static boolean displayReachable() {
        if (GraphicsEnvironment.isHeadless()) {
            return false;
        }
        try {
            return GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices().length > 0;
        } catch (RuntimeException | Error e) {
            // AWTError "Can't connect to X11 window server", a missing native library, …
            return false;
        }
    }
}
