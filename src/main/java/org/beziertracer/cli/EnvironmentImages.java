package org.beziertracer.cli;

import java.nio.file.Path;

import org.beziertracer.model.io.ImageFiles;
import org.beziertracer.render.EnvironmentMap;

/** Reads the {@code emap} view's environment image from a PNG or JPEG file, with one-line errors. */
final class EnvironmentImages {
    private EnvironmentImages() {}

    /** Most pixels of an environment image (64 Mpixels), so a huge file is refused before it is decoded. */
    static final long MAX_PIXELS = 1L << 26;

    static EnvironmentMap read(Path file) {
        ImageFiles.Argb picture = ImageFiles.read(file, "an environment image", 2, MAX_PIXELS);
        return EnvironmentMap.fromSrgb(picture.width(), picture.height(), picture.argb());
    }
}
