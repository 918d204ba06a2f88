package org.beziertracer.accel;

/**
 * A packet of rays that share one traversal of a {@link Bvh}: the bounds of their origins and
 * reciprocal directions (interval arithmetic, as in S. Boulos, D. Edwards, J. D. Lacewell, J.
 * Kniss, J. Kautz, P. Shirley, I. Wald, "Packet-based Whitted and Distribution Ray Tracing",
 * Graphics Interface 2007, and I. Wald, S. Boulos, P. Shirley, "Ray Tracing Deformable Scenes using
 * Dynamic Bounding Volume Hierarchies", ACM TOG 26(1), 2007), and the leaves a traversal with those
 * bounds could not rule out ({@link Bvh#gather}), sorted by a lower bound of the distance at which
 * any ray of the packet enters them. Each ray then tests only those leaves ({@link
 * Bvh#closestHitsIn}, the rays as lanes of a batch): its own slab test on each leaf box, and the leaf's primitives, nearest entry
 * first until its {@code tMax} is passed. Neighbouring camera rays mostly meet the same few leaves,
 * so one traversal of the tree stands for the whole packet's.
 *
 * <p><b>Why the answers are the same as one ray at a time.</b> For one ray the slab distances are
 * {@code fl(fl(P - o) · invD)} (and the exit one times {@code 1 + 2γ₃}, {@link RayBox}). Rounded
 * subtraction and multiplication are monotone in each operand, so over the box of origins and
 * reciprocal directions the least entry and the greatest exit distance of each slab are reached at
 * a corner, which {@link Bvh#gather} computes with the same rounded operations; the box test with
 * those bounds ({@code max} of the least entries against {@code min} of the greatest exits) passes
 * whenever any ray of the packet passes its own. A leaf a ray would visit alone is therefore in the
 * list, and the ray visits it with its own slab test, so it meets exactly the primitives it would
 * meet alone, in nearest-entry order instead of near-child-first order.
 *
 * <p>The bounds need every ray's direction component on an axis to have the same sign and to be
 * non-zero (a zero gives an infinite reciprocal); a packet that breaks this, or whose list would
 * pass {@link #MAX_LEAVES}, is not gathered and its rays are traced one at a time.
 *
 * <p>Per-thread scratch: mutable, not thread-safe, allocates nothing after construction.
 */
public final class RayPacket {

    /** Most leaves a packet keeps; past this the packet is traced ray by ray. */
    public static final int MAX_LEAVES = 128;

    // Bounds of the origins and reciprocal directions, axis by axis (x, y, z)
    final double[] oLo = new double[3], oHi = new double[3];
    final double[] dLo = new double[3], dHi = new double[3];
    final double[] invLo = new double[3], invHi = new double[3];
    private int rays;
    private boolean spread;

    // The gathered leaves (node numbers of the hierarchy) and their least entry, ascending
    final int[] leafNodes = new int[MAX_LEAVES];
    final float[] leafEntry = new float[MAX_LEAVES];
    int leafCount;
    /** The hierarchy the leaves belong to, or null when the packet is not gathered. */
    Accelerator gatheredBy;

    /** Empties the packet: no rays, not gathered. */
    public void clear() {
        rays = 0;
        spread = false;
        gatheredBy = null;
        leafCount = 0;
    }

    /**
     * Adds a ray {@code o + t d}. Its reciprocal direction, as the traversal of one ray takes it, is
     * {@code 1.0 / d} per component; rounded division is monotone on each side of zero, so the
     * bounds of the reciprocals are the reciprocals of the bounds of {@code d}, taken once per
     * packet ({@link #reciprocals}).
     */
    public void add(double ox, double oy, double oz, double dx, double dy, double dz) {
        gatheredBy = null;
        if (rays == 0) {
            oLo[0] = ox; oLo[1] = oy; oLo[2] = oz;
            oHi[0] = ox; oHi[1] = oy; oHi[2] = oz;
            dLo[0] = dx; dLo[1] = dy; dLo[2] = dz;
            dHi[0] = dx; dHi[1] = dy; dHi[2] = dz;
        } else {
            widen(0, ox, dx);
            widen(1, oy, dy);
            widen(2, oz, dz);
        }
        rays++;
    }

    /**
     * Makes the packet hold the {@code n} rays at {@code rays[0 .. 6n-1]} (origin, direction each),
     * as {@link #clear} and {@link #add} for each would; returns this.
     */
    public RayPacket of(double[] rays, int n) {
        clear();
        if (n == 0) {
            return this;
        }
        // add() per ray, its bounds in locals rather than in the arrays
        double oxLo = rays[0], oyLo = rays[1], ozLo = rays[2], dxLo = rays[3], dyLo = rays[4], dzLo = rays[5];
        double oxHi = oxLo, oyHi = oyLo, ozHi = ozLo, dxHi = dxLo, dyHi = dyLo, dzHi = dzLo;
        boolean nan = false;
        for (int o = 6; o < 6 * n; o += 6) {
            double ox = rays[o], oy = rays[o + 1], oz = rays[o + 2];
            double dx = rays[o + 3], dy = rays[o + 4], dz = rays[o + 5];
            oxLo = ox < oxLo ? ox : oxLo; oxHi = ox > oxHi ? ox : oxHi;
            oyLo = oy < oyLo ? oy : oyLo; oyHi = oy > oyHi ? oy : oyHi;
            ozLo = oz < ozLo ? oz : ozLo; ozHi = oz > ozHi ? oz : ozHi;
            dxLo = dx < dxLo ? dx : dxLo; dxHi = dx > dxHi ? dx : dxHi;
            dyLo = dy < dyLo ? dy : dyLo; dyHi = dy > dyHi ? dy : dyHi;
            dzLo = dz < dzLo ? dz : dzLo; dzHi = dz > dzHi ? dz : dzHi;
            nan |= ox != ox | oy != oy | oz != oz | dx != dx | dy != dy | dz != dz;
        }
        oLo[0] = oxLo; oLo[1] = oyLo; oLo[2] = ozLo;
        oHi[0] = oxHi; oHi[1] = oyHi; oHi[2] = ozHi;
        dLo[0] = dxLo; dLo[1] = dyLo; dLo[2] = dzLo;
        dHi[0] = dxHi; dHi[1] = dyHi; dHi[2] = dzHi;
        this.rays = n;
        spread = nan;
        return this;
    }

    private void widen(int a, double o, double d) {
        // NaN compares false both ways: it is caught by the finiteness test in reciprocals()
        if (o < oLo[a]) oLo[a] = o;
        if (o > oHi[a]) oHi[a] = o;
        if (d < dLo[a]) dLo[a] = d;
        if (d > dHi[a]) dHi[a] = d;
        if (o != o || d != d) spread = true;
    }

    /**
     * Sets {@code invLo, invHi} from the bounds of the directions; false when a component's
     * directions are not all of one sign and non-zero, or a bound is not finite.
     */
    boolean reciprocals() {
        if (rays == 0 || spread) {
            return false;
        }
        for (int a = 0; a < 3; a++) {
            double lo = dLo[a], hi = dHi[a];
            if (!(Math.abs(oLo[a]) < Double.POSITIVE_INFINITY && Math.abs(oHi[a]) < Double.POSITIVE_INFINITY)
                    || !(lo > 0 || hi < 0)) {
                return false;
            }
            double invA = 1.0 / hi, invB = 1.0 / lo;   // invA <= invB on either side of zero
            if (invA == 0 || invB == 0 || !(Math.abs(invA) < Double.POSITIVE_INFINITY && Math.abs(invB) < Double.POSITIVE_INFINITY)) {
                return false;
            }
            invLo[a] = invA;
            invHi[a] = invB;
        }
        return true;
    }

    /** True when the last {@link Accelerator#gather} on {@code accel} succeeded for the rays added. */
    public boolean gatheredBy(Accelerator accel) {
        return gatheredBy == accel;
    }

    /** Leaves gathered (0 when the packet misses the whole hierarchy). */
    public int leafCount() {
        return leafCount;
    }
}
