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
        launch(args.length > 0 ? args[0] : null);
    }

    /**
     * Opens the main window with the user's preferences, then — when {@code model} is not null —
     * the file or built-in model it names; returns at once (the app lives on the event thread).
     */
    public static void launch(String model) {
        start(AppPreferences.user(), model);
    }

    /**
     * Opens the main window, then the file or built-in {@code model} names (when not null), and
     * completes with the window once shown.
     *
     * @param prefs where the theme and recent files are kept (tests pass a node of their own)
     */
    public static CompletableFuture<AppFrame> start(AppPreferences prefs, String model) {
        return start(prefs).thenApply(frame -> {
            if (model != null) {
                SwingUtilities.invokeLater(() -> frame.app().files().openArgument(model));
            }
            return frame;
        });
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
                        AppThreads.start(SwingUtilities::invokeLater), prefs), theme);
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
