package org.beziertracer.render;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;

/**
 * The Radiance RGBE encoding of a film's linear RGB ({@code .hdr}; G. Ward, "Real pixels",
 * Graphics Gems II, 1991): the header {@code #?RADIANCE}, {@code FORMAT=32-bit_rle_rgbe}, a blank
 * line, {@code -Y H +X W}, then the rows from the top, each pixel a shared exponent E and three
 * 8-bit mantissas: with {@code v = max(r, g, b) = m·2^e}, {@code ½ ≤ m < 1}, the bytes are
 * {@code floor(c·2^(8−e))} and {@code e + 128} (all 0 below 1e-32 or for NaN) — Radiance's
 * {@code setcolr}, read back as {@code (C + ½)·2^(E−136)}, within 1/256 of the largest channel.
 * Rows 8..32767 pixels wide are run-length encoded per channel (runs of ≥ 4 equal bytes as
 * {@code 128 + n, byte}, the rest as {@code n, n bytes}: Radiance's {@code fwritecolrs}); others flat.
 * Stateless.
 */
public final class RadianceHdr {
    /** Shortest run worth a run code. */
    private static final int MIN_RUN = 4;

    private RadianceHdr() {}

    /** The bytes of a {@code .hdr} file holding the averaged linear image of {@code film}. */
    public static byte[] encode(Film film) {
        return encode(film, film.window());
    }

    /** The pixels of {@code window} (image coordinates, inside the film's) as a {@code .hdr} file. */
    public static byte[] encode(Film film, PixelWindow window) {
        int w = window.width(), h = window.height();
        ByteArrayOutputStream out = new ByteArrayOutputStream(64 + 4 * w * h);
        out.writeBytes(("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + h + " +X " + w + "\n")
                .getBytes(StandardCharsets.US_ASCII));
        boolean rle = w >= 8 && w < 0x8000;
        byte[] scan = new byte[4 * w], channel = new byte[w];
        float[] px = new float[3];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                film.pixel(window.x0() + x, window.y0() + y, px);
                rgbe(px[0], px[1], px[2], scan, 4 * x);
            }
            if (!rle) {
                out.write(scan, 0, scan.length);
                continue;
            }
            out.write(2);
            out.write(2);
            out.write(w >> 8);
            out.write(w & 0xFF);
            for (int c = 0; c < 4; c++) {
                for (int x = 0; x < w; x++) {
                    channel[x] = scan[4 * x + c];
                }
                runs(channel, out);
            }
        }
        return out.toByteArray();
    }

    /** One pixel's four bytes into {@code out[at..at+3]}. */
    static void rgbe(float r, float g, float b, byte[] out, int at) {
        double v = Math.max(r, Math.max(g, b));
        if (!(v >= 1e-32) || !Double.isFinite(v)) {
            out[at] = 0; out[at + 1] = 0; out[at + 2] = 0; out[at + 3] = 0;
            return;
        }
        int e = Math.getExponent(v) + 1; // v = m·2^e with ½ ≤ m < 1
        out[at] = (byte) (int) Math.scalb(Math.max(0, (double) r), 8 - e);
        out[at + 1] = (byte) (int) Math.scalb(Math.max(0, (double) g), 8 - e);
        out[at + 2] = (byte) (int) Math.scalb(Math.max(0, (double) b), 8 - e);
        out[at + 3] = (byte) (e + 128);
    }

    /** One channel of a row, run-length encoded. */
    private static void runs(byte[] data, ByteArrayOutputStream out) {
        int n = data.length, cur = 0;
        while (cur < n) {
            // Find the next run of at least MIN_RUN equal bytes (or the end)
            int run = cur, count = 0, before = 0;
            while (count < MIN_RUN && run < n) {
                run += count;
                before = count;
                count = 1;
                while (run + count < n && count < 127 && data[run] == data[run + count]) {
                    count++;
                }
            }
            // A short run right before it is worth its own run code
            if (before > 1 && before == run - cur) {
                out.write(128 + before);
                out.write(data[cur]);
                cur = run;
            }
            // The bytes up to the run, literally
            while (cur < run) {
                int literal = Math.min(128, run - cur);
                out.write(literal);
                out.write(data, cur, literal);
                cur += literal;
            }
            if (count >= MIN_RUN) {
                out.write(128 + count);
                out.write(data[run]);
                cur += count;
            }
        }
    }
}
