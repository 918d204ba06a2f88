package org.beziertracer.geometry;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.BezierPatch;

/**
 * How continuous a surface is across a border two patches share: the largest position gap (G0),
 * normal angle (G1) and normal-curvature mismatch (G2) over the whole border, each an upper bound
 * proved from Bernstein coefficients and refined by subdivision until it is within 1 % of the
 * largest sampled value ({@link CertifiedMax}).
 *
 * <h2>The border</h2>
 * Side {@code sideA} of patch A and side {@code sideB} of patch B, B's running against A's when
 * {@code reversed}; both are parametrised by the same {@code t ∈ [0,1]} ({@link BorderStrip}), A's
 * cross direction taken outward and B's inward, so both point from A into B. Measures compare the
 * two patches at the same {@code t}.
 *
 * <h2>Measures</h2>
 * <ul>
 *   <li><b>G0</b>, {@code max_t |S_A(t) − S_B(t)|}. Polynomial patches: the gap is a Bézier curve
 *       (the lower degree elevated) and {@code |d(t)| ≤ max_k |d_k|} (convex hull). Rational:
 *       {@code d = (X_A w_B − X_B w_A) / (w_A w_B)}, bounded by the numerator's largest coefficient
 *       over the denominator's smallest (positive, the weights being positive).</li>
 *   <li><b>G1</b>, the angle between the normals {@code n = S_t × S_s} of the two sides (polynomial
 *       in t; homogeneous form for rational patches, {@link BorderStrip#normal}). With
 *       {@code c = n_A × n_B}, {@code δ = n_A · n_B}, the angle is {@code atan2(|c|, δ)}, increasing in
 *       {@code |c|} where {@code δ ≥ 0} and decreasing where {@code δ < 0}, so on a segment it is at
 *       most {@code atan2(max|c_k|, min δ_k)} when {@code min δ_k ≥ 0}, else
 *       {@code atan2(√max(0, min (c·c)_k), min δ_k)}. This is the bounding of normal cones by the
 *       coefficients of the normal's Bernstein form (T. W. Sederberg and R. J. Meyers, "Loop
 *       detection in surface patch intersections", CAGD 5 (1988) 161–171), applied to the pair.
 *       The angle is between the surface's two sides as they continue each other (0 for a smooth
 *       join, 180° for a fold back), whatever the patches' own orientation; {@link Report#flipped}
 *       says whether their own normals {@code S_u × S_v} disagree.</li>
 *   <li><b>G2</b>, {@code max_t |κ_A − κ_B|}, the normal curvatures of the two sides in their
 *       direction across the border, {@code w = n × S_t} (in the tangent plane, perpendicular to the
 *       border): with {@code (α, β) = (−S_t·S_s, S_t·S_t)} the parameter direction of {@code w},
 *       {@code κ = Q / (N^{3/2} τ)}, {@code Q = α² S_tt·n + 2αβ S_ts·n + β² S_ss·n}, {@code N = n·n},
 *       {@code τ = S_t·S_t} (do Carmo, <i>Differential Geometry of Curves and Surfaces</i>, §3-2:
 *       {@code κ_n = II(w)/I(w)}, with {@code I(w) = |w|² = τN}). On a segment the bound is the
 *       smaller of the interval difference of the two curvatures (each from the ranges of
 *       {@code Q, N, τ}) and of the exact identity
 *       <pre>
 *   κ_A − κ_B = (P − ζ V) / (|n_A| N_A² N_B² τ_A τ_B),   U = Q_A N_B² τ_B,  V = Q_B N_A² τ_A,
 *   P = N_A U − δ V,   ζ = |n_A||n_B| − δ = |n_A × n_B|² / (|n_A||n_B| + δ),   δ = n_A · n_B
 *       </pre>
 *       (from {@code N^{3/2} = N²/|n|} and Lagrange's identity), bounded term by term: {@code P}
 *       and {@code V} are polynomials (degree 50 and 40 for bicubics), {@code P} vanishes on a G2
 *       border and {@code ζ} with the G1 angle, and nothing is divided by a curvature, so the bound
 *       falls to rounding level on a G2 border even where the curvature changes sign (the interval
 *       difference alone converges only linearly there). Polynomial patches only: for a rational
 *       side G2 is the largest of {@value #RATIONAL_G2_SAMPLES}+1 evenly spaced samples and is
 *       reported as not certified.</li>
 * </ul>
 *
 * <h2>Degenerate points</h2>
 * Where a normal vanishes at an end of the border (a collapsed edge: the teapot's lid and bottom
 * poles), its coefficient there is at most {@link #DEGENERATE_RELATIVE} of its largest (the weld
 * tolerance's scale), and the factor {@code t} (or {@code 1 − t}) is divided out
 * ({@link BernsteinPoly#dividedByT}), as many times as it occurs: G1 is then the angle between the
 * limit normals, and the end is reported in {@link Bound#degenerate}. G2 is bounded on the border
 * less {@link #DEGENERATE_MARGIN} (1/1024 in t) at such an end: there the cross-border curvature
 * {@code Q / (N^{3/2} τ)} divides quantities that vanish together, and rounding in them, not the
 * surface, would decide the value. At interior points where a normal vanishes, G1 and G2 exclude
 * segments shorter than {@code 2^-24} around them ({@link CertifiedMax}), reported the same way.
 *
 * <p>Stateless and thread-safe.
 */
public final class BorderContinuity {

    /** A normal's end coefficient at most this fraction of its largest is a degenerate (zero) normal. */
    public static final double DEGENERATE_RELATIVE = 1e-9;
    /** G2 is bounded this far in t from an end of the border where a normal vanishes. */
    public static final double DEGENERATE_MARGIN = 1.0 / 1024;
    /** Samples (plus one) of G2 on a rational border. */
    public static final int RATIONAL_G2_SAMPLES = 1024;
    /** Most segments per measure and border. */
    public static final int MAX_SEGMENTS = 4000;

    private BorderContinuity() {}

    /**
     * One measure over a border.
     *
     * @param bound      upper bound over the border (NaN when it could not be computed)
     * @param t          border parameter of the worst sample
     * @param worst      the worst sampled value
     * @param certified  true when {@code bound} is proved; false for a sampled maximum
     * @param tight      true when the bound is within 1 % of {@code worst} (or below the floor)
     * @param degenerate parameters where a normal vanishes (limit taken, or a tiny segment excluded)
     */
    public record Bound(double bound, double t, double worst, boolean certified, boolean tight, double[] degenerate) {}

    /**
     * The continuity of one border.
     *
     * @param g0      position gap, model units
     * @param g1      normal angle, radians
     * @param g2      normal-curvature mismatch, 1/model units
     * @param flipped the patches' own normals ({@code S_u × S_v}) point to opposite sides
     */
    public record Report(Bound g0, Bound g1, Bound g2, boolean flipped) {}

    /**
     * Measures the border between {@code sideA} of {@code a} and {@code sideB} of {@code b}.
     *
     * @param reversed B's side runs against A's
     * @param scale    model size: sets the floors below which bounds need not be tighter
     *                 ({@code 1e-14·scale} for G0, 1e-14 rad for G1, {@code 1e-12/scale} for G2)
     */
    public static Report analyze(BezierPatch a, int sideA, BezierPatch b, int sideB, boolean reversed, double scale) {
        BorderStrip sa = BorderStrip.of(a, sideA, false, true), sb = BorderStrip.of(b, sideB, reversed, false);
        double size = scale > 0 ? scale : 1;
        Bound g0 = gap(sa, sb, 1e-14 * size);
        Bound g1 = angle(sa, sb, 1e-14);
        // G2 away from ends where a normal vanishes
        double t0 = 0, t1 = 1;
        for (double end : g1.degenerate()) {
            if (end == 0) {
                t0 = DEGENERATE_MARGIN;
            } else if (end == 1) {
                t1 = 1 - DEGENERATE_MARGIN;
            }
        }
        Bound g2 = sa.rational() || sb.rational() ? sampledCurvature(sa, sb, t0, t1)
                : curvature(sa, sb, t0, t1, 1e-12 / size);
        return new Report(g0, g1, g2, sa.sign() != sb.sign());
    }

    private static Bound of(CertifiedMax.Result r, double[] degenerate) {
        return new Bound(r.bound(), r.tWorst(), r.worst(), true, r.tight(), union(degenerate, r.degenerate()));
    }

    // ---- G0

    static Bound gap(BorderStrip a, BorderStrip b, double floor) {
        BernsteinPoly num, den;
        if (!a.rational() && !b.rational()) {
            num = a.position().minus(b.position());
            den = BernsteinPoly.constant(1);
        } else {
            BernsteinPoly wa = a.weight(), wb = b.weight();
            num = a.position().scaledBy(wb).minus(b.position().scaledBy(wa));
            den = wa.scaledBy(wb);
        }
        return of(CertifiedMax.maximise(GAP, new BernsteinPoly[] {num, den}, floor, MAX_SEGMENTS), new double[0]);
    }

    private static final CertifiedMax.Measure GAP = new CertifiedMax.Measure() {
        @Override
        public double bound(BernsteinPoly[] p) {
            double lo = p[1].min();
            return lo > 0 ? p[0].maxNorm() / lo : Double.POSITIVE_INFINITY;
        }

        @Override
        public double value(BernsteinPoly[] p, boolean atOne) {
            return p[0].norm(atOne ? p[0].degree() : 0) / p[1].endValue(atOne);
        }

        @Override
        public boolean degenerate(BernsteinPoly[] p) { return false; }
    };

    // ---- G1

    static Bound angle(BorderStrip a, BorderStrip b, double floor) {
        List<Double> ends = new ArrayList<>();
        BernsteinPoly na = limitNormal(a.normal(), ends), nb = limitNormal(b.normal(), ends);
        BernsteinPoly c = na.cross(nb);
        BernsteinPoly[] polys = {c, na.dot(nb), c.dot(c), na.dot(na), nb.dot(nb)};
        double[] degenerate = ends.stream().mapToDouble(Double::doubleValue).distinct().sorted().toArray();
        return of(CertifiedMax.maximise(ANGLE, polys, floor, MAX_SEGMENTS), degenerate);
    }

    /** Divides out the factors {@code t} and {@code 1 − t} of a normal that vanishes at an end, noting the end. */
    static BernsteinPoly limitNormal(BernsteinPoly n, List<Double> ends) {
        double scale = n.maxNorm();
        while (n.degree() > 0 && n.norm(0) <= DEGENERATE_RELATIVE * scale) {
            n = n.dividedByT();
            ends.add(0.0);
        }
        while (n.degree() > 0 && n.norm(n.degree()) <= DEGENERATE_RELATIVE * scale) {
            n = n.dividedByOneMinusT();
            ends.add(1.0);
        }
        return n;
    }

    private static final CertifiedMax.Measure ANGLE = new CertifiedMax.Measure() {
        @Override
        public double bound(BernsteinPoly[] p) {
            double dotLo = p[1].min();
            if (dotLo >= 0) {
                return Math.atan2(p[0].maxNorm(), dotLo);
            }
            return Math.atan2(Math.sqrt(Math.max(0, p[2].min())), dotLo);
        }

        @Override
        public double value(BernsteinPoly[] p, boolean atOne) {
            if (!(p[3].endValue(atOne) > 0 && p[4].endValue(atOne) > 0)) {
                return Double.NaN;
            }
            return Math.atan2(p[0].norm(atOne ? p[0].degree() : 0), p[1].endValue(atOne));
        }

        @Override
        public boolean degenerate(BernsteinPoly[] p) { return !(p[3].min() > 0 && p[4].min() > 0); }
    };

    // ---- G2

    static Bound curvature(BorderStrip a, BorderStrip b, double t0, double t1, double floor) {
        BernsteinPoly[] ka = curvatureParts(a), kb = curvatureParts(b);
        BernsteinPoly qa = ka[0], na = ka[1], ta = ka[2], qb = kb[0], nb = kb[1], tb = kb[2];
        BernsteinPoly u = qa.scaledBy(nb.scaledBy(nb)).scaledBy(tb), v = qb.scaledBy(na.scaledBy(na)).scaledBy(ta);
        BernsteinPoly d = ka[3].dot(kb[3]), c = ka[3].cross(kb[3]);
        BernsteinPoly pg = na.scaledBy(u).minus(d.scaledBy(v));
        BernsteinPoly[] polys = {qa, na, ta, qb, nb, tb, pg, v, c.dot(c), d};
        if (t0 > 0 || t1 < 1) {
            for (int k = 0; k < polys.length; k++) {
                polys[k] = polys[k].restricted(t0, t1);
            }
        }
        CertifiedMax.Result r = CertifiedMax.maximise(CURVATURE, polys, floor, MAX_SEGMENTS);
        double[] excluded = java.util.Arrays.stream(r.degenerate()).map(t -> t0 + (t1 - t0) * t).toArray();
        double[] ends = t0 > 0 && t1 < 1 ? new double[] {0, 1} : t0 > 0 ? new double[] {0} : t1 < 1 ? new double[] {1} : new double[0];
        return new Bound(r.bound(), t0 + (t1 - t0) * r.tWorst(), r.worst(), true, r.tight(), union(ends, excluded));
    }

    /** {@code Q, N, τ} and the normal {@code n} of one side (polynomial patches). */
    static BernsteinPoly[] curvatureParts(BorderStrip s) {
        BernsteinPoly t = s.xt().coordinates(0, 3), d = s.xs().coordinates(0, 3);
        BernsteinPoly n = t.cross(d);
        BernsteinPoly td = t.dot(d), tau = t.dot(t);
        BernsteinPoly ltt = s.xtt().coordinates(0, 3).dot(n), lts = s.xts().coordinates(0, 3).dot(n);
        BernsteinPoly lss = s.xss().coordinates(0, 3).dot(n);
        BernsteinPoly q = ltt.scaledBy(td.scaledBy(td))
                .minus(lts.scaledBy(td.scaledBy(tau)).times(2))
                .plus(lss.scaledBy(tau.scaledBy(tau)));
        return new BernsteinPoly[] {q, n.dot(n), tau, n};
    }

    private static final CertifiedMax.Measure CURVATURE = new CertifiedMax.Measure() {
        @Override
        public double bound(BernsteinPoly[] p) {
            double naLo = p[1].min(), taLo = p[2].min(), nbLo = p[4].min(), tbLo = p[5].min();
            if (!(naLo > 0 && taLo > 0 && nbLo > 0 && tbLo > 0)) {
                return Double.POSITIVE_INFINITY;
            }
            // Each curvature's range from the ranges of Q, N and τ
            double daLo = Math.pow(naLo, 1.5) * taLo, daHi = Math.pow(p[1].max(), 1.5) * p[2].max();
            double dbLo = Math.pow(nbLo, 1.5) * tbLo, dbHi = Math.pow(p[4].max(), 1.5) * p[5].max();
            double[] ka = quotient(p[0].min(), p[0].max(), daLo, daHi);
            double[] kb = quotient(p[3].min(), p[3].max(), dbLo, dbHi);
            double b1 = Math.max(ka[1] - kb[0], kb[1] - ka[0]);
            // κ_A − κ_B = (P − ζ V) / (|n_A| N_A² N_B² τ_A τ_B), ζ = |n_A||n_B| − δ = |c|² / (|n_A||n_B| + δ)
            double eLo = Math.sqrt(naLo * nbLo), eHi = Math.sqrt(p[1].max() * p[4].max()), dLo = p[9].min();
            double zeta = eHi - dLo;
            if (eLo + dLo > 0) {
                zeta = Math.min(zeta, Math.max(0, p[8].max()) / (eLo + dLo));
            }
            double den = Math.sqrt(naLo) * naLo * naLo * nbLo * nbLo * taLo * tbLo;
            double b2 = (p[6].maxNorm() + zeta * p[7].maxNorm()) / den;
            return Math.min(b1, b2);
        }

        @Override
        public double value(BernsteinPoly[] p, boolean atOne) {
            double ka = kappa(p[0].endValue(atOne), p[1].endValue(atOne), p[2].endValue(atOne));
            double kb = kappa(p[3].endValue(atOne), p[4].endValue(atOne), p[5].endValue(atOne));
            return Math.abs(ka - kb);
        }

        @Override
        public boolean degenerate(BernsteinPoly[] p) {
            return !(p[1].min() > 0 && p[2].min() > 0 && p[4].min() > 0 && p[5].min() > 0);
        }
    };

    private static double kappa(double q, double n, double tau) {
        return n > 0 && tau > 0 ? q / (Math.pow(n, 1.5) * tau) : Double.NaN;
    }

    /** The range of {@code x / y} for {@code x ∈ [xLo, xHi]}, {@code y ∈ [yLo, yHi]}, {@code yLo > 0}. */
    private static double[] quotient(double xLo, double xHi, double yLo, double yHi) {
        return new double[] {Math.min(xLo / yLo, xLo / yHi), Math.max(xHi / yLo, xHi / yHi)};
    }

    /** G2 of a rational border: the largest of evenly spaced samples (not certified). */
    static Bound sampledCurvature(BorderStrip a, BorderStrip b, double t0, double t1) {
        double worst = Double.NaN, tWorst = 0;
        for (int k = 0; k <= RATIONAL_G2_SAMPLES; k++) {
            double t = t0 + (t1 - t0) * k / RATIONAL_G2_SAMPLES;
            double v = Math.abs(normalCurvature(a.euclidean(t)) - normalCurvature(b.euclidean(t)));
            if (!(v <= worst) && !Double.isNaN(v)) {
                worst = v;
                tWorst = t;
            }
        }
        double[] ends = t0 > 0 && t1 < 1 ? new double[] {0, 1} : t0 > 0 ? new double[] {0} : t1 < 1 ? new double[] {1} : new double[0];
        return new Bound(worst, tWorst, worst, false, false, ends);
    }

    /** {@code κ = Q / (N^{3/2} τ)} from Euclidean {@code S, S_t, S_s, S_tt, S_ts, S_ss} (18 doubles). */
    static double normalCurvature(double[] e) {
        double[] t = {e[3], e[4], e[5]}, d = {e[6], e[7], e[8]};
        double[] n = {t[1] * d[2] - t[2] * d[1], t[2] * d[0] - t[0] * d[2], t[0] * d[1] - t[1] * d[0]};
        double td = dot(t, d), tau = dot(t, t);
        double q = td * td * (e[9] * n[0] + e[10] * n[1] + e[11] * n[2])
                - 2 * td * tau * (e[12] * n[0] + e[13] * n[1] + e[14] * n[2])
                + tau * tau * (e[15] * n[0] + e[16] * n[1] + e[17] * n[2]);
        return kappa(q, dot(n, n), tau);
    }

    private static double dot(double[] x, double[] y) {
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    }

    private static double[] union(double[] x, double[] y) {
        double[] all = new double[x.length + y.length];
        System.arraycopy(x, 0, all, 0, x.length);
        System.arraycopy(y, 0, all, x.length, y.length);
        return java.util.Arrays.stream(all).distinct().sorted().toArray();
    }
}
