package org.beziertracer.model.io;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

import org.beziertracer.model.HdrImage;

/**
 * Reads 8-bit pictures (PNG, JPEG: whatever the JDK's ImageIO decodes) with one-line errors
 * naming the file, the size checked from the header before any pixel is decoded. Headless: it
 * uses only ImageIO's decoders and {@code java.awt.image} rasters, never a display (the one
 * class of {@code model.io} that may, see docs/architecture.md). Stateless.
 */
public final class ImageFiles {
    private ImageFiles() {}

    /** A decoded picture: {@code argb[y * width + x]}, row 0 at the top. */
    public record Argb(int width, int height, int[] argb) {}

    /**
     * The picture in {@code file}; an error when it is missing, not an image, or outside
     * {@code minSide × minSide} .. {@code maxPixels} pixels ({@code what} names it: "an environment
     * image").
     */
    public static Argb read(Path file, String what, int minSide, long maxPixels) {
        String name = file.toString();
        if (!Files.isRegularFile(file)) {
            throw new ModelFormatException(name, "no such image file");
        }
        ImageIO.setUseCache(false);
        try (InputStream in = Files.newInputStream(file); ImageInputStream stream = ImageIO.createImageInputStream(in)) {
            Iterator<ImageReader> readers = stream == null ? null : ImageIO.getImageReaders(stream);
            if (readers == null || !readers.hasNext()) {
                throw new ModelFormatException(name, "not a PNG or JPEG image");
            }
            ImageReader reader = readers.next();
            try {
                reader.setInput(stream, true, true);
                // the size from the header, before any pixel is decoded
                int w = reader.getWidth(0), h = reader.getHeight(0);
                if ((long) w * h > maxPixels || w < minSide || h < minSide) {
                    throw new ModelFormatException(name, what + " of " + w + "×" + h + " pixels; expected "
                            + minSide + "×" + minSide + " up to " + maxPixels + " pixels");
                }
                BufferedImage img = reader.read(0);
                return new Argb(w, h, img.getRGB(0, 0, w, h, null, 0, w));
            } finally {
                reader.dispose();
            }
        } catch (IOException | RuntimeException e) {
            if (e instanceof ModelFormatException m) {
                throw m;
            }
            String reason = e instanceof IOException io ? IoReasons.of(io) : "not a readable PNG or JPEG image";
            throw new ModelFormatException(name, "cannot read the image: " + reason);
        }
    }

    /** Linear RGB of an sRGB picture (IEC 61966-2-1's transfer curve undone; alpha ignored). */
    public static HdrImage linear(Argb picture) {
        float[] table = new float[256];
        for (int k = 0; k < 256; k++) {
            double c = k / 255.0;
            table[k] = (float) (c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4));
        }
        int[] argb = picture.argb();
        float[] rgb = new float[3 * argb.length];
        for (int p = 0; p < argb.length; p++) {
            rgb[3 * p] = table[argb[p] >> 16 & 0xFF];
            rgb[3 * p + 1] = table[argb[p] >> 8 & 0xFF];
            rgb[3 * p + 2] = table[argb[p] & 0xFF];
        }
        return new HdrImage(picture.width(), picture.height(), rgb);
    }
}
