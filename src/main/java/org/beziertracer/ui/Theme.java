package org.beziertracer.ui;

import java.awt.Window;

import javax.swing.SwingUtilities;
import javax.swing.UIManager;

import org.beziertracer.app.AppPreferences;

import com.formdev.flatlaf.FlatDarkLaf;
import com.formdev.flatlaf.FlatLaf;
import com.formdev.flatlaf.FlatLightLaf;

/**
 * Look-and-feel set-up: FlatLaf light or dark, the user's choice kept in the app's
 * {@link AppPreferences} (injected, so tests use a node of their own); falls back to the platform
 * look and feel when FlatLaf cannot be installed. Theme colours live in {@code FlatLightLaf.properties}
 * / {@code FlatDarkLaf.properties} in {@code org.beziertracer.ui.themes} (registered with
 * {@code FlatLaf.registerCustomDefaultsSource}). Event thread only (except {@link #install},
 * called before any component exists).
 */
public final class Theme {

    private final AppPreferences prefs;
    private boolean dark;

    public Theme(AppPreferences prefs) {
        this.prefs = prefs;
    }

    /** Installs the saved theme (light by default). */
    public void install() {
        FlatLaf.registerCustomDefaultsSource("org.beziertracer.ui.themes");
        dark = prefs.darkTheme();
        apply();
    }

    private void apply() {
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

    public boolean isDark() { return dark; }

    /** Switches light ↔ dark, saves the choice and updates every open window. */
    public void toggle() {
        dark = !dark;
        prefs.setDarkTheme(dark);
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
