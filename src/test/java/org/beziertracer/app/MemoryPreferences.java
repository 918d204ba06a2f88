package org.beziertracer.app;

import java.util.HashMap;
import java.util.Map;
import java.util.prefs.AbstractPreferences;

/**
 * Preferences held in memory only: tests give the app a fresh root of these, so no test reads or
 * writes the user's own preferences and no test sees another's.
 */
public final class MemoryPreferences extends AbstractPreferences {

    private final Map<String, String> values = new HashMap<>();
    private final Map<String, MemoryPreferences> children = new HashMap<>();

    private MemoryPreferences(MemoryPreferences parent, String name) {
        super(parent, name);
    }

    /** The app's preferences in a new, empty in-memory root. */
    public static AppPreferences fresh() {
        return new AppPreferences(root().node(AppPreferences.NODE));
    }

    /** A new, empty root. */
    public static MemoryPreferences root() {
        return new MemoryPreferences(null, "");
    }

    @Override
    protected void putSpi(String key, String value) { values.put(key, value); }

    @Override
    protected String getSpi(String key) { return values.get(key); }

    @Override
    protected void removeSpi(String key) { values.remove(key); }

    @Override
    protected void removeNodeSpi() { children.clear(); }

    @Override
    protected String[] keysSpi() { return values.keySet().toArray(String[]::new); }

    @Override
    protected String[] childrenNamesSpi() { return children.keySet().toArray(String[]::new); }

    @Override
    protected AbstractPreferences childSpi(String name) {
        return children.computeIfAbsent(name, n -> new MemoryPreferences(this, n));
    }

    @Override
    protected void syncSpi() {}

    @Override
    protected void flushSpi() {}
}
