package org.beziertracer.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.io.BptWriter;
import org.beziertracer.model.io.ObjWriter;

/**
 * Seeded big bicubic models for the "lean acceleration data" measurements (issue [6]) and the
 * scale benchmarks: a connected CAD-like body and a random soup of the same size.
 *
 * <p><b>Body</b> ({@link #body}): one closed, watertight, tangent-continuous surface of genus 1 —
 * a ring swept along a rounded-square path (polar superellipse, exponent 4) with a rounded-
 * rectangle section (exponent 6: flat faces joined by fillets), knurled by a grid of shallow
 * bumps of about four patches a wavelength, like the grip of a machined part. Patch
 * {@code (i, j)} of the {@code I×J} grid covers {@code [i/I, (i+1)/I] × [j/J, (j+1)/J]} of the
 * surface's periodic parameters; its bicubic net is the Hermite interpolant of the surface at the
 * four corners (position, both first derivatives and the twist, by central differences), so
 * neighbours share their border curves exactly. Patches are curved at their own scale (fillets,
 * bumps), as in a finely detailed CAD model, not flat tiles.
 *
 * <p><b>Soup</b> ({@link #soup}): independent wavy bicubic height fields with random orientation,
 * size and position in the unit cube, sized so that their total area is about that of the body's
 * bounding box faces: no shared borders, many overlapping boxes.
 *
 * <p>Command line (writes OBJ, or BPT for a {@code .bpt} name):
 * {@code java -cp bench/target/benchmarks.jar org.beziertracer.bench.BigModels body|soup COUNT FILE [SEED]}.
 */
public final class BigModels {
    private BigModels() {}

    /** Half-length of the path's square (x) and its half-width (y), in model units. */
    static final double PATH_X = 100, PATH_Y = 70;
    /** Half-width (radial) and half-height of the section. */
    static final double SECTION_W = 18, SECTION_H = 12;
    /** Bump height as a fraction of the section half-height, and patches per bump wavelength. */
    static final double BUMP = 0.08;
    static final int PATCHES_PER_WAVE = 4;
    /** Step of the central differences, in the surface's parameters. */
    private static final double H = 1e-5;

    /** The body with {@code count} patches (a ring of {@code I×J = count}, I about 2.5 J). */
    public static List<BezierPatch> body(int count) {
        int rows = rows(count);
        int cols = count / rows;
        Surface s = new Surface(cols, rows);
        // Corner data on the periodic grid: the seam's corners are the first column's and row's
        double[][][] corner = new double[cols + 1][rows + 1][];
        for (int i = 0; i <= cols; i++) {
            for (int j = 0; j <= rows; j++) {
                corner[i][j] = i < cols && j < rows ? s.hermite((double) i / cols, (double) j / rows)
                        : corner[i % cols][j % rows];
            }
        }
        List<BezierPatch> patches = new ArrayList<>(count);
        double du = 1.0 / cols, dv = 1.0 / rows;
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < cols; i++) {
                patches.add(bicubic(corner[i][j], corner[i + 1][j], corner[i][j + 1], corner[i + 1][j + 1], du, dv));
            }
        }
        return patches;
    }

    /** Rows J of the body's grid: the divisor of {@code count} nearest to {@code √(count / 2.5)}. */
    static int rows(int count) {
        if (count < 1) {
            throw new IllegalArgumentException("patch count must be positive, got " + count);
        }
        int ideal = (int) Math.max(1, Math.round(Math.sqrt(count / 2.5)));
        for (int d = 0; ; d++) {
            if (ideal - d >= 1 && count % (ideal - d) == 0) {
                return ideal - d;
            }
            if (count % (ideal + d) == 0) {
                return ideal + d;
            }
        }
    }

    /**
     * The bicubic Bézier net interpolating the Hermite data (position, d/du, d/dv, twist; 12
     * doubles each, {@link Surface#hermite}) at its four corners, for parameter steps du, dv.
     */
    static BezierPatch bicubic(double[] c00, double[] c10, double[] c01, double[] c11, double du, double dv) {
        double[] net = new double[48];
        double[][] c = {c00, c10, c01, c11};
        for (int k = 0; k < 4; k++) {
            int a = k & 1, b = k >> 1;
            double su = a == 0 ? du / 3 : -du / 3, sv = b == 0 ? dv / 3 : -dv / 3;
            int i0 = 3 * a, j0 = 3 * b, i1 = a == 0 ? 1 : 2, j1 = b == 0 ? 1 : 2;
            for (int x = 0; x < 3; x++) {
                double p = c[k][x], pu = c[k][3 + x], pv = c[k][6 + x], puv = c[k][9 + x];
                net[3 * (4 * j0 + i0) + x] = p;
                net[3 * (4 * j0 + i1) + x] = p + su * pu;
                net[3 * (4 * j1 + i0) + x] = p + sv * pv;
                net[3 * (4 * j1 + i1) + x] = p + su * pu + sv * pv + su * sv * puv;
            }
        }
        return new BezierPatch(3, 3, net);
    }

    /** The body's surface, periodic in both parameters. */
    static final class Surface {
        final double wavesU, wavesV;
        final double[] a = new double[3], b = new double[3], c = new double[3], d = new double[3];

        Surface(int cols, int rows) {
            wavesU = Math.max(1, Math.round((double) cols / PATCHES_PER_WAVE));
            wavesV = Math.max(1, Math.round((double) rows / PATCHES_PER_WAVE));
        }

        /** Position, d/du, d/dv and d²/dudv at (u, v), 12 doubles. */
        double[] hermite(double u, double v) {
            double[] out = new double[12];
            point(u, v, out, 0);
            point(u + H, v, a, 0);
            point(u - H, v, b, 0);
            for (int x = 0; x < 3; x++) {
                out[3 + x] = (a[x] - b[x]) / (2 * H);
            }
            point(u, v + H, a, 0);
            point(u, v - H, b, 0);
            for (int x = 0; x < 3; x++) {
                out[6 + x] = (a[x] - b[x]) / (2 * H);
            }
            point(u + H, v + H, a, 0);
            point(u - H, v - H, b, 0);
            point(u + H, v - H, c, 0);
            point(u - H, v + H, d, 0);
            for (int x = 0; x < 3; x++) {
                out[9 + x] = (a[x] + b[x] - c[x] - d[x]) / (4 * H * H);
            }
            return out;
        }

        /** The point at (u, v): u along the path, v around the section. */
        void point(double u, double v, double[] out, int o) {
            double theta = 2 * Math.PI * u, phi = 2 * Math.PI * v;
            double r = superellipse(theta, 4);
            double cx = PATH_X * r * Math.cos(theta), cy = PATH_Y * r * Math.sin(theta);
            // Outward in-plane normal of the path from its tangent (numerically, from the same formula)
            double t2 = theta + 1e-6, r2 = superellipse(t2, 4);
            double tx = PATH_X * r2 * Math.cos(t2) - cx, ty = PATH_Y * r2 * Math.sin(t2) - cy;
            double len = Math.hypot(tx, ty);
            double nx = ty / len, ny = -tx / len;
            double rho = superellipse(phi, 6);
            double bump = 1 + BUMP * Math.sin(2 * Math.PI * wavesU * u) * Math.sin(2 * Math.PI * wavesV * v);
            double x = SECTION_W * rho * Math.cos(phi) * bump, z = SECTION_H * rho * Math.sin(phi) * bump;
            out[o] = cx + x * nx;
            out[o + 1] = cy + x * ny;
            out[o + 2] = z;
        }

        /** Polar radius of the unit superellipse {@code |x|^p + |y|^p = 1} (p even: smooth). */
        static double superellipse(double angle, int p) {
            double c = Math.cos(angle), s = Math.sin(angle);
            return Math.pow(Math.pow(c * c, p / 2.0) + Math.pow(s * s, p / 2.0), -1.0 / p);
        }
    }

    /**
     * {@code count} random wavy bicubic patches in the body's bounding box, each a height field of
     * relief 0.3 with a random orientation and a size that makes their total area about twice the
     * box's largest face.
     */
    public static List<BezierPatch> soup(int count, long seed) {
        Random rnd = new Random(seed);
        double bx = PATH_X + SECTION_W, by = PATH_Y + SECTION_W, bz = SECTION_H;
        double size = Math.sqrt(2 * (2 * bx) * (2 * by) / count);
        List<BezierPatch> patches = new ArrayList<>(count);
        for (int k = 0; k < count; k++) {
            BezierPatch p = Fixtures.heightField(rnd, 3, 3, size * (0.5 + rnd.nextDouble()), 0.3);
            double[] net = p.copyNet();
            double[] rot = randomRotation(rnd);
            double ox = bx * (2 * rnd.nextDouble() - 1), oy = by * (2 * rnd.nextDouble() - 1);
            double oz = bz * (2 * rnd.nextDouble() - 1);
            for (int i = 0; i < net.length; i += 3) {
                double x = net[i], y = net[i + 1], z = net[i + 2];
                net[i] = ox + rot[0] * x + rot[1] * y + rot[2] * z;
                net[i + 1] = oy + rot[3] * x + rot[4] * y + rot[5] * z;
                net[i + 2] = oz + rot[6] * x + rot[7] * y + rot[8] * z;
            }
            patches.add(new BezierPatch(3, 3, net));
        }
        return patches;
    }

    /** A uniformly random rotation matrix (row-major), from a random unit quaternion. */
    static double[] randomRotation(Random rnd) {
        double w = rnd.nextGaussian(), x = rnd.nextGaussian(), y = rnd.nextGaussian(), z = rnd.nextGaussian();
        double n = Math.sqrt(w * w + x * x + y * y + z * z);
        w /= n; x /= n; y /= n; z /= n;
        return new double[] {
            1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
            2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    }

    /** The model named {@code body} or {@code soup} with {@code count} patches. */
    public static List<BezierPatch> of(String kind, int count, long seed) {
        return switch (kind) {
            case "body" -> body(count);
            case "soup" -> soup(count, seed);
            default -> throw new IllegalArgumentException("model must be body or soup, got " + kind);
        };
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 3) {
            System.err.println("usage: BigModels body|soup COUNT FILE.obj|FILE.bpt [SEED]");
            System.exit(2);
        }
        List<BezierPatch> patches = of(args[0], Integer.parseInt(args[1]), args.length > 3 ? Long.parseLong(args[3]) : 1);
        Path file = Path.of(args[2]);
        if (file.toString().toLowerCase(Locale.ROOT).endsWith(".bpt")) {
            BptWriter.write(file, patches);
        } else {
            ObjWriter.write(file, patches);
        }
        System.out.println(patches.size() + " patches written to " + file);
    }
}
