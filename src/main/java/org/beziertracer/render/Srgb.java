package org.beziertracer.render;

/**
 * The colour pipeline's last step: linear RGB → clamp to [0,1] → sRGB transfer curve (IEC
 * 61966-2-1) → 8 bits → opaque ARGB. A 16,384-entry table over the clamped linear value keeps it
 * fast; its error is under a quarter of an 8-bit step. NaN encodes as 0.
 */
public final class Srgb {
    private static final int SIZE = 1 << 14;
    private static final byte[] TABLE = new byte[SIZE + 1];

    static {
        for (int k = 0; k <= SIZE; k++) {
            TABLE[k] = (byte) Math.round(255 * encode((double) k / SIZE));
        }
    }

    private Srgb() {}

    /** The exact sRGB transfer function of a linear value in [0,1]. */
    public static double encode(double linear) {
        return linear <= 0.0031308 ? 12.92 * linear : 1.055 * Math.pow(linear, 1 / 2.4) - 0.055;
    }

    /** The inverse transfer function: the linear value of an sRGB-encoded value in [0,1]. */
    public static double decode(double encoded) {
        return encoded <= 0.04045 ? encoded / 12.92 : Math.pow((encoded + 0.055) / 1.055, 2.4);
    }

    /** 8-bit sRGB of a linear value (clamped; NaN → 0). */
    public static int to8(float linear) {
        if (!(linear > 0)) {
            return 0;
        }
        if (linear >= 1) {
            return 255;
        }
        return TABLE[(int) (linear * SIZE + 0.5f)] & 0xFF;
    }

    /** Opaque ARGB of a linear RGB triple. */
    public static int argb(float r, float g, float b) {
        return 0xFF000000 | to8(r) << 16 | to8(g) << 8 | to8(b);
    }
}
