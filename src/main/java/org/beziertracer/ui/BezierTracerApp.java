package org.beziertracer.ui;

import java.util.concurrent.CompletableFuture;

import javax.swing.SwingUtilities;

/**
 * Desktop-app bootstrap: system properties, the look and feel ({@link Theme}), then the window,
 * built on the event thread. {@code main} only bootstraps.
 */
public final class BezierTracerApp {
    private BezierTracerApp() {}

    public static void main(String[] args) {
        launch();
    }

    /** Opens the main window; returns at once (the app lives on the event thread). */
    public static void launch() {
        start();
    }

    /** Opens the main window and completes with it once shown (tests use the frame). */
    public static CompletableFuture<AppFrame> start() {
        setProperties();
        CompletableFuture<AppFrame> shown = new CompletableFuture<>();
        SwingUtilities.invokeLater(() -> {
            try {
                Theme.install();
                AppFrame frame = new AppFrame(Engines.create());
                frame.setVisible(true);
                shown.complete(frame);
            } catch (RuntimeException | Error e) {
                shown.completeExceptionally(e);
                throw e;
            }
        });
        return shown;
    }

    private static void setProperties() {
        System.setProperty("awt.useSystemAAFontSettings", System.getProperty("awt.useSystemAAFontSettings", "on"));
        System.setProperty("swing.aatext", "true");
        System.setProperty("flatlaf.menuBarEmbedded", "false");
    }
}
