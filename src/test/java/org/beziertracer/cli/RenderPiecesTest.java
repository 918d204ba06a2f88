package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import org.beziertracer.UserMessages;
import org.beziertracer.model.HdrImage;
import org.beziertracer.model.io.HdrReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code render --crop} and {@code --tile} (issue 37): the PNG of a piece holds the whole render's
 * pixels, and so do its linear {@code .pfm} and {@code .hdr} (issue 34).
 */
class RenderPiecesTest {

    @TempDir
    Path dir;

    private static final String[] SCENE = {"--size", "50x36", "--spp", "3", "--sampler", "adaptive", "--threads", "2",
            "--light", "-200,-350,450"};

    @Test
    void aCroppedPngHoldsTheSamePixelsAsTheWholeRender() throws IOException {
        BufferedImage whole = render("whole.png");
        BufferedImage crop = render("crop.png", "--crop", "13,7,41,30");
        assertEquals(28, crop.getWidth());
        assertEquals(23, crop.getHeight());
        assertArrayEquals(whole.getRGB(13, 7, 28, 23, null, 0, 28), crop.getRGB(0, 0, 28, 23, null, 0, 28));
        BufferedImage tile = render("tile.png", "--tile", "5/5");
        assertEquals(50, tile.getWidth());
        assertEquals(8, tile.getHeight(), "the last of 5 bands of 36 rows (7 each) takes the rest: rows 28..35");
        assertArrayEquals(whole.getRGB(0, 28, 50, 8, null, 0, 50), tile.getRGB(0, 0, 50, 8, null, 0, 50));
    }

    @Test
    void aPathTracedCropIsTheSamePixelsAndItsPfmTheSameFloats() throws IOException {
        String[] path = {"--integrator", "path", "--depth", "4"};
        BufferedImage whole = render("pwhole.png", path);
        BufferedImage crop = render("pcrop.png", concat(path, "--crop", "9,5,30,21"));
        assertArrayEquals(whole.getRGB(9, 5, 21, 16, null, 0, 21), crop.getRGB(0, 0, 21, 16, null, 0, 21));
        assertEquals(0, Run.of(args(dir.resolve("whole.pfm"), path)).code());
        Run r = Run.of(args(dir.resolve("crop.pfm"), concat(path, "--crop", "9,5,30,21")));
        assertEquals(0, r.code(), r.err());
        float[] all = pfm(dir.resolve("whole.pfm"), 50, 36), piece = pfm(dir.resolve("crop.pfm"), 21, 16);
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 21; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(all[3 * ((y + 5) * 50 + x + 9) + c], piece[3 * (y * 21 + x) + c], "pixel " + x + "," + y);
                }
            }
        }
    }

    @Test
    void aPathTracedHdrHoldsThePfmsFloatsWithinRgbePrecisionAndItsPiecesTheWholesPixels() throws IOException {
        String[] path = {"--integrator", "path", "--depth", "4"};
        assertEquals(0, Run.of(args(dir.resolve("whole.pfm"), path)).code());
        Run r = Run.of(args(dir.resolve("whole.hdr"), path));
        assertEquals(0, r.code(), r.err());
        float[] linear = pfm(dir.resolve("whole.pfm"), 50, 36);
        HdrImage whole = HdrReader.read(dir.resolve("whole.hdr"));
        assertEquals(50, whole.width());
        assertEquals(36, whole.height());
        for (int p = 0; p < 50 * 36; p++) {
            double max = Math.max(linear[3 * p], Math.max(linear[3 * p + 1], linear[3 * p + 2]));
            for (int c = 0; c < 3; c++) {
                assertEquals(linear[3 * p + c], whole.get(p % 50, p / 50, c), max / 256, "pixel " + p + " channel " + c);
            }
        }
        assertTrue(max(whole) > 0, "the teapot is lit");
        Run crop = Run.of(args(dir.resolve("crop.hdr"), concat(path, "--crop", "9,5,30,21")));
        assertEquals(0, crop.code(), crop.err());
        assertPiece(whole, HdrReader.read(dir.resolve("crop.hdr")), 9, 5, 21, 16);
        Run tile = Run.of(args(dir.resolve("tile.hdr"), concat(path, "--tile", "5/5")));
        assertEquals(0, tile.code(), tile.err());
        assertPiece(whole, HdrReader.read(dir.resolve("tile.hdr")), 0, 28, 50, 8);
        try (var files = Files.list(dir)) {
            assertEquals(List.of(), files.filter(f -> f.getFileName().toString().contains(".tmp")).toList(),
                    "atomic saves leave no temporary file");
        }
    }

    private static double max(HdrImage image) {
        double max = 0;
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                max = Math.max(max, image.get(x, y, 1));
            }
        }
        return max;
    }

    /** The piece holds the whole image's pixels from {@code (x0, y0)}, to the float. */
    private static void assertPiece(HdrImage whole, HdrImage piece, int x0, int y0, int w, int h) {
        assertEquals(w, piece.width());
        assertEquals(h, piece.height());
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(whole.get(x0 + x, y0 + y, c), piece.get(x, y, c), "pixel " + x + "," + y);
                }
            }
        }
    }

    /** The floats of a PFM of the given size, top row first. */
    private static float[] pfm(Path file, int w, int h) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        String header = "PF\n" + w + " " + h + "\n-1.0\n";
        assertEquals(header, new String(bytes, 0, header.length(), java.nio.charset.StandardCharsets.US_ASCII));
        java.nio.ByteBuffer b = java.nio.ByteBuffer.wrap(bytes, header.length(), 12 * w * h).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        float[] out = new float[3 * w * h];
        for (int y = h - 1; y >= 0; y--) {
            for (int k = 0; k < 3 * w; k++) {
                out[3 * y * w + k] = b.getFloat();
            }
        }
        return out;
    }

    private static String[] concat(String[] a, String... b) {
        String[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    @Test
    void badPiecesGetOneLineErrors() {
        assertError("x1 must be greater than x0", "--crop", "20,0,10,10");
        assertError("outside the 50x36 image", "--crop", "0,0,51,10");
        assertError("i must be 1..4", "--tile", "5/4");
        assertError("at most the image height 36", "--tile", "1/37");
        assertError("cannot be used together", "--tile", "1/2", "--crop", "0,0,5,5");
        assertError("--frames needs a job file", "--frames", "1-2");
    }

    private void assertError(String expected, String... piece) {
        Path png = dir.resolve("bad.png");
        Run r = Run.of(args(png, piece));
        assertEquals(1, r.code(), r.err());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.contains(expected), line);
        assertFalse(Files.exists(png), "no image for a bad piece");
    }

    private BufferedImage render(String name, String... piece) throws IOException {
        Path png = dir.resolve(name);
        Run r = Run.of(args(png, piece));
        assertEquals(0, r.code(), r.err());
        return ImageIO.read(png.toFile());
    }

    private static String[] args(Path png, String... piece) {
        String[] head = {"render", "teapot", "-o", png.toString()};
        String[] all = new String[head.length + SCENE.length + piece.length];
        System.arraycopy(head, 0, all, 0, head.length);
        System.arraycopy(SCENE, 0, all, head.length, SCENE.length);
        System.arraycopy(piece, 0, all, head.length + SCENE.length, piece.length);
        return all;
    }
}
