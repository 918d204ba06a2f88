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
        for (int k = 0; k < spp; k++) {
            int c = kind == SamplerKind.ADAPTIVE ? Math.max(k - 1, 0) : k;
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
