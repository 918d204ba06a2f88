package org.beziertracer.render;

/**
 * Two renders of the same view compared pixel by pixel (docs/methods.md: how far a ray–patch
 * method's picture lies from Bézier clipping's). A pixel differs when some colour channel differs
 * by more than {@code percent} of the full range (255 levels). Pure functions over packed ARGB.
 */
public final class ImageDifference {
    private ImageDifference() {}

    /** Mark of a differing pixel in {@link #overlay}: opaque red. */
    public static final int MARK = 0xFFFF0000;

    /** True when some channel of {@code a} and {@code b} differs by more than {@code percent} % of 255. */
    public static boolean differs(int a, int b, double percent) {
        double limit = 2.55 * percent;
        for (int shift = 0; shift <= 16; shift += 8) {
            if (Math.abs(((a >> shift) & 0xFF) - ((b >> shift) & 0xFF)) > limit) {
                return true;
            }
        }
        return false;
    }

    /** The number of pixels where {@code a} and {@code b} (same size) differ by more than {@code percent} %. */
    public static int count(int[] a, int[] b, double percent) {
        requireSameSize(a, b);
        int n = 0;
        for (int i = 0; i < a.length; i++) {
            if (differs(a[i], b[i], percent)) {
                n++;
            }
        }
        return n;
    }

    /**
     * {@code image} as a dimmed grey picture with its pixels that differ from {@code other} by
     * more than {@code percent} % in {@link #MARK}, so a few differing pixels stand out.
     */
    public static int[] overlay(int[] image, int[] other, double percent) {
        requireSameSize(image, other);
        int[] out = new int[image.length];
        for (int i = 0; i < image.length; i++) {
            int c = image[i];
            int grey = (((c >> 16) & 0xFF) + ((c >> 8) & 0xFF) + (c & 0xFF)) / 6; // half brightness
            out[i] = differs(c, other[i], percent) ? MARK : 0xFF000000 | grey << 16 | grey << 8 | grey;
        }
        return out;
    }

    private static void requireSameSize(int[] a, int[] b) {
        if (a.length != b.length) {
            throw new IllegalArgumentException("images of different sizes: " + a.length + " and " + b.length + " pixels");
        }
    }
}
