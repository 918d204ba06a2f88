package org.beziertracer.app;

import java.util.Objects;
import java.util.function.Consumer;

import org.beziertracer.intersect.Method;

/**
 * The current {@link Settings} and the toolbox's commands on them; every change hands the new
 * value to the owner (which re-renders). UI thread only.
 */
public final class SettingsModel {

    private final Consumer<Settings> onChange;
    private Settings current = Settings.defaults();

    SettingsModel(Consumer<Settings> onChange) {
        this.onChange = onChange;
    }

    public Settings current() { return current; }

    /** Replaces every setting (a loaded scene file's settings, tests). */
    public void replace(Settings s) {
        current = Objects.requireNonNull(s);
        onChange.accept(current);
    }

    /** Replaces every setting without telling the owner (it follows up itself: a model was opened). */
    void replaceQuietly(Settings s) {
        current = Objects.requireNonNull(s);
    }

    public void toggle(Toggle t) { replace(current.with(t, !current.on(t))); }

    public void set(Toggle t, boolean on) { replace(current.with(t, on)); }

    /** @throws IllegalArgumentException one line, outside the level's range */
    public void set(Level l, int value) { replace(current.with(l, value)); }

    /** One step up or down, kept within the range (Finer / Coarser, More / Less Perspective…). */
    public void step(Level l, int delta) { replace(current.with(l, l.step(current.level(l), delta))); }

    /** The next offered choice, wrapping round. */
    public void cycle(Level l) { replace(current.with(l, l.next(current.level(l)))); }

    public void set(Method m) { replace(current.with(m)); }

    public void cycleMethod() { set(Method.values()[(current.method().ordinal() + 1) % Method.values().length]); }

    public void set(LightPlacement p) { replace(current.with(p)); }

    /** Shows the analysis view {@code view} instead of the shading (null: the shading again). */
    public void setAnalysis(org.beziertracer.render.ShadingMode view) { replace(current.withAnalysis(view)); }

    /** The analysis views' settings (View → Analysis → Analysis Settings…). */
    public void setAnalysisSettings(org.beziertracer.render.Analysis a) { replace(current.withAnalysisSettings(a)); }

    public void cycleLight() {
        set(LightPlacement.values()[(current.light().ordinal() + 1) % LightPlacement.values().length]);
    }
}
