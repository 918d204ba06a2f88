package org.beziertracer.model.io;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.model.HdrImage;

/**
 * Reads a Radiance RGBE picture ({@code .hdr}, G. Ward, "Real pixels", Graphics Gems II, 1991;
 * the format of the Radiance {@code ra_*} tools): a text header starting {@code #?RADIANCE} or
 * {@code #?RGBE}, {@code FORMAT=32-bit_rle_rgbe}, a blank line, the resolution {@code -Y H +X W},
 * then scanlines, flat or adaptive run-length encoded per channel. A pixel {@code (R, G, B, E)} is
 * {@code ((R + ½)·2^(E−136), …)}, 0 when E = 0 (Radiance's {@code colr_color}). Other orientations,
 * the XYZE format and the old-style run-length code are refused. Errors are one line naming the
 * file. Stateless.
 *
 * <p>Chosen over a library: TwelveMonkeys' HDR plugin would pull ImageIO (AWT) into
 * {@code model.io}, and the format is a page of code.
 */
public final class HdrReader {
    /** Most pixels (64 Mpixels), so a huge header is refused before anything is allocated. */
    public static final long MAX_PIXELS = 1L << 26;

    private HdrReader() {}

    public static HdrImage read(Path file) {
        byte[] bytes;
        try {
            if (!Files.isRegularFile(file)) {
                throw new ModelFormatException(file.toString(), "no such image file");
            }
            bytes = Files.readAllBytes(file);
        } catch (IOException e) {
            throw new ModelFormatException(file.toString(), "cannot read: " + e.getMessage());
        }
        return decode(bytes, file.toString());
    }

    /** Decodes the bytes of a {@code .hdr} file called {@code name} (for messages). */
    public static HdrImage decode(byte[] b, String name) {
        int[] pos = {0};
        String first = line(b, pos, name);
        if (!first.startsWith("#?")) {
            throw new ModelFormatException(name, "not a Radiance HDR picture (no #? first line)");
        }
        while (true) {
            String l = line(b, pos, name);
            if (l.isEmpty()) {
                break;
            }
            if (l.startsWith("FORMAT=") && !l.equals("FORMAT=32-bit_rle_rgbe")) {
                throw new ModelFormatException(name, "unsupported " + Echo.quote(l) + " (only 32-bit_rle_rgbe)");
            }
        }
        String res = line(b, pos, name).trim();
        String[] parts = res.split("\\s+");
        if (parts.length != 4 || !parts[0].equals("-Y") || !parts[2].equals("+X")) {
            throw new ModelFormatException(name, "unsupported resolution line " + Echo.quote(res) + " (only -Y H +X W)");
        }
        int w, h;
        try {
            h = Integer.parseInt(parts[1]);
            w = Integer.parseInt(parts[3]);
        } catch (NumberFormatException e) {
            throw new ModelFormatException(name, "bad resolution line " + Echo.quote(res));
        }
        if (w < 1 || h < 1 || (long) w * h > MAX_PIXELS) {
            throw new ModelFormatException(name, "image size " + w + "x" + h + " is not 1.." + MAX_PIXELS + " pixels");
        }
        float[] rgb = new float[3 * w * h];
        byte[] scan = new byte[4 * w];
        for (int y = 0; y < h; y++) {
            scanline(b, pos, scan, w, name, y);
            for (int x = 0; x < w; x++) {
                int e = scan[4 * x + 3] & 0xFF;
                int o = 3 * (y * w + x);
                if (e != 0) {
                    float f = (float) Math.scalb(1.0, e - 136);
                    rgb[o] = ((scan[4 * x] & 0xFF) + 0.5f) * f;
                    rgb[o + 1] = ((scan[4 * x + 1] & 0xFF) + 0.5f) * f;
                    rgb[o + 2] = ((scan[4 * x + 2] & 0xFF) + 0.5f) * f;
                }
            }
        }
        try {
            return new HdrImage(w, h, rgb);
        } catch (IllegalArgumentException e) {
            throw new ModelFormatException(name, e.getMessage());
        }
    }

    /** One scanline into {@code scan} as R, G, B, E per pixel. */
    private static void scanline(byte[] b, int[] pos, byte[] scan, int w, String name, int y) {
        int p = pos[0];
        need(b, p, 4, name, y);
        boolean rle = w >= 8 && w < 0x8000 && b[p] == 2 && b[p + 1] == 2 && ((b[p + 2] & 0xFF) << 8 | b[p + 3] & 0xFF) == w;
        if (!rle) {
            need(b, p, 4 * w, name, y);
            for (int i = 0; i < w; i++) {
                if (b[p + 4 * i] == 1 && b[p + 4 * i + 1] == 1 && b[p + 4 * i + 2] == 1) {
                    throw new ModelFormatException(name, "scanline " + y + " uses the old run-length code, not supported");
                }
            }
            System.arraycopy(b, p, scan, 0, 4 * w);
            pos[0] = p + 4 * w;
            return;
        }
        p += 4;
        for (int c = 0; c < 4; c++) {
            int x = 0;
            while (x < w) {
                need(b, p, 1, name, y);
                int count = b[p++] & 0xFF;
                if (count > 128) {
                    count -= 128;
                    need(b, p, 1, name, y);
                    if (x + count > w) {
                        throw new ModelFormatException(name, "scanline " + y + ": a run passes the end of the line");
                    }
                    byte v = b[p++];
                    for (int k = 0; k < count; k++) {
                        scan[4 * x++ + c] = v;
                    }
                } else {
                    if (count == 0 || x + count > w) {
                        throw new ModelFormatException(name, "scanline " + y + ": a bad run length " + count);
                    }
                    need(b, p, count, name, y);
                    for (int k = 0; k < count; k++) {
                        scan[4 * x++ + c] = b[p++];
                    }
                }
            }
        }
        pos[0] = p;
    }

    private static void need(byte[] b, int p, int n, String name, int y) {
        if (p + n > b.length) {
            throw new ModelFormatException(name, "the file ends inside scanline " + y);
        }
    }

    /** One header line (without its newline); an error at the end of the file. */
    private static String line(byte[] b, int[] pos, String name) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int p = pos[0];
        while (true) {
            if (p >= b.length) {
                throw new ModelFormatException(name, "the file ends inside its header");
            }
            if (b[p] == '\n') {
                break;
            }
            if (out.size() > 4096) {
                throw new ModelFormatException(name, "a header line longer than 4096 bytes");
            }
            out.write(b[p++]);
        }
        pos[0] = p + 1;
        return out.toString(StandardCharsets.ISO_8859_1);
    }
}
