package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

class PixelWindowTest {

    @Test
    void tilesCoverEveryRowExactlyOnceAndTheLastTakesTheRest() {
        Random random = new Random(37);
        for (int trial = 0; trial < 500; trial++) {
            int width = 1 + random.nextInt(50), height = 1 + random.nextInt(300);
            int n = 1 + random.nextInt(height);
            int[] covered = new int[height];
            for (int i = 1; i <= n; i++) {
                PixelWindow t = PixelWindow.tile(i, n, width, height);
                assertEquals(0, t.x0());
                assertEquals(width, t.x1());
                if (i < n) {
                    assertEquals(height / n, t.height(), "band " + i + "/" + n + " of " + height + " rows");
                }
                for (int y = t.y0(); y < t.y1(); y++) {
                    covered[y]++;
                }
            }
            for (int y = 0; y < height; y++) {
                assertEquals(1, covered[y], "row " + y + " of " + height + " in " + n + " tiles");
            }
        }
    }

    @Test
    void aCropIsReadAsHalfOpenPixelRanges() {
        PixelWindow c = PixelWindow.parseCrop(" 3, 4,10,20 ", 10, 20);
        assertEquals(new PixelWindow(3, 4, 10, 20), c);
        assertEquals(7, c.width());
        assertEquals(16, c.height());
        assertTrue(PixelWindow.parseCrop("0,0,10,20", 10, 20).isWhole(10, 20));
        assertEquals(new PixelWindow(0, 10, 8, 20), PixelWindow.parseTile("2/2", 8, 20));
    }

    @Test
    void badCropsAndTilesGetOneLineErrorsNamingTheProblem() {
        String m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseCrop("5,0,5,10", 20, 10));
        assertTrue(m.contains("x1 must be greater than x0"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseCrop("0,0,21,10", 20, 10));
        assertTrue(m.contains("outside the 20x10 image"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseCrop("-1,0,4,4", 20, 10));
        assertTrue(m.contains("0 or more"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseCrop("1,2,3", 20, 10));
        assertTrue(m.contains("x0,y0,x1,y1"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseCrop("a,2,3,4", 20, 10));
        assertTrue(m.contains("whole numbers"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseTile("3/2", 20, 10));
        assertTrue(m.contains("i must be 1..2"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseTile("0/2", 20, 10));
        assertTrue(m.contains("i must be 1..2"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseTile("1/11", 20, 10));
        assertTrue(m.contains("at most the image height 10"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseTile("1/0", 20, 10));
        assertTrue(m.contains("N must be 1 or more"), m);
        m = UserMessages.of(IllegalArgumentException.class, () -> PixelWindow.parseTile("half", 20, 10));
        assertTrue(m.contains("i/N"), m);
    }
}
