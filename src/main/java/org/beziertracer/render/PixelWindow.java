package org.beziertracer.render;

/**
 * A rectangle of an image's pixels, {@code x0 ≤ x < x1, y0 ≤ y < y1}, counted from the top left:
 * the piece of a render that {@code render --crop} or {@code --tile} asks for. A render of a window
 * uses the whole image's camera and the same per-pixel samples, so its pixels are byte-identical to
 * the same pixels of the whole render (issue 37).
 *
 * <p>Immutable. The factories check the window against the image and fail with one line naming the
 * problem.
 */
public record PixelWindow(int x0, int y0, int x1, int y1) {

    public PixelWindow {
        if (x0 < 0 || y0 < 0 || x1 <= x0 || y1 <= y0) {
            throw new IllegalArgumentException("a pixel window needs 0 <= x0 < x1 and 0 <= y0 < y1, got "
                    + x0 + "," + y0 + "," + x1 + "," + y1);
        }
    }

    /** Every pixel of a {@code width × height} image. */
    public static PixelWindow whole(int width, int height) {
        return new PixelWindow(0, 0, width, height);
    }

    /**
     * {@code x0,y0,x1,y1} as typed after {@code --crop}, checked against a {@code width × height} image.
     *
     * @throws IllegalArgumentException one line naming the problem
     */
    public static PixelWindow parseCrop(String text, int width, int height) {
        String[] parts = text.trim().split(",", -1);
        if (parts.length != 4) {
            throw new IllegalArgumentException("--crop must be x0,y0,x1,y1, got '" + text + "'");
        }
        int[] v = new int[4];
        for (int k = 0; k < 4; k++) {
            try {
                v[k] = Integer.parseInt(parts[k].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("--crop must be x0,y0,x1,y1 (whole numbers), got '" + text + "'");
            }
        }
        return crop(v[0], v[1], v[2], v[3], width, height);
    }

    /** The crop {@code x0 ≤ x < x1, y0 ≤ y < y1} of a {@code width × height} image, checked. */
    public static PixelWindow crop(int x0, int y0, int x1, int y1, int width, int height) {
        String c = "--crop " + x0 + "," + y0 + "," + x1 + "," + y1;
        if (x0 < 0 || y0 < 0) {
            throw new IllegalArgumentException(c + ": x0 and y0 must be 0 or more");
        }
        if (x1 <= x0 || y1 <= y0) {
            throw new IllegalArgumentException(c + ": x1 must be greater than x0 and y1 greater than y0");
        }
        if (x1 > width || y1 > height) {
            throw new IllegalArgumentException(c + ": outside the " + width + "x" + height
                    + " image (x1 <= " + width + ", y1 <= " + height + ")");
        }
        return new PixelWindow(x0, y0, x1, y1);
    }

    /**
     * {@code i/N} as typed after {@code --tile}: the {@code i}-th (from 1) of {@code N} bands of rows of
     * a {@code width × height} image ({@link #tile}).
     */
    public static PixelWindow parseTile(String text, int width, int height) {
        String[] parts = text.trim().split("/", -1);
        int i, n;
        try {
            if (parts.length != 2) {
                throw new NumberFormatException();
            }
            i = Integer.parseInt(parts[0].trim());
            n = Integer.parseInt(parts[1].trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("--tile must be i/N (whole numbers, e.g. 2/8), got '" + text + "'");
        }
        return tile(i, n, width, height);
    }

    /**
     * The {@code i}-th (1..N) of {@code n} bands of rows of equal height {@code floor(height / n)}, the
     * last one taking the rest; the bands cover the image exactly once.
     */
    public static PixelWindow tile(int i, int n, int width, int height) {
        if (n < 1) {
            throw new IllegalArgumentException("--tile " + i + "/" + n + ": N must be 1 or more");
        }
        if (i < 1 || i > n) {
            throw new IllegalArgumentException("--tile " + i + "/" + n + ": i must be 1.." + n);
        }
        if (n > height) {
            throw new IllegalArgumentException("--tile " + i + "/" + n + ": N must be at most the image height "
                    + height + " (each band needs a row)");
        }
        int band = height / n;
        int y0 = (i - 1) * band;
        return new PixelWindow(0, y0, width, i == n ? height : y0 + band);
    }

    public int width() { return x1 - x0; }

    public int height() { return y1 - y0; }

    /** True when this window is every pixel of a {@code width × height} image. */
    public boolean isWhole(int width, int height) {
        return x0 == 0 && y0 == 0 && x1 == width && y1 == height;
    }

    /** True when the window lies inside a {@code width × height} image. */
    public boolean fits(int width, int height) {
        return x1 <= width && y1 <= height;
    }

    /** This window grown by {@code margin} pixels on every side, clipped to a {@code width × height} image. */
    public PixelWindow grow(int margin, int width, int height) {
        return new PixelWindow(Math.max(0, x0 - margin), Math.max(0, y0 - margin), Math.min(width, x1 + margin),
                Math.min(height, y1 + margin));
    }

    @Override
    public String toString() {
        return x0 + "," + y0 + "," + x1 + "," + y1;
    }
}
