package org.beziertracer.ui;

import org.beziertracer.model.io.ModelFormatException;
import org.beziertracer.model.io.SceneDocument;

/** Scene files (JSON) and built-in scenes; placeholder until the scene-file reader is merged. */
final class SceneSource {
    private SceneSource() {}

    static SceneDocument load(String nameOrPath) {
        throw new ModelFormatException(nameOrPath, "scene files are not supported by this build yet");
    }
}
