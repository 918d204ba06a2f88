package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;

import org.beziertracer.UserMessages;
import org.beziertracer.model.HdrImage;
import org.junit.jupiter.api.Test;

/** {@link HdrReader}: flat and run-length scanlines decode to the RGBE values; bad files are one-line errors. */
class HdrReaderTest {

    private static byte[] file(String resolution, byte[] pixels) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(("#?RADIANCE\n# made by a test\nFORMAT=32-bit_rle_rgbe\n\n" + resolution + "\n")
                .getBytes(StandardCharsets.US_ASCII));
        out.writeBytes(pixels);
        return out.toByteArray();
    }

    /** Radiance's colr_color: (m + ½) · 2^(e − 136). */
    private static float value(int m, int e) { return (float) ((m + 0.5) * Math.pow(2, e - 136)); }

    @Test
    void flatScanlinesDecodeToRadiancesValues() {
        byte[] px = {(byte) 128, 64, 0, (byte) 129, 0, 0, 0, 0, 10, 20, 30, (byte) 140, 1, 2, 3, (byte) 128, 5, 5, 5, 100,
            (byte) 255, 0, 0, (byte) 130};
        HdrImage img = HdrReader.decode(file("-Y 2 +X 3", px), "sky.hdr");
        assertEquals(3, img.width());
        assertEquals(2, img.height());
        assertEquals(value(128, 129), img.get(0, 0, 0));
        assertEquals(value(64, 129), img.get(0, 0, 1));
        assertEquals(0, img.get(1, 0, 0), "exponent 0 is black");
        assertEquals(value(30, 140), img.get(2, 0, 2));
        assertEquals(value(255, 130), img.get(2, 1, 0));
        assertEquals(value(5, 100), img.get(1, 1, 1));
    }

    @Test
    void runLengthScanlinesDecodeLikeFlatOnes() {
        int w = 10;
        // channel runs: R = 9 × 200 then literal 7; G literal 10 values; B run of 10 × 3; E run of 10 × 130
        ByteArrayOutputStream rle = new ByteArrayOutputStream();
        rle.writeBytes(new byte[] {2, 2, 0, (byte) w});
        rle.writeBytes(new byte[] {(byte) (128 + 9), (byte) 200, 1, 7});
        rle.write(10);
        for (int i = 0; i < 10; i++) {
            rle.write(i * 20);
        }
        rle.writeBytes(new byte[] {(byte) (128 + 10), 3});
        rle.writeBytes(new byte[] {(byte) (128 + 10), (byte) 130});
        HdrImage img = HdrReader.decode(file("-Y 1 +X " + w, rle.toByteArray()), "run.hdr");
        for (int x = 0; x < w; x++) {
            assertEquals(value(x < 9 ? 200 : 7, 130), img.get(x, 0, 0), "R at " + x);
            assertEquals(value(x * 20, 130), img.get(x, 0, 1), "G at " + x);
            assertEquals(value(3, 130), img.get(x, 0, 2), "B at " + x);
        }
    }

    @Test
    void badFilesAreOneLineErrorsNamingTheFile() {
        assertError("sky.hdr: not a Radiance HDR picture", "P6\n1 1\n255\n".getBytes(StandardCharsets.US_ASCII));
        assertError("unsupported \"FORMAT=32-bit_rle_xyze\"",
                "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\0\0\0\0".getBytes(StandardCharsets.US_ASCII));
        assertError("unsupported resolution line \"+Y 1 +X 1\"", file("+Y 1 +X 1", new byte[4]));
        assertError("the file ends inside scanline 1", file("-Y 2 +X 2", new byte[8]));
        assertError("image size 100000x100000 is not 1..", file("-Y 100000 +X 100000", new byte[0]));
        assertError("the file ends inside its header", "#?RADIANCE\nFORMAT=32".getBytes(StandardCharsets.US_ASCII));
    }

    private static void assertError(String expected, byte[] bytes) {
        String message = UserMessages.of(ModelFormatException.class, () -> HdrReader.decode(bytes, "sky.hdr"));
        assertTrue(message.startsWith("sky.hdr:") && message.contains(expected), "expected \"" + expected + "\" in: " + message);
    }
}
