package org.beziertracer.app;

import java.util.prefs.Preferences;

/**
 * What the app remembers between runs, in one {@link Preferences} node: the theme (and, later,
 * recent files). The desktop app uses the user's node {@value #NODE}; tests inject a node of their
 * own (an in-memory one), so they never write the user's preferences. A node that cannot be read
 * or written (no preferences store) is treated as empty, and a choice then lasts for the run only.
 */
public final class AppPreferences {

    /** The user's node of the desktop app (the same as before this class existed). */
    public static final String NODE = "org/beziertracer/ui";
    static final String THEME = "theme";

    private final Preferences node;

    public AppPreferences(Preferences node) {
        this.node = node;
    }

    /** The user's own preferences. */
    public static AppPreferences user() {
        return new AppPreferences(Preferences.userRoot().node(NODE));
    }

    /** The node written to (tests check what landed there). */
    public Preferences node() { return node; }

    public boolean darkTheme() {
        return "dark".equals(get(THEME, "light"));
    }

    public void setDarkTheme(boolean dark) {
        put(THEME, dark ? "dark" : "light");
    }

    private String get(String key, String fallback) {
        try {
            return node.get(key, fallback);
        } catch (RuntimeException e) {
            return fallback;
        }
    }

    private void put(String key, String value) {
        try {
            node.put(key, value);
        } catch (RuntimeException e) {
            // no preferences store: the choice lasts for this run only
        }
    }
}
