package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

/** Output names of a job's frames (issue 37): numbered PNGs and the {@code .pfm} beside each. */
class FramePatternTest {

    @Test
    void eachRunOfHashesIsTheFrameNumberPaddedToItsLength() {
        assertEquals(Path.of("out", "teapot-0007.png"), FramePattern.fileOf(Path.of("out", "teapot-####.png"), 7));
        assertEquals(Path.of("a12-012.png"), FramePattern.fileOf(Path.of("a#-###.png"), 12));
        assertEquals(Path.of("f-12345.png"), FramePattern.fileOf(Path.of("f-##.png"), 12345), "never cut");
        assertEquals(Path.of("still.png"), FramePattern.fileOf(Path.of("still.png"), 3));
        assertTrue(FramePattern.numbered(Path.of("x", "f-#.png")));
        assertFalse(FramePattern.numbered(Path.of("x#", "f.png")), "only the file name counts");
    }

    @Test
    void theLinearImageSitsBesideThePngWithPfmInPlaceOfPng() {
        assertEquals("teapot-0007.pfm", FramePattern.pfmName("teapot-0007.png"));
        assertEquals("SHOT.pfm", FramePattern.pfmName("SHOT.PNG"));
        assertEquals("frame.png.x.pfm", FramePattern.pfmName("frame.png.x"));
        assertEquals(Path.of("out", "f-01.pfm"), FramePattern.pfmOf(Path.of("out", "f-01.png")));
    }

    @Test
    void rangesAreAToBOrOneFrame() {
        assertArrayEquals(new int[] {2, 5}, FramePattern.range(" 2 - 5 ", "--frames"));
        assertArrayEquals(new int[] {4, 4}, FramePattern.range("4", "--frames"));
        assertEquals("--frames 5-2: the last frame is before the first",
                assertThrows(IllegalArgumentException.class, () -> FramePattern.range("5-2", "--frames")).getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> FramePattern.range("1..3", "job.json: frames"))
                .getMessage().startsWith("job.json: frames must be A-B or A"));
    }
}
