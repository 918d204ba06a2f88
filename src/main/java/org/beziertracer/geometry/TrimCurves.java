package org.beziertracer.geometry;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.beziertracer.math.BezierDecomposition;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * A {@link TrimRegion} as flat arrays of rational 2-D Bézier segments, with the exact point test
 * {@link #contains} and the box test {@link #classify}. Immutable; shared by render threads, each
 * passing its own scratch array.
 *
 * <h2>Segments</h2>
 * Every trim curve piece is cut into its Bézier segments by knot insertion
 * ({@link BezierDecomposition}) and stored in homogeneous form {@code (w·u, w·v, w)}, 3 doubles a
 * point, in loop order (a piece run backwards is reversed). Where consecutive pieces meet with a
 * gap (at most {@link TrimLoop#CLOSURE_TOLERANCE}) a straight segment closes it, so every loop is
 * exactly closed.
 *
 * <h2>Inside test</h2>
 * A point is inside a loop when the half-line {@code {(s, v) : s > u}} crosses the loop an odd
 * number of times, whatever the loop's orientation (the even–odd rule). A crossing is a change of
 * side, with "above" meaning {@code V > v} and "below" {@code V ≤ v} (half-open, so a crossing
 * through a joint between segments counts once). It is decided on the curves themselves by
 * recursive subdivision (the curve-side form of the ray–curve tests of Nishita, Sederberg and
 * Kakimoto, "Ray tracing trimmed rational surface patches", SIGGRAPH 1990, who count crossings
 * of the trim curves by Bézier clipping): a piece whose control box lies wholly above, below or
 * left of the point adds nothing; one wholly to its right adds 1 exactly when its end points lie
 * on different sides; otherwise it is halved with de Casteljau. A piece below
 * {@link #TINY} of the region's size is replaced by its chord, so the answer is exact for every
 * point farther than that from the curves. A region point is inside when it is inside some
 * outer loop (or there is none) and inside no hole.
 *
 * <h2>Points on a curve</h2>
 * The half-open rule decides a point on a curve as the point an infinitesimal step toward
 * {@code +u} and {@code +v} (a symbolic perturbation in the sense of Edelsbrunner and Mücke,
 * "Simulation of Simplicity", ACM TOG 9(1), 1990): every point of the plane belongs to exactly
 * one of two regions that share a curve, so no ray slips between them. The step may also be taken
 * toward {@code −u} or {@code −v} ({@link #contains(double, double, boolean, boolean, double[])}):
 * a hit on a patch's {@code u1} or {@code v1} edge is decided as a point just inside the patch,
 * so a loop running along the domain's border (a CAD face trimmed by its own edges) keeps its
 * {@code u_max} and {@code v_max} edges and a sphere's pole.
 */
public final class TrimCurves {

    /** Pieces smaller than this fraction of the region's size are decided by their chord. */
    public static final double TINY = 1e-13;
    /** Most pieces the subdivision stack holds; the depth needed for {@link #TINY} is about 45. */
    static final int STACK = 96;
    /** Where the box of the piece in hand is kept in the scratch array (after the stack). */
    private static final int BOX = STACK * DeCasteljau.MAX_ORDER * 3;
    /** Doubles of scratch {@link #contains} and {@link #classify} need. */
    public static final int SCRATCH_LENGTH = BOX + 4;

    /** {@link #classify} results. */
    public static final int OUTSIDE = 0, INSIDE = 1, MIXED = 2;

    private final int count;
    private final int[] degree;
    private final int[] offset;
    private final double[] points;
    /** Per segment: uMin, uMax, vMin, vMax of its Euclidean control points. */
    private final double[] boxes;
    /** Per segment: v of its first and of its last point (Euclidean). */
    private final double[] endV;
    private final int[] loop;
    private final boolean[] hole;
    private final int outerCount;
    private final double tiny;

    private TrimCurves(Builder b, boolean[] hole, int outerCount) {
        this.count = b.count;
        this.degree = Arrays.copyOf(b.degree, count);
        this.offset = Arrays.copyOf(b.offset, count);
        this.points = Arrays.copyOf(b.points, b.used);
        this.loop = Arrays.copyOf(b.loop, count);
        this.hole = hole;
        this.outerCount = outerCount;
        this.boxes = new double[4 * count];
        this.endV = new double[2 * count];
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int s = 0; s < count; s++) {
            box(points, offset[s], degree[s], boxes, 4 * s);
            int first = offset[s], last = first + 3 * degree[s];
            endV[2 * s] = points[first + 1] / points[first + 2];
            endV[2 * s + 1] = points[last + 1] / points[last + 2];
            lo = Math.min(lo, Math.min(boxes[4 * s], boxes[4 * s + 2]));
            hi = Math.max(hi, Math.max(boxes[4 * s + 1], boxes[4 * s + 3]));
        }
        this.tiny = TINY * Math.max(hi - lo, Double.MIN_NORMAL);
    }

    /** The segments of every loop of {@code region}. */
    public static TrimCurves of(TrimRegion region) {
        Builder b = new Builder();
        int loops = region.loopCount();
        boolean[] hole = new boolean[loops];
        int l = 0;
        for (TrimLoop loop : region.outer()) {
            b.addLoop(loop, l++);
        }
        for (TrimLoop loop : region.holes()) {
            hole[l] = true;
            b.addLoop(loop, l++);
        }
        return new TrimCurves(b, hole, region.outer().size());
    }

    /**
     * The trim curves of each patch (null for an untrimmed one), built once per distinct trim
     * region: the pieces of one surface share theirs.
     */
    public static TrimCurves[] forPatches(List<BezierPatch> patches) {
        TrimCurves[] out = new TrimCurves[patches.size()];
        Map<TrimRegion, TrimCurves> built = new IdentityHashMap<>();
        for (int k = 0; k < out.length; k++) {
            TrimRegion region = patches.get(k).trim();
            out[k] = region == null ? null : built.computeIfAbsent(region, TrimCurves::of);
        }
        return out;
    }

    /**
     * Every segment as a polyline of {@code samples + 1} points {@code u0, v0, u1, v1, …} at equal
     * parameter steps (for drawing; allocates).
     */
    public List<double[]> polylines(int samples) {
        List<double[]> out = new ArrayList<>(count);
        double[] p = new double[3], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int s = 0; s < count; s++) {
            double[] line = new double[2 * (samples + 1)];
            for (int k = 0; k <= samples; k++) {
                DeCasteljau.evaluateCurve(points, offset[s], 3, degree[s], 3, (double) k / samples, p, 0, scratch);
                line[2 * k] = p[0] / p[2];
                line[2 * k + 1] = p[1] / p[2];
            }
            out.add(line);
        }
        return out;
    }

    /** Number of Bézier segments, closing segments included. */
    public int segmentCount() { return count; }

    /**
     * True when {@code (u,v)} (surface parameters) is in the trimmed region, a point on a curve
     * decided as the point a step toward {@code +u, +v}. Allocation-free for regions of up to 64
     * loops; {@code scratch} needs {@link #SCRATCH_LENGTH} doubles.
     */
    public boolean contains(double u, double v, double[] scratch) {
        return contains(u, v, false, false, scratch);
    }

    /**
     * True when {@code (u,v)} is in the trimmed region, a point on a curve decided as the point an
     * infinitesimal step toward {@code −u} when {@code uBefore} (else {@code +u}) and toward
     * {@code −v} when {@code vBefore} (else {@code +v}). Exact like {@link #contains(double, double,
     * double[])}; allocation-free for regions of up to 64 loops.
     */
    public boolean contains(double u, double v, boolean uBefore, boolean vBefore, double[] scratch) {
        long parity = 0; // bit l: loop l crossed an odd number of times (loops ≥ 64 go to the slow path)
        boolean[] odd = hole.length > 64 ? new boolean[hole.length] : null;
        for (int s = 0; s < count; s++) {
            int b = 4 * s;
            if (above(boxes[b + 2], v, vBefore) || !above(boxes[b + 3], v, vBefore) || !right(boxes[b + 1], u, uBefore)) {
                continue; // wholly above, below or left: no crossing
            }
            // wholly right: a crossing exactly when the end points lie on different sides
            boolean crossed = right(boxes[b], u, uBefore)
                    ? above(endV[2 * s], v, vBefore) != above(endV[2 * s + 1], v, vBefore)
                    : crossings(s, u, v, uBefore, vBefore, scratch);
            if (crossed) {
                if (odd != null) {
                    odd[loop[s]] ^= true;
                } else {
                    parity ^= 1L << loop[s];
                }
            }
        }
        boolean inOuter = outerCount == 0;
        for (int l = 0; l < hole.length; l++) {
            boolean in = odd != null ? odd[l] : (parity >>> l & 1) != 0;
            if (in && hole[l]) {
                return false;
            }
            inOuter |= in && !hole[l];
        }
        return inOuter;
    }

    /**
     * Where the parameter box {@code [u0,u1]×[v0,v1]} lies: {@link #OUTSIDE} or {@link #INSIDE}
     * the region when no trim curve comes near it (decided at its centre), else {@link #MIXED}.
     * Conservative: a box reported inside or outside is so entirely.
     */
    public int classify(double u0, double u1, double v0, double v1, double[] scratch) {
        double size = Math.max(u1 - u0, v1 - v0);
        for (int s = 0; s < count; s++) {
            int b = 4 * s;
            if (boxes[b] > u1 || boxes[b + 1] < u0 || boxes[b + 2] > v1 || boxes[b + 3] < v0) {
                continue;
            }
            if (touches(s, u0, u1, v0, v1, size / 16, scratch)) {
                return MIXED;
            }
        }
        return contains(0.5 * (u0 + u1), 0.5 * (v0 + v1), scratch) ? INSIDE : OUTSIDE;
    }

    /** Parity of the crossings of segment {@code s} with the half-line right of {@code (u,v)}, perturbed as told. */
    private boolean crossings(int s, double u, double v, boolean uBefore, boolean vBefore, double[] arena) {
        int d = degree[s], len = 3 * (d + 1), stride = 3 * DeCasteljau.MAX_ORDER;
        System.arraycopy(points, offset[s], arena, 0, len);
        boolean odd = false;
        int top = 1;
        while (top > 0) {
            int e = (top - 1) * stride;
            box(arena, e, d, arena, BOX);
            double uMin = arena[BOX], uMax = arena[BOX + 1], vMin = arena[BOX + 2], vMax = arena[BOX + 3];
            if (above(vMin, v, vBefore) || !above(vMax, v, vBefore) || !right(uMax, u, uBefore)) {
                top--;
                continue;
            }
            int last = e + 3 * d;
            double y0 = arena[e + 1] / arena[e + 2], y1 = arena[last + 1] / arena[last + 2];
            if (right(uMin, u, uBefore)) {
                odd ^= above(y0, v, vBefore) != above(y1, v, vBefore);
                top--;
                continue;
            }
            if (Math.max(uMax - uMin, vMax - vMin) <= tiny || top == STACK) {
                odd ^= chordCrosses(arena[e] / arena[e + 2], y0, arena[last] / arena[last + 2], y1, u, v, uBefore, vBefore);
                top--;
                continue;
            }
            DeCasteljau.splitCurve(arena, e, 3, d, 3, 0.5, arena, e, arena, e + stride);
            top++;
        }
        return odd;
    }

    /** Crossing of the segment (x0,y0)–(x1,y1) with the half-line right of (u,v), half-open in v. */
    static boolean chordCrosses(double x0, double y0, double x1, double y1, double u, double v) {
        return chordCrosses(x0, y0, x1, y1, u, v, false, false);
    }

    /** {@link #chordCrosses(double, double, double, double, double, double)} for the point perturbed as told. */
    static boolean chordCrosses(double x0, double y0, double x1, double y1, double u, double v, boolean uBefore,
            boolean vBefore) {
        if (above(y0, v, vBefore) == above(y1, v, vBefore)) {
            return false;
        }
        double x = x0 + (x1 - x0) * ((v - y0) / (y1 - y0));
        return right(x, u, uBefore);
    }

    /** True when curve ordinate {@code y} lies above the point's {@code v} (a step below it when {@code vBefore}, above else). */
    private static boolean above(double y, double v, boolean vBefore) {
        return vBefore ? y >= v : y > v;
    }

    /** True when curve abscissa {@code x} lies right of the point's {@code u} (perturbed as in {@link #above}). */
    private static boolean right(double x, double u, boolean uBefore) {
        return uBefore ? x >= u : x > u;
    }

    /** True when some piece of segment {@code s} of size above {@code fine} meets the box (conservative). */
    private boolean touches(int s, double u0, double u1, double v0, double v1, double fine, double[] arena) {
        int d = degree[s], len = 3 * (d + 1), stride = 3 * DeCasteljau.MAX_ORDER;
        System.arraycopy(points, offset[s], arena, 0, len);
        int top = 1;
        while (top > 0) {
            int e = (top - 1) * stride;
            box(arena, e, d, arena, BOX);
            double uMin = arena[BOX], uMax = arena[BOX + 1], vMin = arena[BOX + 2], vMax = arena[BOX + 3];
            if (uMin > u1 || uMax < u0 || vMin > v1 || vMax < v0) {
                top--;
                continue;
            }
            if (Math.max(uMax - uMin, vMax - vMin) <= fine || top == STACK) {
                return true;
            }
            DeCasteljau.splitCurve(arena, e, 3, d, 3, 0.5, arena, e, arena, e + stride);
            top++;
        }
        return false;
    }

    /** Box (uMin, uMax, vMin, vMax) of the Euclidean control points of a homogeneous segment. */
    private static void box(double[] pts, int off, int d, double[] out, int o) {
        double uMin = Double.POSITIVE_INFINITY, uMax = Double.NEGATIVE_INFINITY;
        double vMin = Double.POSITIVE_INFINITY, vMax = Double.NEGATIVE_INFINITY;
        for (int k = 0, p = off; k <= d; k++, p += 3) {
            double x = pts[p] / pts[p + 2], y = pts[p + 1] / pts[p + 2];
            uMin = Math.min(uMin, x);
            uMax = Math.max(uMax, x);
            vMin = Math.min(vMin, y);
            vMax = Math.max(vMax, y);
        }
        out[o] = uMin;
        out[o + 1] = uMax;
        out[o + 2] = vMin;
        out[o + 3] = vMax;
    }

    /** Collects segments loop by loop (set-up time only). */
    private static final class Builder {
        int count, used;
        int[] degree = new int[16], offset = new int[16], loop = new int[16];
        double[] points = new double[256];

        void addLoop(TrimLoop trimLoop, int index) {
            int first = count;
            double[] prevEnd = null;
            for (TrimPiece piece : trimLoop.pieces()) {
                double[] ends = TrimLoop.ends(piece);
                if (prevEnd != null) {
                    link(prevEnd[0], prevEnd[1], ends[0], ends[1], index);
                }
                addPiece(piece, index);
                prevEnd = new double[] {ends[2], ends[3]};
            }
            double[] start = TrimLoop.ends(trimLoop.pieces().get(0));
            link(prevEnd[0], prevEnd[1], start[0], start[1], index);
            if (count == first) {
                throw new IllegalStateException("empty trim loop");
            }
        }

        private void addPiece(TrimPiece piece, int index) {
            TrimCurve c = piece.curve();
            boolean backwards = piece.from() > piece.to();
            double lo = Math.min(piece.from(), piece.to()), hi = Math.max(piece.from(), piece.to());
            BezierDecomposition.Segments s = BezierDecomposition.curve(c.degree(), c.knots(), c.homogeneous(), 3, lo, hi);
            int d = c.degree();
            for (int k = 0; k < s.count(); k++) {
                int seg = backwards ? s.count() - 1 - k : k;
                double[] pts = Arrays.copyOfRange(s.points(), s.offset(seg), s.offset(seg + 1));
                if (backwards) {
                    for (int a = 0, b = d; a < b; a++, b--) {
                        for (int x = 0; x < 3; x++) {
                            double t = pts[3 * a + x];
                            pts[3 * a + x] = pts[3 * b + x];
                            pts[3 * b + x] = t;
                        }
                    }
                }
                add(d, pts, index);
            }
        }

        /** A straight segment closing a gap (nothing when the points coincide). */
        private void link(double u0, double v0, double u1, double v1, int index) {
            if (u0 != u1 || v0 != v1) {
                add(1, new double[] {u0, v0, 1, u1, v1, 1}, index);
            }
        }

        private void add(int d, double[] pts, int index) {
            if (count == degree.length) {
                degree = Arrays.copyOf(degree, 2 * count);
                offset = Arrays.copyOf(offset, 2 * count);
                loop = Arrays.copyOf(loop, 2 * count);
            }
            if (used + pts.length > points.length) {
                points = Arrays.copyOf(points, 2 * (used + pts.length));
            }
            degree[count] = d;
            offset[count] = used;
            loop[count] = index;
            System.arraycopy(pts, 0, points, used, pts.length);
            used += pts.length;
            count++;
        }
    }
}
