package org.beziertracer.render;

import java.nio.ByteBuffer;

/**
 * The finished pixels of a piece of a frame (issue 37): the 8-bit picture as {@code render} writes it to
 * a PNG (the path tracer's tone map, or the Whitted renderer's clamp-and-encode) and the linear floats of
 * its {@code .pfm}. A tile of a job carried between machines ({@link #toBytes}) and put into its frame by
 * {@link FrameAssembly}.
 *
 * <p>Immutable by contract (the arrays are not copied; do not change them). Layouts, with
 * {@code p = (y − window.y0) * window.width + (x − window.x0)}: {@code argb[p]}, {@code rgb[3 * p + c]}.
 *
 * @param window the pixels of the image this tile holds
 * @param argb   opaque sRGB ARGB, row-major
 * @param rgb    linear RGB floats, row-major
 */
public record TilePixels(PixelWindow window, int[] argb, float[] rgb) {

    /** Start of the bytes of {@link #toBytes}: "BTT1". */
    private static final int MAGIC = 0x42545431;
    /** Bytes before the pixels: the magic and the window. */
    private static final int HEADER = 20;

    public TilePixels {
        int n = window.width() * window.height();
        if (argb.length != n || rgb.length != 3 * n) {
            throw new IllegalArgumentException("a " + window.width() + "x" + window.height() + " tile needs " + n
                    + " pixels and " + 3 * n + " floats, got " + argb.length + " and " + rgb.length);
        }
    }

    /**
     * The pixels of {@code window} of a finished render: tone mapped with {@code exposure} for the path
     * tracer, as {@link RenderResult#argb()} otherwise (the {@code render} command's PNG).
     */
    public static TilePixels of(RenderResult result, PixelWindow window, Integrator integrator, double exposure) {
        int[] argb = integrator == Integrator.PATH ? ToneMap.argb(result.film(), window, exposure)
                : result.film().toArgb(window);
        return new TilePixels(window, argb, result.film().linearRgb(window));
    }

    /** The PNG of these pixels ({@link Png}): for a whole frame, the bytes {@link FrameAssembly#png()} gives. */
    public byte[] png() {
        return Png.encode(window.width(), window.height(), argb);
    }

    /** The linear {@code .pfm} of these pixels ({@link Pfm}): for a whole frame, {@link FrameAssembly#pfm()}'s bytes. */
    public byte[] pfm() {
        return Pfm.encode(window.width(), window.height(), rgb);
    }

    /**
     * This tile as bytes: magic, window (4 ints), pixels, floats (their raw bits); big-endian. Written
     * with bulk copies into one array (16 bytes a pixel), not a value at a time through a stream.
     */
    public byte[] toBytes() {
        byte[] bytes = new byte[HEADER + 16 * argb.length];
        ByteBuffer buf = ByteBuffer.wrap(bytes);
        buf.putInt(MAGIC).putInt(window.x0()).putInt(window.y0()).putInt(window.x1()).putInt(window.y1());
        buf.asIntBuffer().put(argb);
        buf.position(HEADER + 4 * argb.length).asFloatBuffer().put(rgb);
        return bytes;
    }

    /**
     * A tile from {@link #toBytes}.
     *
     * @throws IllegalArgumentException one line naming {@code name} when the bytes are not a whole tile
     */
    public static TilePixels fromBytes(byte[] bytes, String name) {
        ByteBuffer buf = ByteBuffer.wrap(bytes);
        if (bytes.length < HEADER || buf.getInt() != MAGIC) {
            throw new IllegalArgumentException(name + ": not a tile file");
        }
        PixelWindow w = new PixelWindow(buf.getInt(), buf.getInt(), buf.getInt(), buf.getInt());
        long n = (long) w.width() * w.height();
        if (bytes.length != HEADER + 16 * n) {
            throw new IllegalArgumentException(name + ": a " + w.width() + "x" + w.height() + " tile needs "
                    + (HEADER + 16 * n) + " bytes, the file has " + bytes.length);
        }
        int[] argb = new int[(int) n];
        float[] rgb = new float[(int) (3 * n)];
        buf.asIntBuffer().get(argb);
        buf.position(HEADER + 4 * argb.length).asFloatBuffer().get(rgb);
        return new TilePixels(w, argb, rgb);
    }
}
