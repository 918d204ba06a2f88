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
    static String noDisplay() {
        return "beziertracer: no display available; set DISPLAY, or use the render, trace "
                + "and info commands (" + launcher() + " --help)";
    }

    /**
     * How this program was started, for hints: the packaged launcher ({@code jpackage} sets
     * {@code jpackage.app-path} to it), else {@code java -jar} and the jar this class came from,
     * else (classes in a build folder) the jar the build makes.
     */
    static String launcher() {
        String app = System.getProperty("jpackage.app-path");
        if (app != null && !app.isBlank()) {
            return app;
        }
        try {
            var source = DisplayCheck.class.getProtectionDomain().getCodeSource();
            if (source != null) {
                java.nio.file.Path jar = java.nio.file.Path.of(source.getLocation().toURI());
                if (jar.getFileName() != null && jar.getFileName().toString().endsWith(".jar")) {
                    return "java -jar " + jar;
                }
            }
        } catch (java.net.URISyntaxException | RuntimeException e) {
            // fall through to the build's jar
        }
        return "java -jar target/beziertracer.jar";
    }

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
