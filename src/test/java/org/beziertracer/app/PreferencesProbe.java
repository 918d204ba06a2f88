package org.beziertracer.app;

/** A child process for {@link FirstLaunchTest}: remembers a theme in the user's preferences, as the app does. */
public final class PreferencesProbe {
    private PreferencesProbe() {}

    public static void main(String[] args) throws Exception {
        AppPreferences prefs = AppPreferences.user();
        prefs.node().put(AppPreferences.THEME, "dark");
        prefs.node().flush();
        System.out.println(AppPreferences.user().darkTheme() ? "dark" : "light");
    }
}
