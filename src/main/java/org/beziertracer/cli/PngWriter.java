package org.beziertracer.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;
import java.util.Iterator;

import javax.imageio.ImageIO;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

import org.beziertracer.model.io.AtomicFiles;

/**
 * Writes sRGB ARGB pixels as a PNG, atomically: into a temporary file next to the target, then
 * moved over it (ImageIO lives here, in {@code cli}, so {@code render} stays free of AWT). The
 * encoder buffers in memory: {@code ImageIO.write} to a stream would cache in a file
 * {@code imageioNNNN.tmp} in {@code java.io.tmpdir}, which a killed process leaves behind and a
 * missing temporary folder makes fail. The desktop app's copy is {@code ui.PngFiles} (the two
 * layers may not share AWT code).
 */
final class PngWriter {
    private PngWriter() {}

    static void write(Path target, int width, int height, int[] argb) throws IOException {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, width, height, argb, 0, width);
        AtomicFiles.writeBytes(target, out -> encode(img, out));
    }

    /** Encodes {@code image} as PNG into {@code out} (not closed), with no cache file. */
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
