package org.beziertracer.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.prefs.Preferences;

/**
 * What the app remembers between runs, in one {@link Preferences} node: the theme, the exposure of
 * the path-traced picture (Render → Exposure) and the recent files (File → Open Recent, the last
 * {@value #MAX_RECENT}, newest first). The desktop app uses the user's node {@value #NODE}; tests inject a node of their
 * own (an in-memory one), so they never write the user's preferences. A node that cannot be read
 * or written (no preferences store) is treated as empty, and a choice then lasts for the run only.
 */
public final class AppPreferences {

    /** The user's node of the desktop app (the same as before this class existed). */
    public static final String NODE = "org/beziertracer/ui";
    static final String THEME = "theme";
    static final String RECENT = "recent.";
    static final String EXPOSURE = "exposure";
    /** Files File → Open Recent lists. */
    public static final int MAX_RECENT = 8;

    private final Preferences node;

    public AppPreferences(Preferences node) {
        this.node = node;
    }

    /** The user's own preferences. */
    public static AppPreferences user() {
        prepareUserRoot();
        return new AppPreferences(Preferences.userRoot().node(NODE));
    }

    /**
     * Creates the folder of the JDK's file-based preferences ({@code ~/.java/.userPrefs}, or under
     * {@code java.util.prefs.userRoot}) when it is missing: the JDK would create it too, but logs
     * two lines on standard error as it does ("INFO: Created user preferences directory.") at
     * every user's first launch. Private to the user, as the JDK makes it; any failure is left
     * for the JDK to meet (and report) as before. Only where that store is used (not Windows or macOS).
     */
    static void prepareUserRoot() {
        String os = System.getProperty("os.name", "");
        if (os.startsWith("Windows") || os.startsWith("Mac")) {
            return;
        }
        try {
            Path root = Path.of(System.getProperty("java.util.prefs.userRoot", System.getProperty("user.home")),
                    ".java", ".userPrefs");
            if (!java.nio.file.Files.isDirectory(root)) {
                java.nio.file.Files.createDirectories(root);
                try {
                    java.nio.file.Files.setPosixFilePermissions(root,
                            java.nio.file.attribute.PosixFilePermissions.fromString("rwx------"));
                } catch (UnsupportedOperationException e) {
                    // not a POSIX file system: its own defaults apply
                }
            }
        } catch (java.io.IOException | RuntimeException e) {
            // the JDK tries again and says what went wrong
        }
    }

    /** The node written to (tests check what landed there). */
    public Preferences node() { return node; }

    public boolean darkTheme() {
        return "dark".equals(get(THEME, "light"));
    }

    public void setDarkTheme(boolean dark) {
        put(THEME, dark ? "dark" : "light");
    }

    /**
     * The exposure last chosen, in tenths of a stop ({@link Level#EXPOSURE}); 0 when none was, or
     * when the stored value is not a number in the level's range.
     */
    public int exposureTenths() {
        try {
            int v = Integer.parseInt(get(EXPOSURE, "0").trim());
            return v >= Level.EXPOSURE.min() && v <= Level.EXPOSURE.max() ? v : 0;
        } catch (NumberFormatException e) {
            return 0;
        }
    }

    public void setExposureTenths(int tenths) {
        put(EXPOSURE, Integer.toString(Level.EXPOSURE.check(tenths)));
    }

    /** The files opened or saved last, newest first (at most {@value #MAX_RECENT}). */
    public List<Path> recentFiles() {
        List<Path> out = new ArrayList<>();
        for (int k = 0; k < MAX_RECENT; k++) {
            String v = get(RECENT + k, null);
            if (v != null && !v.isEmpty()) {
                // a value this system cannot read as a path is left out
                org.beziertracer.model.io.FilePaths.find(v).ifPresent(out::add);
            }
        }
        return out;
    }

    /** Puts {@code file} first in the recent files (once), keeping the newest {@value #MAX_RECENT}. */
    public void addRecent(Path file) {
        Path abs = file.toAbsolutePath().normalize();
        List<Path> list = new ArrayList<>(recentFiles());
        list.remove(abs);
        list.add(0, abs);
        storeRecent(list);
    }

    /** Takes {@code file} off the recent files (it could not be opened). */
    public void removeRecent(Path file) {
        List<Path> list = new ArrayList<>(recentFiles());
        if (list.remove(file.toAbsolutePath().normalize()) | list.remove(file)) {
            storeRecent(list);
        }
    }

    private void storeRecent(List<Path> list) {
        for (int k = 0; k < MAX_RECENT; k++) {
            put(RECENT + k, k < list.size() ? list.get(k).toString() : "");
        }
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
