package org.beziertracer.render;

/**
 * Sub-pixel sample positions: stateless and allocation-free. Positions depend only on the pixel,
 * the sample index and the seed, never on the thread or the order of work, so every render of the
 * same job is bit-for-bit identical and a progressive render ends on the one-shot image.
 *
 * <p>Random numbers come from a SplitMix64-style hash of {@code (seed, x, y, sample, dimension)}
 * (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014).
 */
public final class PixelSampler {
    private final SamplerKind kind;
    private final PixelFilter filter;
    private final int spp, kx, ky;
    private final long seed;
    /**
     * Offsets (already warped) of the samples whose position does not depend on the pixel:
     * every sample of the regular sampler, the centre sample 0 of the adaptive one;
     * {@code fixed[2s], fixed[2s+1]}, NaN where the position is random.
     */
    private final double[] fixed;
    /** The stratum of each sample: {@code cell[2s], cell[2s+1]} (no division per pixel). */
    private final int[] cell;

    public PixelSampler(SamplerKind kind, PixelFilter filter, int spp, long seed) {
        this(kind, filter, spp, seed, false);
    }

    /**
     * A sampler; with {@code spread} (the path tracer's) the regular and jittered samples visit the
     * cells of the grid in a spread order instead of row by row: sample k takes cell
     * {@code (centre + k·stride) mod spp}, the stride the integer nearest {@code spp/φ} (φ the golden
     * ratio) prime to spp — a rank-1 lattice order (Korobov; the golden-ratio choice as in
     * M. Roberts, "The unreasonable effectiveness of quasirandom sequences", 2018) that starts at the
     * centre cell. Every cell is still taken once, but any first samples of a pixel are spread over
     * it: a progressive picture stopped early (a time budget) is not shifted toward the top of its
     * pixels, as a row-by-row order would leave it.
     */
    public PixelSampler(SamplerKind kind, PixelFilter filter, int spp, long seed, boolean spread) {
        if (spp < 1) {
            throw new IllegalArgumentException("samples per pixel must be >= 1, got " + spp);
        }
        this.kind = kind;
        this.filter = filter;
        this.spp = spp;
        this.seed = seed;
        int extra = kind == SamplerKind.ADAPTIVE ? Math.max(spp - 1, 1) : spp;
        this.kx = (int) Math.ceil(Math.sqrt(extra));
        this.ky = (extra + kx - 1) / kx;
        this.fixed = new double[2 * spp];
        this.cell = new int[2 * spp];
        boolean spreadOrder = spread && kind != SamplerKind.ADAPTIVE;
        int stride = spreadOrder ? goldenStride(spp) : 1, start = spreadOrder ? centreCell(spp) : 0;
        for (int k = 0; k < spp; k++) {
            int c = kind == SamplerKind.ADAPTIVE ? Math.max(k - 1, 0) : (int) ((start + (long) k * stride) % spp);
            cell[2 * k] = c % kx;
            cell[2 * k + 1] = c / kx;
        }
        double[] o = new double[2];
        for (int k = 0; k < spp; k++) {
            boolean isFixed = kind == SamplerKind.REGULAR || kind == SamplerKind.ADAPTIVE && k == 0;
            if (isFixed) {
                position(0, 0, k, o);
            }
            fixed[2 * k] = isFixed ? o[0] : Double.NaN;
            fixed[2 * k + 1] = isFixed ? o[1] : Double.NaN;
        }
    }

    /** The integer nearest {@code n/φ} that is prime to {@code n} (1 for n ≤ 2): the spread order's stride. */
    static int goldenStride(int n) {
        int base = (int) Math.round(n / ((1 + Math.sqrt(5)) / 2));
        for (int d = 0; d < n; d++) {
            for (int candidate : new int[] {base + d, base - d}) {
                if (candidate >= 1 && candidate < n && gcd(candidate, n) == 1) {
                    return candidate;
                }
            }
        }
        return 1;
    }

    /** The cell in the middle of the grid (row ky/2, column kx/2), or the last cell when that row is not full. */
    private int centreCell(int n) {
        return Math.min(n - 1, (ky / 2) * kx + kx / 2);
    }

    private static int gcd(int a, int b) {
        return b == 0 ? a : gcd(b, a % b);
    }

    public int spp() { return spp; }

    public SamplerKind kind() { return kind; }

    /**
     * Writes the offset of sample {@code s} of pixel {@code (x, y)} from the pixel's top-left corner
     * into {@code out[0], out[1]} (in [0,1) for the box filter, [-0.5,1.5) for the tent).
     */
    public void offset(int x, int y, int s, double[] out) {
        double fx = fixed[2 * s];
        if (fx == fx) { // not NaN: the same for every pixel, computed once
            out[0] = fx;
            out[1] = fixed[2 * s + 1];
            return;
        }
        position(x, y, s, out);
    }

    private void position(int x, int y, int s, double[] out) {
        double ox, oy;
        if (kind == SamplerKind.ADAPTIVE && s == 0) {
            ox = 0.5;
            oy = 0.5;
        } else {
            int cx = cell[2 * s], cy = cell[2 * s + 1];
            double jx = 0.5, jy = 0.5;
            if (kind != SamplerKind.REGULAR) {
                jx = uniform(x, y, s, 0);
                jy = uniform(x, y, s, 1);
            }
            ox = (cx + jx) / kx;
            oy = (cy + jy) / ky;
        }
        out[0] = filter.warp(ox);
        out[1] = filter.warp(oy);
    }

    /** A uniform double in [0,1) from the hash of the pixel, sample and dimension. */
    double uniform(int x, int y, int s, int dim) {
        long z = seed + 0x9E3779B97F4A7C15L * (((long) x << 40) ^ ((long) y << 20) ^ ((long) s << 2) ^ dim);
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        z ^= z >>> 31;
        return (z >>> 11) * 0x1.0p-53;
    }
}
