package org.beziertracer.ui;

import java.awt.image.BufferedImage;
import java.io.IOException;

import javax.imageio.ImageIO;

import org.beziertracer.model.io.AtomicFiles;

/** Encodes a picture as PNG for an atomic write (Export Picture). Stateless. */
final class PngFiles {
    private PngFiles() {}

    /** What writes {@code argb} ({@code width × height}, row after row) as PNG (Export Image). */
    static AtomicFiles.BinaryContent encoder(int width, int height, int[] argb) {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, width, height, argb, 0, width);
        return content(img);
    }

    /** What writes {@code image} as PNG; the image must not change afterwards. */
    static AtomicFiles.BinaryContent content(BufferedImage image) {
        return out -> {
            if (!ImageIO.write(image, "png", out)) {
                throw new IOException("no PNG writer available");
            }
        };
    }
}
