package org.beziertracer.ui;

import java.awt.Window;
import java.util.prefs.Preferences;

import javax.swing.SwingUtilities;
import javax.swing.UIManager;

import com.formdev.flatlaf.FlatDarkLaf;
import com.formdev.flatlaf.FlatLaf;
import com.formdev.flatlaf.FlatLightLaf;

/**
 * Look-and-feel set-up: FlatLaf light or dark, the user's choice kept in
 * {@link Preferences} (node {@code org/beziertracer/ui}, key {@value #KEY}); falls back to the
 * platform look and feel when FlatLaf cannot be installed. Theme colours live in
 * {@code FlatLightLaf.properties} / {@code FlatDarkLaf.properties} next to this class (FlatLaf
 * loads them from the package registered with {@code FlatLaf.registerCustomDefaultsSource}).
 * Event thread only (except {@link #install}, called before any component exists).
 */
public final class Theme {

    static final String KEY = "theme";
    private static boolean dark;

    private Theme() {}

    private static Preferences prefs() {
        return Preferences.userNodeForPackage(Theme.class);
    }

    /** Installs the saved theme (light by default). */
    public static void install() {
        FlatLaf.registerCustomDefaultsSource("org.beziertracer.ui.themes");
        dark = "dark".equals(safeGet());
        apply();
    }

    private static String safeGet() {
        try {
            return prefs().get(KEY, "light");
        } catch (RuntimeException | Error e) {
            return "light";
        }
    }

    private static void apply() {
        try {
            if (!(dark ? FlatDarkLaf.setup() : FlatLightLaf.setup())) {
                throw new IllegalStateException("FlatLaf setup failed");
            }
        } catch (RuntimeException | LinkageError e) {
            try {
                UIManager.setLookAndFeel(UIManager.getSystemLookAndFeelClassName());
            } catch (Exception ignored) {
                // keep Swing's default look and feel
            }
        }
    }

    public static boolean isDark() { return dark; }

    /** Switches light ↔ dark, saves the choice and updates every open window. */
    public static void toggle() {
        dark = !dark;
        try {
            prefs().put(KEY, dark ? "dark" : "light");
        } catch (RuntimeException e) {
            // preferences unavailable: the choice lasts for this run only
        }
        apply();
        if (UIManager.getLookAndFeel() instanceof FlatLaf) {
            FlatLaf.updateUI();
        } else {
            for (Window w : Window.getWindows()) {
                SwingUtilities.updateComponentTreeUI(w);
            }
        }
    }
}
