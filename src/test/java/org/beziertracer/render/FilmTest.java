package org.beziertracer.render;

import static org.beziertracer.Tolerances.FLOAT;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * {@link Film}: a pixel shows the mean of its samples, remembers its first sample, and a pixel
 * without samples shows its block's anchor; nothing leaks into other pixels.
 */
class FilmTest {

    @Test
    void aPixelShowsTheMeanOfItsSamplesAndKeepsTheFirst() {
        Random rnd = new Random(8);
        Film film = new Film(7, 5);
        double[][][] sums = new double[5][7][3];
        int[][] counts = new int[5][7];
        double[][][] firsts = new double[5][7][3];
        for (int k = 0; k < 400; k++) {
            int x = rnd.nextInt(7), y = rnd.nextInt(5);
            double r = rnd.nextDouble(), g = 2 * rnd.nextDouble(), b = rnd.nextDouble() * 0.1;
            if (counts[y][x] == 0) {
                firsts[y][x] = new double[] {r, g, b};
            }
            sums[y][x][0] += r; sums[y][x][1] += g; sums[y][x][2] += b;
            counts[y][x]++;
            film.addSample(x, y, r, g, b);
        }
        float[] px = new float[3];
        float[] linear = film.linearRgb();
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 7; x++) {
                String where = "pixel " + x + "," + y;
                assertEquals(counts[y][x], film.sampleCount(x, y), where);
                film.pixel(x, y, px);
                for (int c = 0; c < 3; c++) {
                    double mean = counts[y][x] == 0 ? 0 : sums[y][x][c] / counts[y][x];
                    assertEquals(mean, px[c], FLOAT * (1 + mean), where + " channel " + c);
                    assertEquals(px[c], linear[3 * (y * 7 + x) + c], 0, where + " linearRgb");
                    assertEquals((float) firsts[y][x][c], film.first[3 * (y * 7 + x) + c], 0, where + " first sample");
                }
            }
        }
    }

    @Test
    void toArgbEncodesEveryPixelInSrgb() {
        Film film = new Film(3, 2);
        film.addSample(0, 0, 1, 0, 0);
        film.addSample(1, 0, 0.5, 0.5, 0.5);
        film.addSample(1, 0, 0, 0, 0);
        film.addSample(2, 1, 7, -1, Double.NaN);
        int[] argb = film.toArgb();
        assertEquals(0xFFFF0000, argb[0]);
        assertEquals(Srgb.argb(0.25f, 0.25f, 0.25f), argb[1], "mean of two samples");
        assertEquals(0xFF000000, argb[2], "no sample: black");
        assertEquals(0xFFFF0000, argb[5], "clamped, negative and NaN channels");
    }

    @Test
    void aPixelWithoutSamplesShowsItsBlocksAnchor() {
        Film film = new Film(8, 8);
        for (int y = 0; y < 8; y += 4) {
            for (int x = 0; x < 8; x += 4) {
                film.addSample(x, y, x / 8.0, y / 8.0, 1);
            }
        }
        film.addSample(5, 6, 0, 0, 0); // a pixel of its own inside the (4,4) block
        int[] argb = new int[6 * 5];
        film.writeArgb(2, 3, 6, 5, 4, argb, 6);
        for (int j = 0; j < 5; j++) {
            for (int i = 0; i < 6; i++) {
                int x = 2 + i, y = 3 + j;
                int expected = x == 5 && y == 6 ? Srgb.argb(0, 0, 0)
                        : Srgb.argb((x - x % 4) / 8f, (y - y % 4) / 8f, 1);
                assertEquals(expected, argb[j * 6 + i], "pixel " + x + "," + y);
            }
        }
        int[] one = new int[6 * 5];
        film.writeArgb(2, 3, 6, 5, 1, one, 6);
        assertEquals(0xFF000000, one[0], "block 1: a pixel without samples is black");
        // blocks are the pass plan's powers of two; anything else is a caller's mistake
        for (int bad : new int[] {0, 3, 6, -4}) {
            assertThrows(IllegalArgumentException.class, () -> film.writeArgb(2, 3, 6, 5, bad, one, 6), "block " + bad);
        }
    }

    @Test
    void everyPixelOfARandomRectangleShowsItsOwnMeanOrItsAnchors() {
        java.util.Random rnd = new java.util.Random(3);
        for (int round = 0; round < 200; round++) {
            int width = 1 + rnd.nextInt(40), height = 1 + rnd.nextInt(30);
            Film film = new Film(width, height);
            for (int k = rnd.nextInt(width * height + 1); k > 0; k--) {
                film.addSample(rnd.nextInt(width), rnd.nextInt(height), rnd.nextDouble(), rnd.nextDouble(),
                        rnd.nextDouble() * 1.2);
            }
            int block = 1 << rnd.nextInt(4);
            int x0 = rnd.nextInt(width), y0 = rnd.nextInt(height);
            int w = 1 + rnd.nextInt(width - x0), h = 1 + rnd.nextInt(height - y0);
            int[] argb = new int[w * h];
            film.writeArgb(x0, y0, w, h, block, argb, w);
            float[] linear = film.linearRgb();
            int[] whole = film.toArgb();
            for (int j = 0; j < h; j++) {
                for (int i = 0; i < w; i++) {
                    int x = x0 + i, y = y0 + j, p = y * width + x;
                    if (film.count[p] == 0) {
                        p = (y - y % block) * width + (x - x % block);
                    }
                    int expected = film.count[p] == 0 ? 0xFF000000
                            : Srgb.argb(linear[3 * p], linear[3 * p + 1], linear[3 * p + 2]);
                    assertEquals(expected, argb[j * w + i], "round " + round + ", pixel " + x + "," + y);
                    if (block == 1) {
                        assertEquals(whole[y * width + x], argb[j * w + i]);
                    }
                }
            }
        }
    }

    @Test
    void writeArgbFillsOnlyItsRectangleWithTheGivenStride() {
        Film film = new Film(4, 4);
        for (int y = 0; y < 4; y++) {
            for (int x = 0; x < 4; x++) {
                film.addSample(x, y, 1, 1, 1);
            }
        }
        int[] argb = new int[3 * 10];
        film.writeArgb(1, 1, 2, 3, 1, argb, 10);
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 10; i++) {
                assertEquals(i < 2 ? 0xFFFFFFFF : 0, argb[j * 10 + i], "row " + j + " column " + i);
            }
        }
    }

    @Test
    void absurdSizesAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> new Film(0, 5));
        assertThrows(IllegalArgumentException.class, () -> new Film(5, -1));
        assertThrows(IllegalArgumentException.class, () -> new Film(1 << 14, 1 << 13));
        assertEquals(28L * 800 * 600, Film.bytesFor(800, 600));
        assertArrayEquals(new float[3 * 2], new Film(2, 1).linearRgb(), 0);
    }
}
