package org.beziertracer.render;

/**
 * An environment image around the scene for the {@code emap} analysis view: linear RGB in an
 * equirectangular (latitude–longitude) layout, {@code z} up: column {@code x} is the azimuth
 * {@code atan2(dy, dx)} from −π (left) to π, row {@code y} the polar angle {@code acos(dz)} from 0
 * (up, top row) to π. Looked up bilinearly, wrapping in azimuth. Immutable.
 *
 * <p>{@link #studio()} is the built-in one: a photographer's studio — a dark floor, a grey wall
 * brightening toward the horizon, two long soft boxes overhead and one on each side — whose
 * sharp-edged, bright shapes make the reflection of every bump and crease readable.
 */
public final class EnvironmentMap {

    private final int width, height;
    private final float[] rgb;

    /**
     * @param rgb linear RGB, row-major, {@code 3·width·height} values, finite and ≥ 0
     * @throws IllegalArgumentException for a wrong length, a size below 2×2, or a bad value
     */
    public EnvironmentMap(int width, int height, float[] rgb) {
        if (width < 2 || height < 2 || rgb == null || rgb.length != 3L * width * height) {
            throw new IllegalArgumentException("an environment image needs at least 2×2 pixels of RGB, got " + width
                    + "×" + height);
        }
        for (float v : rgb) {
            if (!(v >= 0) || !Float.isFinite(v)) {
                throw new IllegalArgumentException("an environment image holds finite colours ≥ 0, got " + v);
            }
        }
        this.width = width;
        this.height = height;
        this.rgb = rgb.clone();
    }

    /** The linear image of 8-bit sRGB pixels {@code argb} (row-major, {@code width × height}), as a PNG holds them. */
    public static EnvironmentMap fromSrgb(int width, int height, int[] argb) {
        if (argb.length != width * height) {
            throw new IllegalArgumentException("expected " + width * height + " pixels, got " + argb.length);
        }
        float[] lin = new float[3 * argb.length];
        for (int k = 0; k < argb.length; k++) {
            for (int c = 0; c < 3; c++) {
                lin[3 * k + c] = (float) Srgb.decode((argb[k] >> (16 - 8 * c) & 0xFF) / 255.0);
            }
        }
        return new EnvironmentMap(width, height, lin);
    }

    public int width() { return width; }

    public int height() { return height; }

    /** The colour seen in the unit direction {@code (dx, dy, dz)}, into {@code out[0..2]}. */
    public void lookup(double dx, double dy, double dz, double[] out) {
        double u = (Math.atan2(dy, dx) / (2 * Math.PI) + 0.5) * width - 0.5;
        double v = Math.acos(Math.max(-1, Math.min(1, dz))) / Math.PI * height - 0.5;
        int x0 = (int) Math.floor(u), y0 = (int) Math.floor(v);
        double fx = u - x0, fy = v - y0;
        int ya = Math.max(0, Math.min(height - 1, y0)), yb = Math.max(0, Math.min(height - 1, y0 + 1));
        int xa = Math.floorMod(x0, width), xb = Math.floorMod(x0 + 1, width);
        for (int c = 0; c < 3; c++) {
            double top = (1 - fx) * rgb[3 * (ya * width + xa) + c] + fx * rgb[3 * (ya * width + xb) + c];
            double bottom = (1 - fx) * rgb[3 * (yb * width + xa) + c] + fx * rgb[3 * (yb * width + xb) + c];
            out[c] = (1 - fy) * top + fy * bottom;
        }
    }

    private static final class Studio {
        static final EnvironmentMap IMAGE = build(512, 256);
    }

    /** The built-in studio (made once). */
    public static EnvironmentMap studio() { return Studio.IMAGE; }

    private static EnvironmentMap build(int w, int h) {
        float[] px = new float[3 * w * h];
        for (int y = 0; y < h; y++) {
            double polar = (y + 0.5) / h * Math.PI, elevation = 90 - Math.toDegrees(polar);
            for (int x = 0; x < w; x++) {
                double azimuth = Math.toDegrees(((x + 0.5) / w - 0.5) * 2 * Math.PI);
                double g;
                if (elevation < 0) {
                    g = 0.02 + 0.03 * Math.exp(elevation / 10);             // floor, lighter near the horizon
                } else {
                    g = 0.05 + 0.25 * Math.exp(-elevation / 25);            // wall, brightest at the horizon
                }
                // two soft boxes overhead (on either side of the zenith), one on each side, a dimmer one behind
                boolean overhead = elevation > 55 && elevation < 75 && Math.abs(Math.sin(Math.toRadians(azimuth))) > 0.55;
                boolean side = elevation > 5 && elevation < 40 && (Math.abs(azimuth - 90) < 18 || Math.abs(azimuth + 90) < 18);
                boolean back = elevation > 10 && elevation < 30 && Math.abs(Math.abs(azimuth) - 180) < 10;
                if (overhead || side) {
                    g = 4.0;
                } else if (back) {
                    g = 1.5;
                }
                int o = 3 * (y * w + x);
                px[o] = (float) g;
                px[o + 1] = (float) g;
                px[o + 2] = (float) (g * (elevation < 0 ? 0.9 : 1.05));
            }
        }
        return new EnvironmentMap(w, h, px);
    }
}
