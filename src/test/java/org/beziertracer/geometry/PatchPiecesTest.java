package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class PatchPiecesTest {

    @Test
    void netLengthCountsThreeCoordinatesPerControlPoint() {
        assertEquals(4 * 4 * 3, new PatchPieces(3, 3, 0, new double[0], new double[0], null, null).netLength());
        assertEquals(3 * 6 * 3, new PatchPieces(2, 5, 0, new double[0], new double[0], null, null).netLength());
        assertEquals(2 * 1 * 3, new PatchPieces(1, 0, 0, new double[0], new double[0], null, null).netLength());
    }
}
