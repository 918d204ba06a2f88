package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.Random;

import org.beziertracer.model.HdrImage;
import org.beziertracer.model.io.HdrReader;
import org.junit.jupiter.api.Test;

/**
 * {@link RadianceHdr}: seeded random films (magnitudes over 2^±20, zeros, long runs of equal
 * pixels, rows narrower than 8 written flat and wider than 128 split into several literal
 * stretches) read back by our {@link HdrReader} within RGBE's precision, 1/256 of each pixel's
 * largest channel; a window of the film holds the same pixels as the whole.
 */
class RadianceHdrTest {
    /** RGBE keeps 8 bits of mantissa under a shared exponent. */
    private static final double RGBE = 1.0 / 256;

    private static Film randomFilm(Random random, int w, int h) {
        Film film = new Film(w, h);
        float[] last = new float[3];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int kind = random.nextInt(6);
                if (kind == 0) {
                    // black: E = 0
                    last = new float[3];
                } else if (kind > 2) {
                    // a new colour; kinds 1 and 2 repeat the last one (runs)
                    last = new float[3];
                    for (int c = 0; c < 3; c++) {
                        last[c] = random.nextInt(8) == 0 ? 0 : (float) Math.scalb(random.nextDouble(), random.nextInt(41) - 20);
                    }
                }
                film.addSample(x, y, last[0], last[1], last[2]);
            }
        }
        return film;
    }

    private static void assertRoundTrip(Film film, PixelWindow window, String what) {
        byte[] bytes = RadianceHdr.encode(film, window);
        String header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + window.height() + " +X " + window.width() + "\n";
        assertEquals(header, new String(bytes, 0, header.length(), StandardCharsets.US_ASCII), what);
        HdrImage back = HdrReader.decode(bytes, what + ".hdr");
        assertEquals(window.width(), back.width(), what);
        assertEquals(window.height(), back.height(), what);
        float[] px = new float[3];
        for (int y = 0; y < window.height(); y++) {
            for (int x = 0; x < window.width(); x++) {
                film.pixel(window.x0() + x, window.y0() + y, px);
                double max = Math.max(px[0], Math.max(px[1], px[2]));
                for (int c = 0; c < 3; c++) {
                    double got = back.get(x, y, c);
                    assertTrue(Math.abs(got - px[c]) <= RGBE * max, what + " pixel " + x + "," + y + " channel " + c
                            + ": wrote " + px[c] + ", read " + got + " (largest channel " + max + ")");
                }
            }
        }
    }

    @Test
    void randomFilmsReadBackWithinRgbePrecisionFlatAndRunLengthEncoded() {
        Random random = new Random(3434);
        for (int[] size : new int[][] {{1, 1}, {3, 5}, {7, 2}, {8, 3}, {37, 11}, {300, 4}}) {
            Film film = randomFilm(random, size[0], size[1]);
            assertRoundTrip(film, film.window(), size[0] + "x" + size[1]);
        }
    }

    @Test
    void runLengthEncodingShrinksAnEvenImage() {
        Film film = new Film(200, 50);
        for (int y = 0; y < 50; y++) {
            for (int x = 0; x < 200; x++) {
                film.addSample(x, y, 0.5, 0.25, 0.125);
            }
        }
        byte[] bytes = RadianceHdr.encode(film);
        assertTrue(bytes.length < 200 * 50, "run-length encoded: " + bytes.length + " bytes, flat would be " + 4 * 200 * 50);
        assertRoundTrip(film, film.window(), "even");
        assertEquals(0.5, HdrReader.decode(bytes, "even.hdr").get(7, 3, 0), 0.5 * RGBE);
    }

    @Test
    void aWindowHoldsTheWholeFilmsPixels() {
        Film film = randomFilm(new Random(34), 40, 30);
        PixelWindow window = new PixelWindow(9, 5, 30, 21);
        HdrImage whole = HdrReader.decode(RadianceHdr.encode(film), "whole.hdr");
        HdrImage piece = HdrReader.decode(RadianceHdr.encode(film, window), "piece.hdr");
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 21; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(whole.get(x + 9, y + 5, c), piece.get(x, y, c), "pixel " + x + "," + y);
                }
            }
        }
        assertRoundTrip(film, window, "window");
    }

    @Test
    void blackNegativeAndNotANumberEncodeAsBlack() {
        byte[] out = new byte[4];
        for (float[] v : new float[][] {{0, 0, 0}, {-1, -2, -3}, {Float.NaN, 1, 1}, {1e-33f, 0, 0}}) {
            RadianceHdr.rgbe(v[0], v[1], v[2], out, 0);
            assertEquals(0, out[3], java.util.Arrays.toString(v));
        }
        RadianceHdr.rgbe(1, 0.5f, 0, out, 0);
        assertEquals(128, out[0] & 0xFF, "1 = 128·2^(129−136)... mantissa 128");
        assertEquals(64, out[1] & 0xFF);
        assertEquals(129, out[3] & 0xFF);
    }
}
