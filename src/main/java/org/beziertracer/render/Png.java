package org.beziertracer.render;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

/**
 * A PNG encoder without AWT, for the layers below {@code cli} and {@code ui} and for Spark executors
 * (which may have no AWT at all): 8-bit RGB (colour type 2), no interlace, every row with filter type 0,
 * one zlib stream in one {@code IDAT} chunk. Follows the W3C "Portable Network Graphics (PNG)
 * Specification (Second Edition)", 2003 (ISO/IEC 15948), sections 5 (datastream), 11.2.2 (IHDR) and
 * 10 (zlib compression). The pixels read back are exactly the ARGB given (alpha dropped); the file's
 * bytes differ from ImageIO's. Stateless.
 */
public final class Png {
    private Png() {}

    private static final byte[] SIGNATURE = {(byte) 137, 80, 78, 71, 13, 10, 26, 10};

    /** The bytes of a PNG holding {@code argb} (row-major, {@code w × h}, alpha ignored). */
    public static byte[] encode(int w, int h, int[] argb) {
        if (w < 1 || h < 1 || argb.length != w * h) {
            throw new IllegalArgumentException("expected " + w + "x" + h + " pixels, got " + argb.length);
        }
        byte[] raw = new byte[h * (1 + 3 * w)];
        int o = 0;
        for (int y = 0; y < h; y++) {
            raw[o++] = 0; // filter type None
            for (int x = 0; x < w; x++) {
                int p = argb[y * w + x];
                raw[o++] = (byte) (p >>> 16);
                raw[o++] = (byte) (p >>> 8);
                raw[o++] = (byte) p;
            }
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream(raw.length / 2 + 64);
        out.writeBytes(SIGNATURE);
        chunk(out, "IHDR", ByteBuffer.allocate(13).putInt(w).putInt(h)
                .put((byte) 8).put((byte) 2).put((byte) 0).put((byte) 0).put((byte) 0).array());
        chunk(out, "IDAT", deflate(raw));
        chunk(out, "IEND", new byte[0]);
        return out.toByteArray();
    }

    private static byte[] deflate(byte[] raw) {
        Deflater d = new Deflater(Deflater.DEFAULT_COMPRESSION);
        try {
            d.setInput(raw);
            d.finish();
            ByteArrayOutputStream z = new ByteArrayOutputStream(raw.length / 2 + 64);
            byte[] buf = new byte[1 << 16];
            while (!d.finished()) {
                z.write(buf, 0, d.deflate(buf));
            }
            return z.toByteArray();
        } finally {
            d.end();
        }
    }

    /** Length, type, data and the CRC-32 of type and data (section 5.3). */
    private static void chunk(ByteArrayOutputStream out, String type, byte[] data) {
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data);
        out.writeBytes(ByteBuffer.allocate(4).putInt(data.length).array());
        out.writeBytes(t);
        out.writeBytes(data);
        out.writeBytes(ByteBuffer.allocate(4).putInt((int) crc.getValue()).array());
    }
}
