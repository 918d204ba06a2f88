package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code render --crop} and {@code --tile} (issue 37): the PNG of a piece holds the whole render's pixels. */
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
