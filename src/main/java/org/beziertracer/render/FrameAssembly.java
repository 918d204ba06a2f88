package org.beziertracer.render;

import java.io.IOException;
import java.nio.file.Path;

import org.beziertracer.model.io.AtomicFiles;

/**
 * Puts the tiles of one frame ({@link TilePixels}, rendered anywhere) into the whole {@code width × height}
 * picture and its linear image (issue 37). Every pixel must come from exactly one tile; since a tile's
 * pixels are byte-identical to the same pixels of a whole render, so is the assembled frame.
 *
 * <p>Not thread-safe: one assembler per frame, filled by one thread.
 */
public final class FrameAssembly {
    private final int width, height;
    private final int[] argb;
    private final float[] rgb;
    private final boolean[] filled;
    private long filledCount;

    public FrameAssembly(int width, int height) {
        if (width < 1 || height < 1 || (long) width * height > (1L << 26)) {
            throw new IllegalArgumentException("a frame of " + width + "x" + height + " pixels is not allowed");
        }
        this.width = width;
        this.height = height;
        argb = new int[width * height];
        rgb = new float[3 * width * height];
        filled = new boolean[width * height];
    }

    /**
     * Copies {@code tile}'s pixels into the frame.
     *
     * @throws IllegalArgumentException when the tile lies outside the frame or covers a pixel already filled
     */
    public void add(TilePixels tile) {
        PixelWindow w = tile.window();
        if (!w.fits(width, height)) {
            throw new IllegalArgumentException("tile " + w + " is outside the " + width + "x" + height + " frame");
        }
        for (int y = w.y0(); y < w.y1(); y++) {
            for (int x = w.x0(); x < w.x1(); x++) {
                if (filled[y * width + x]) {
                    throw new IllegalArgumentException("tile " + w + " covers pixel " + x + "," + y + " twice");
                }
            }
        }
        int tw = w.width();
        for (int y = w.y0(); y < w.y1(); y++) {
            int from = (y - w.y0()) * tw, to = y * width + w.x0();
            System.arraycopy(tile.argb(), from, argb, to, tw);
            System.arraycopy(tile.rgb(), 3 * from, rgb, 3 * to, 3 * tw);
            java.util.Arrays.fill(filled, to, to + tw, true);
        }
        filledCount += (long) tw * w.height();
    }

    /** True when every pixel came from a tile. */
    public boolean isComplete() { return filledCount == (long) width * height; }

    /** The frame's PNG bytes ({@link Png}). */
    public byte[] png() {
        requireComplete();
        return Png.encode(width, height, argb);
    }

    /** The frame's linear {@code .pfm} bytes ({@link Pfm}). */
    public byte[] pfm() {
        requireComplete();
        return Pfm.encode(width, height, rgb);
    }

    /** Writes {@link #png()} to {@code png} and {@link #pfm()} to {@code pfm} (null: none), each atomically. */
    public void write(Path png, Path pfm) throws IOException {
        byte[] p = png(), f = pfm == null ? null : pfm();
        AtomicFiles.writeBytes(png, out -> out.write(p));
        if (f != null) {
            AtomicFiles.writeBytes(pfm, out -> out.write(f));
        }
    }

    private void requireComplete() {
        if (!isComplete()) {
            throw new IllegalStateException("the frame has " + filledCount + " of " + (long) width * height
                    + " pixels; a tile is missing");
        }
    }
}
