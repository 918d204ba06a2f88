package org.beziertracer.model.io;

import java.util.List;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;

/**
 * What a scene file (or a built-in scene, or a bare model) provides: the scene, its render
 * settings and the reader's notes — one line each, naming the file, about what it read past
 * without drawing ({@code "cad.obj: skipped 12 curv, 4 con (3-D curves and connectivity hints are
 * not drawn)"}); empty for most files. The notes are for the user, shown once ({@code info} prints
 * them, the other commands on standard error, the app in its status line); never an error.
 */
public record SceneDocument(Scene scene, RenderSettings settings, List<String> notes) {
    public SceneDocument {
        if (scene == null || settings == null) {
            throw new IllegalArgumentException("scene and settings are required");
        }
        notes = notes == null ? List.of() : List.copyOf(notes);
    }

    /** A document without notes. */
    public SceneDocument(Scene scene, RenderSettings settings) {
        this(scene, settings, List.of());
    }
}
