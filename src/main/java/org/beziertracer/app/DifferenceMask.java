package org.beziertracer.app;

import java.util.BitSet;
import java.util.function.BooleanSupplier;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.render.Camera;
import org.beziertracer.render.ImageDifference;

/**
 * View → Difference to clipping: the pixels of a picture whose primary ray hits something else
 * with the selected method than with Bézier clipping. One ray per pixel, through its centre; a
 * pixel differs when one method hits and the other misses, when they hit different objects
 * (another patch, plane or sphere), or when their distances along the ray differ by more than
 * {@link #RELATIVE_T} of the scene size. The criterion is on the hits, not on colours (compare
 * {@link ImageDifference}, the CLI's difference of two pictures). Immutable once made.
 */
public final class DifferenceMask {

    /** Largest distance between two hits along the ray that is still "the same hit", as a share of the scene size. */
    public static final double RELATIVE_T = 1e-6;
    /** Colour of a differing pixel in {@link #argb()}: opaque red. */
    public static final int MARK = ImageDifference.MARK;
    /** Colour of an agreeing pixel in {@link #argb()}: a half-transparent dark veil, so the marks stand out. */
    public static final int VEIL = 0x80000000;

    private final int width;
    private final int height;
    private final BitSet marks;
    private final int count;
    private final String method;

    private DifferenceMask(int width, int height, BitSet marks, String method) {
        this.width = width;
        this.height = height;
        this.marks = marks;
        this.count = marks.cardinality();
        this.method = method;
    }

    /**
     * Compares the primary rays of a {@code width × height} picture seen by {@code camera}, traced
     * through {@code method} and through {@code clipping} (snapshots of the same scene). Checks
     * {@code cancelled} once per row and returns null when it says so.
     *
     * @param label what the status bar calls the selected method
     */
    public static DifferenceMask compare(SceneIntersector method, SceneIntersector clipping, CameraSpec camera,
                                         int width, int height, String label, BooleanSupplier cancelled) {
        Camera cam = new Camera(camera);
        TraceContext ctxA = method.newContext(), ctxB = clipping.newContext();
        Hit a = new Hit(), b = new Hit();
        double[] ray = new double[6];
        double tolerance = RELATIVE_T * clipping.sceneSize();
        BitSet marks = new BitSet(width * height);
        for (int y = 0; y < height; y++) {
            if (cancelled.getAsBoolean()) {
                return null;
            }
            for (int x = 0; x < width; x++) {
                cam.generateRay(x + 0.5, y + 0.5, width, height, ray);
                double len = Math.sqrt(ray[3] * ray[3] + ray[4] * ray[4] + ray[5] * ray[5]);
                double dx = ray[3] / len, dy = ray[4] / len, dz = ray[5] / len; // t in scene units
                boolean hitA = method.closestHit(ctxA, ray[0], ray[1], ray[2], dx, dy, dz, 0, Double.POSITIVE_INFINITY, a);
                boolean hitB = clipping.closestHit(ctxB, ray[0], ray[1], ray[2], dx, dy, dz, 0, Double.POSITIVE_INFINITY, b);
                if (differ(hitA, a, hitB, b, tolerance)) {
                    marks.set(y * width + x);
                }
            }
        }
        return new DifferenceMask(width, height, marks, label);
    }

    /** True when two outcomes of one ray are not the same hit. */
    static boolean differ(boolean hitA, Hit a, boolean hitB, Hit b, double tolerance) {
        if (hitA != hitB) {
            return true;
        }
        return hitA && (a.kind != b.kind || a.index != b.index || !(Math.abs(a.t - b.t) <= tolerance));
    }

    public int width() { return width; }

    public int height() { return height; }

    /** Pixels that differ. */
    public int count() { return count; }

    /** The compared method as the status bar names it (e.g. {@code newton}, {@code tessellated 16}). */
    public String method() { return method; }

    /** True when pixel {@code (x, y)} differs. */
    public boolean marked(int x, int y) { return marks.get(y * width + x); }

    /** The overlay as {@code width × height} ARGB pixels, row after row: {@link #MARK} where they differ, {@link #VEIL} elsewhere. */
    public int[] argb() {
        int[] out = new int[width * height];
        java.util.Arrays.fill(out, VEIL);
        for (int i = marks.nextSetBit(0); i >= 0; i = marks.nextSetBit(i + 1)) {
            out[i] = MARK;
        }
        return out;
    }

    /** The status bar's words for this mask, e.g. {@code newton: 12 pixels differ from clipping}. */
    public String describe() {
        return method + ": " + count + (count == 1 ? " pixel differs" : " pixels differ") + " from clipping";
    }
}
