package org.beziertracer.model.io;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;

/** What a scene file (or a built-in scene, or a bare model) provides: the scene and its render settings. */
public record SceneDocument(Scene scene, RenderSettings settings) {
    public SceneDocument {
        if (scene == null || settings == null) {
            throw new IllegalArgumentException("scene and settings are required");
        }
    }
}
