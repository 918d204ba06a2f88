package org.beziertracer.render;

/**
 * The first two dimensions of the Sobol sequence (I. M. Sobol', "On the distribution of points in a
 * cube and the approximate evaluation of integrals", 1967), Owen-scrambled and index-shuffled by
 * hashing as in B. Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020, with the
 * Laine–Karras permutation (S. Laine, T. Karras, "Stratified sampling for stochastic
 * transparency", EGSR 2011) for the nested uniform scramble (A. B. Owen, "Randomly permuted
 * (t,m,s)-nets and (t,s)-sequences", 1995).
 *
 * <p>For any seed, the points ({@link #sample}{@code (i, 0, seed)}, {@code sample(i, 1, seed)}) of
 * the first {@code 2^k} indices form a (0, k, 2)-net in base 2: each elementary interval of area
 * {@code 2^-k} holds exactly one point (the shuffle maps them onto an aligned block of Sobol
 * indices, which is such a net, and the scramble keeps nets nets). Each point alone is uniformly
 * distributed, so an estimate stays unbiased. Stateless, allocation-free; 32 bits of resolution.
 */
final class OwenSobol {
    private OwenSobol() {}

    /**
     * Sobol's direction numbers of dimension 1 (the Pascal matrix mod 2; dimension 0 is the
     * identity), XOR-summed a byte of the index at a time: {@code BYTES[256 * k + b]} is the XOR of
     * the direction numbers of the bits set in {@code b} at byte {@code k}. The point is linear in
     * the index's bits over GF(2), so four look-ups give what the loop over 32 bits gives, to the bit.
     */
    private static final int[] BYTES = new int[4 * 256];

    static {
        int[] directions = new int[32];
        int v = 0x8000_0000;
        for (int bit = 0; bit < 32; bit++) {
            directions[bit] = v;
            v ^= v >>> 1;
        }
        for (int k = 0; k < 4; k++) {
            for (int b = 0; b < 256; b++) {
                int x = 0;
                for (int bit = 0; bit < 8; bit++) {
                    if ((b >>> bit & 1) != 0) {
                        x ^= directions[8 * k + bit];
                    }
                }
                BYTES[256 * k + b] = x;
            }
        }
    }

    /** Dimension {@code dim} (0 or 1) of Sobol point {@code index}, unscrambled, as a 32-bit fraction. */
    static int sobol(int index, int dim) {
        if (dim == 0) {
            return Integer.reverse(index);
        }
        return BYTES[index & 0xFF] ^ BYTES[256 + (index >>> 8 & 0xFF)] ^ BYTES[512 + (index >>> 16 & 0xFF)]
                ^ BYTES[768 + (index >>> 24)];
    }

    /**
     * An Owen scramble of a 32-bit fraction: the Laine–Karras permutation on its reversed bits,
     * so each bit is flipped by a hash of the bits above it only.
     */
    static int nestedUniformScramble(int x, int seed) {
        x = Integer.reverse(x);
        x += seed;
        x ^= x * 0x6c50b47c;
        x ^= x * 0xb82f1e52;
        x ^= x * 0xc7afe638;
        x ^= x * 0x8d22f6e6;
        return Integer.reverse(x);
    }

    /**
     * Dimension {@code dim} (0 or 1) of point {@code index} of the shuffled, scrambled sequence
     * of {@code seed}, in [0, 1).
     */
    static double sample(int index, int dim, int seed) {
        return coordinate(shuffle(index, seed), dim, seed);
    }

    /** The Sobol index that sample {@code index} of {@code seed}'s sequence takes. */
    static int shuffle(int index, int seed) {
        return nestedUniformScramble(index, seed);
    }

    /** Dimension {@code dim} of the shuffled index {@code shuffled} ({@link #shuffle}), scrambled, in [0, 1). */
    static double coordinate(int shuffled, int dim, int seed) {
        int x = nestedUniformScramble(sobol(shuffled, dim), hash(seed, dim + 1));
        return (x & 0xFFFF_FFFFL) * 0x1.0p-32;
    }

    /** A 32-bit hash of a seed and a small number (the SplitMix64 finaliser). */
    static int hash(int seed, int k) {
        long z = ((long) seed << 32 | (k & 0xFFFF_FFFFL)) * 0x9E3779B97F4A7C15L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return (int) (z ^ (z >>> 31));
    }
}
