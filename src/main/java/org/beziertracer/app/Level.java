package org.beziertracer.app;

import org.beziertracer.geometry.Tessellator;

/**
 * The numeric settings of the toolbox: each has a range, its value in a fresh app and, where the
 * toolbox offers a short list, the choices that {@link #next} cycles through.
 */
public enum Level {
    /** Subdivisions per direction of the projected wireframe. */
    WIREFRAME_SUBDIVISION("wireframe subdivision", 1, 64, 12),
    /** Samples per pixel while super-sampling is on. */
    SAMPLES_PER_PIXEL("samples per pixel", 1, 16, 4, 4, 9, 16),
    /** Render → Path Traced: the samples a pixel the picture refines to before it stops. */
    PATH_SAMPLES("path-traced samples per pixel", 1, 1024, 256, 16, 64, 256, 1024),
    /** Render → Path Traced: seconds the picture may refine before it stops (0: no limit but the samples). */
    PATH_SECONDS("path-traced time limit in seconds", 0, 3600, 0, 0, 10, 30, 60, 300),
    /** Progressive passes per displayed frame (the memoir's interactivity). */
    INTERACTIVITY("interactivity", 1, 8, 1),
    /** 0 = orthographic .. 100 = {@value OrbitView#MAX_FOV_DEGREES}° of horizontal field of view. */
    PERSPECTIVE("perspective", 0, 100, 36),
    /**
     * K of the tessellated mode: K×K cells per patch. The default 16 is the first offered choice
     * whose teapot silhouette stays within 0.5 px of the exact one at 800×600 (0.32 px; the
     * smallest such K is 15; docs/performance-journal.md, "Exact vs tessellated at equal accuracy").
     */
    TESSELLATION("tessellation", 1, Tessellator.MAX_SEGMENTS, 16, 4, 8, 16, 32, 64),
    /** Control points along u of the grid that Replace with Flat Grid makes. */
    GRID_U("grid points along u", 2, 10, 4),
    /** Control points along v of that grid. */
    GRID_V("grid points along v", 2, 10, 4),
    /**
     * Render → Exposure: tenths of a stop of exposure before the path tracer's tone curve, −5..+5
     * stops ({@link Settings#exposure()}; the command line's {@code --exposure}). Changing it tone
     * maps the picture again without restarting it.
     */
    EXPOSURE("exposure in tenths of a stop", -50, 50, 0);

    /** Tenths of a stop that Render → Brighter / Darker step. */
    public static final int EXPOSURE_STEP = 5;

    private final String label;
    private final int min;
    private final int max;
    private final int initial;
    private final int[] choices;

    Level(String label, int min, int max, int initial, int... choices) {
        this.label = label;
        this.min = min;
        this.max = max;
        this.initial = initial;
        this.choices = choices;
    }

    public int min() { return min; }

    public int max() { return max; }

    /** The value in a fresh app. */
    public int initial() { return initial; }

    /** The values the toolbox offers (a copy); all of {@code min..max} when it offers a range. */
    public int[] choices() {
        if (choices.length > 0) {
            return choices.clone();
        }
        int[] all = new int[max - min + 1];
        for (int k = 0; k < all.length; k++) {
            all[k] = min + k;
        }
        return all;
    }

    /** {@code value}, or a one-line error naming the setting and its range. */
    public int check(int value) {
        if (value < min || value > max) {
            throw new IllegalArgumentException(label + " must be " + min + ".." + max + ", got " + value);
        }
        return value;
    }

    /** {@code value + delta}, kept within the range. */
    public int step(int value, int delta) {
        return Math.max(min, Math.min(max, value + delta));
    }

    /** The next offered choice after {@code value}, wrapping round. */
    public int next(int value) {
        int[] offered = choices();
        for (int k = 0; k < offered.length; k++) {
            if (offered[k] == value) {
                return offered[(k + 1) % offered.length];
            }
        }
        for (int c : offered) {
            if (c > value) {
                return c;
            }
        }
        return offered[0];
    }

    /** The offered choice nearest above or at {@code value} (the largest when none is). */
    public int snap(int value) {
        int[] offered = choices();
        for (int c : offered) {
            if (c >= value) {
                return c;
            }
        }
        return offered[offered.length - 1];
    }
}
