package org.beziertracer.ui;

import java.util.concurrent.CompletableFuture;

import javax.swing.SwingUtilities;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.AppPreferences;
import org.beziertracer.app.AppThreads;
import org.beziertracer.app.RayTraceEngine;

/**
 * Desktop-app bootstrap: system properties, the look and feel ({@link Theme}), the handler of
 * uncaught errors, then the window, built on the event thread. {@code main} only bootstraps.
 */
public final class BezierTracerApp {
    private BezierTracerApp() {}

    public static void main(String[] args) {
        launch();
    }

    /** Opens the main window with the user's preferences; returns at once (the app lives on the event thread). */
    public static void launch() {
        start(AppPreferences.user());
    }

    /**
     * Opens the main window and completes with it once shown.
     *
     * @param prefs where the theme is kept (tests pass a node of their own)
     */
    public static CompletableFuture<AppFrame> start(AppPreferences prefs) {
        setProperties();
        CompletableFuture<AppFrame> shown = new CompletableFuture<>();
        SwingUtilities.invokeLater(() -> {
            try {
                Theme theme = new Theme(prefs);
                theme.install();
                AppFrame frame = new AppFrame(dialogs -> new AppModel(new RayTraceEngine(), dialogs,
                        AppThreads.start(SwingUtilities::invokeLater)), theme);
                UncaughtErrors.install(frame);
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
