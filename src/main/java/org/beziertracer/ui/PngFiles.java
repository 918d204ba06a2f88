package org.beziertracer.ui;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.Iterator;

import javax.imageio.ImageIO;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

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
        return out -> encode(image, out);
    }

    /**
     * Encodes {@code image} as PNG into {@code out} (not closed), buffering in memory: ImageIO's
     * default file cache ({@code imageioNNNN.tmp} in {@code java.io.tmpdir}) is left behind by a
     * killed process. The command line's copy is {@code cli.PngWriter}.
     */
    static void encode(BufferedImage image, OutputStream out) throws IOException {
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
        if (!writers.hasNext()) {
            throw new IOException("no PNG writer available");
        }
        ImageWriter writer = writers.next();
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.write(image);
        } finally {
            writer.dispose();
        }
    }
}
