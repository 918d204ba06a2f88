package org.beziertracer.render.light;

import org.beziertracer.model.HdrImage;

/**
 * An environment of radiance from an equirectangular (latitude–longitude) HDR image, z up: column
 * x is the azimuth {@code atan2(wy, wx)} from −π (left) to π, turned by {@code rotate} degrees about
 * z; row y is the polar angle {@code acos(wz)} from 0 (top) to π. Each pixel is constant (no
 * filtering), so the radiance and the sampling density match exactly.
 *
 * <p>Importance-sampled by luminance: a piecewise-constant 2D distribution over (u, v) of weight
 * {@code Y(pixel) · sin θ}, sampled as the marginal over rows then the conditional within the row,
 * {@code pdf_ω = pdf_uv / (2π² sin θ)} (pbrt-v4 §12.5.2 and §A.5, "Piecewise-constant 2D
 * distributions"; M. Pharr, G. Humphreys, "Infinite area light source with importance sampling",
 * 2004). Luminance: Rec. 709 weights (0.2126, 0.7152, 0.0722). Immutable.
 */
public final class ImageEnvironment implements Light {
    private final int w, h;
    private final float[] rgb;
    private final double rotate;
    /** Per row the cumulative weights of its pixels, {@code rowCdf[y * (w + 1) + x]}, normalised to 1. */
    private final double[] rowCdf;
    /** The cumulative weight of the rows, {@code rowsCdf[y]}, normalised to 1; and each row's share. */
    private final double[] rowsCdf, rowShare;
    /** Each pixel's density over the unit square (u, v). */
    private final double[] density;
    private final boolean black;

    /** @param image radiance; @param intensity its scale; @param rotateDegrees turn about z */
    public ImageEnvironment(HdrImage image, double intensity, double rotateDegrees) {
        if (!(intensity >= 0) || !Double.isFinite(intensity) || !Double.isFinite(rotateDegrees)) {
            throw new IllegalArgumentException("an image environment needs a finite intensity >= 0 and rotation");
        }
        w = image.width();
        h = image.height();
        rotate = Math.toRadians(rotateDegrees);
        rgb = new float[3 * w * h];
        double[] weight = new double[w * h];
        double total = 0;
        for (int y = 0; y < h; y++) {
            double sinTheta = Math.sin(Math.PI * (y + 0.5) / h);
            for (int x = 0; x < w; x++) {
                int p = y * w + x;
                for (int c = 0; c < 3; c++) {
                    rgb[3 * p + c] = (float) (image.get(x, y, c) * intensity);
                }
                weight[p] = (0.2126 * rgb[3 * p] + 0.7152 * rgb[3 * p + 1] + 0.0722 * rgb[3 * p + 2]) * sinTheta;
                total += weight[p];
            }
        }
        black = !(total > 0);
        rowCdf = new double[h * (w + 1)];
        rowsCdf = new double[h + 1];
        rowShare = new double[h];
        density = new double[w * h];
        for (int y = 0; y < h; y++) {
            double row = 0;
            for (int x = 0; x < w; x++) {
                row += weight[y * w + x];
                rowCdf[y * (w + 1) + x + 1] = row;
            }
            for (int x = 1; x <= w; x++) {
                rowCdf[y * (w + 1) + x] = row > 0 ? rowCdf[y * (w + 1) + x] / row : (double) x / w;
            }
            rowShare[y] = black ? 0 : row / total;
            rowsCdf[y + 1] = rowsCdf[y] + rowShare[y];
            for (int x = 0; x < w; x++) {
                density[y * w + x] = black ? 0 : weight[y * w + x] / total * w * h;
            }
        }
        rowsCdf[h] = 1;
    }

    @Override
    public boolean sample(double px, double py, double pz, double u1, double u2, LightSample out) {
        if (black) {
            return false;
        }
        int y = find(rowsCdf, 0, h, u1);
        double dv = (u1 - rowsCdf[y]) / (rowsCdf[y + 1] - rowsCdf[y]);
        int o = y * (w + 1);
        int x = find(rowCdf, o, w, u2);
        double c0 = rowCdf[o + x], c1 = rowCdf[o + x + 1];
        double du = c1 > c0 ? (u2 - c0) / (c1 - c0) : 0.5;
        double u = (x + Math.min(Math.max(du, 0), 1)) / w, v = (y + Math.min(Math.max(dv, 0), 1)) / h;
        double theta = Math.PI * v, phi = -Math.PI + 2 * Math.PI * u + rotate;
        double sinTheta = Math.sin(theta);
        if (!(sinTheta > 0)) {
            return false;
        }
        int p = y * w + x;
        double pdf = density[p] / (2 * Math.PI * Math.PI * sinTheta);
        if (!(pdf > 0)) {
            return false;
        }
        out.set(sinTheta * Math.cos(phi), sinTheta * Math.sin(phi), Math.cos(theta), Double.POSITIVE_INFINITY,
                rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2], pdf, false);
        return true;
    }

    /** The index i in [0, n) with {@code cdf[o + i] <= u < cdf[o + i + 1]} (binary search). */
    private static int find(double[] cdf, int o, int n, double u) {
        int lo = 0, hi = n - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (cdf[o + mid] <= u) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    /** The pixel seen in the unit direction w. */
    private int pixel(double wx, double wy, double wz) {
        double phi = Math.atan2(wy, wx) - rotate;
        double u = phi / (2 * Math.PI) + 0.5;
        u -= Math.floor(u);
        double v = Math.acos(Math.max(-1, Math.min(1, wz))) / Math.PI;
        int x = Math.min(w - 1, (int) (u * w)), y = Math.min(h - 1, (int) (v * h));
        return y * w + x;
    }

    @Override
    public double pdf(double px, double py, double pz, double wx, double wy, double wz) {
        double sinTheta = Math.sqrt(Math.max(0, 1 - wz * wz));
        if (black || !(sinTheta > 0)) {
            return 0;
        }
        return density[pixel(wx, wy, wz)] / (2 * Math.PI * Math.PI * sinTheta);
    }

    @Override
    public double hit(double ox, double oy, double oz, double wx, double wy, double wz, double[] le) {
        int p = pixel(wx, wy, wz);
        le[0] = rgb[3 * p]; le[1] = rgb[3 * p + 1]; le[2] = rgb[3 * p + 2];
        return Double.MAX_VALUE;
    }

    @Override
    public boolean isEnvironment() { return true; }
}
