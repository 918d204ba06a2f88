package org.beziertracer.render;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * The Portable Float Map encoding of a film's linear RGB (the format of P. Debevec's HDRShop and
 * Netpbm's {@code pfm}): the header {@code "PF\n<width> <height>\n-1.0\n"} (a negative scale means
 * little-endian), then 32-bit floats, three per pixel, rows from the bottom of the image up.
 * Stateless.
 */
public final class Pfm {
    private Pfm() {}

    /** The bytes of a PFM file holding the averaged linear image of {@code film}. */
    public static byte[] encode(Film film) {
        return encode(film, film.window());
    }

    /** The pixels of {@code window} (image coordinates, inside the film's) as a PFM file. */
    public static byte[] encode(Film film, PixelWindow window) {
        return encode(window.width(), window.height(), film.linearRgb(window));
    }

    /**
     * A {@code w × h} linear image as a PFM file; {@code rgb[3 * (y * w + x) + c]}, row 0 at the top (the
     * file stores it last).
     */
    public static byte[] encode(int w, int h, float[] rgb) {
        if (rgb.length != 3 * w * h) {
            throw new IllegalArgumentException("expected " + 3 * w * h + " floats for " + w + "x" + h + ", got " + rgb.length);
        }
        byte[] header = ("PF\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII);
        ByteBuffer buf = ByteBuffer.allocate(header.length + 12 * w * h).order(ByteOrder.LITTLE_ENDIAN);
        buf.put(header);
        for (int y = h - 1; y >= 0; y--) {
            for (int k = 3 * y * w, end = k + 3 * w; k < end; k++) {
                buf.putFloat(rgb[k]);
            }
        }
        return buf.array();
    }
}
