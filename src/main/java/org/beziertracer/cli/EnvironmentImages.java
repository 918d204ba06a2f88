package org.beziertracer.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.beziertracer.model.io.IoReasons;
import org.beziertracer.render.EnvironmentMap;

/** Reads the {@code emap} view's environment image from a PNG or JPEG file, with one-line errors. */
final class EnvironmentImages {
    private EnvironmentImages() {}

    /** Most pixels of an environment image (64 Mpixels), so a huge file is refused before it is decoded. */
    static final long MAX_PIXELS = 1L << 26;

    static EnvironmentMap read(Path file) {
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException(file + ": no such image file");
        }
        BufferedImage img;
        int w, h;
        ImageIO.setUseCache(false);
        try (InputStream in = Files.newInputStream(file);
             javax.imageio.stream.ImageInputStream stream = ImageIO.createImageInputStream(in)) {
            java.util.Iterator<javax.imageio.ImageReader> readers = ImageIO.getImageReaders(stream);
            if (stream == null || !readers.hasNext()) {
                throw new IllegalArgumentException(file + ": not a PNG or JPEG image");
            }
            javax.imageio.ImageReader reader = readers.next();
            try {
                reader.setInput(stream, true, true);
                // the size from the header, before any pixel is decoded
                w = reader.getWidth(0);
                h = reader.getHeight(0);
                if ((long) w * h > MAX_PIXELS || w < 2 || h < 2) {
                    throw new IllegalArgumentException(file + ": an environment image of " + w + "×" + h
                            + " pixels; expected 2×2 up to " + MAX_PIXELS + " pixels");
                }
                img = reader.read(0);
            } finally {
                reader.dispose();
            }
        } catch (IOException e) {
            throw new IllegalArgumentException(file + ": cannot read the image: " + IoReasons.of(e));
        }
        return EnvironmentMap.fromSrgb(w, h, img.getRGB(0, 0, w, h, null, 0, w));
    }
}
