package org.beziertracer.render;

import org.beziertracer.model.HdrImage;
import org.beziertracer.model.Texture;

/**
 * Looks up a {@link Texture} at a hit's (u,v): a checker by the parity of its square, an image by
 * bilinear interpolation between the four texel centres around {@code (u·su, v·sv)}, wrapping
 * around at the image's borders (repeat), u along the columns and v up the rows from the bottom
 * (pbrt-v4 §10.4, "Image texture": M. Pharr, W. Jakob, G. Humphreys, "Physically Based
 * Rendering", 4th ed., 2023). Reads the texture's immutable pixels in place; no lookup allocates.
 * Immutable and thread-safe.
 */
final class SurfaceTexture {
    private final double su, sv;
    /** The checker's colours, even then odd; unused for an image. */
    private final double[] checker;
    /** The image, or null for a checker. */
    private final HdrImage image;
    private final int w, h;

    SurfaceTexture(Texture t) {
        su = t.su();
        sv = t.sv();
        if (t instanceof Texture.Checker c) {
            checker = new double[] {c.even().r(), c.even().g(), c.even().b(), c.odd().r(), c.odd().g(), c.odd().b()};
            image = null;
            w = 0;
            h = 0;
        } else {
            image = ((Texture.Image) t).pixels();
            checker = null;
            w = image.width();
            h = image.height();
        }
    }

    /** The colour at {@code (u, v)} into {@code out[0..2]}. */
    void lookup(double u, double v, double[] out) {
        double s = u * su, t = v * sv;
        if (image == null) {
            long cu = (long) Math.floor(s), cv = (long) Math.floor(t);
            int o = ((cu + cv) & 1) == 0 ? 0 : 3;
            out[0] = checker[o]; out[1] = checker[o + 1]; out[2] = checker[o + 2];
            return;
        }
        // Continuous texel coordinates: texel centres at i + ½, row 0 at the top (v = 1)
        double x = (s - Math.floor(s)) * w - 0.5;
        double y = (1 - (t - Math.floor(t))) * h - 0.5;
        double fx = Math.floor(x), fy = Math.floor(y);
        double ax = x - fx, ay = y - fy;
        int x0 = wrap((long) fx, w), x1 = wrap((long) fx + 1, w);
        int y0 = wrap((long) fy, h), y1 = wrap((long) fy + 1, h);
        for (int c = 0; c < 3; c++) {
            double top = (1 - ax) * image.get(x0, y0, c) + ax * image.get(x1, y0, c);
            double bottom = (1 - ax) * image.get(x0, y1, c) + ax * image.get(x1, y1, c);
            out[c] = (1 - ay) * top + ay * bottom;
        }
    }

    private static int wrap(long i, int n) {
        return (int) Math.floorMod(i, (long) n);
    }
}
