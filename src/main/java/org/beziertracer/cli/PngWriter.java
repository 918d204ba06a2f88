package org.beziertracer.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.beziertracer.model.io.AtomicFiles;

/**
 * Writes sRGB ARGB pixels as a PNG, atomically: into a temporary file next to the target, then
 * moved over it (ImageIO lives here, in {@code cli}, so {@code render} stays free of AWT).
 */
final class PngWriter {
    private PngWriter() {}

    static void write(Path target, int width, int height, int[] argb) throws IOException {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, width, height, argb, 0, width);
        AtomicFiles.writeBytes(target, out -> {
            if (!ImageIO.write(img, "png", out)) {
                throw new IOException("no PNG writer available");
            }
        });
    }
}
