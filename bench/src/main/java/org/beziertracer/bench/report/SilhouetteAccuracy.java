package org.beziertracer.bench.report;

import java.util.Locale;
import java.util.stream.IntStream;

import org.beziertracer.bench.FrameScenes;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.model.Scene;
import org.beziertracer.render.Camera;

/**
 * Screen-space silhouette error of a tessellated {@link FrameScenes} case (default the teapot)
 * against the exact one, through the renderer's own camera (the case's view, 800×600).
 *
 * <p><b>Method.</b> A coverage mask (primary ray hits the model or not) is sampled on an
 * {@code S×S} sub-pixel grid (sample spacing {@code 1/S} px, rays from
 * {@link Camera#generateRay}), exact and tessellated, with the same BVH options.
 * <ol>
 * <li>Exact coverage at every pixel centre; the <i>band</i> is every pixel within {@code R} px
 * (Chebyshev) of a pixel whose coverage differs from a 4-neighbour's.</li>
 * <li>Inside the band, both masks at {@code S×S} samples per pixel. A sample covered by one and
 * not the other lies between the two silhouettes; its <i>displacement</i> is the distance to
 * the nearest sample of opposite exact coverage (the exact silhouette runs between them),
 * i.e. how far the tessellated silhouette has moved the edge at that point (±{@code 1/S} px).</li>
 * <li>Reported: the largest displacement (the number to keep ≤ 0.5 px), the 99th percentile,
 * the mismatching area in px², and the pixel centres outside the band whose coverage differs
 * (must be 0, else the band was too narrow).</li>
 * </ol>
 * Only the outline against the background is measured (hit/miss); inner silhouettes (spout and
 * handle over the body) move by the same per-triangle chord error. Run:
 * {@code java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.SilhouetteAccuracy [-s S]
 * [--scene NAME] [--first] 8 16 24 32}; {@code --first} stops at the first K within 0.5 px
 * (list the Ks in increasing order).
 */
public final class SilhouetteAccuracy {
    private SilhouetteAccuracy() {}

    static final int W = FrameScenes.WIDTH, H = FrameScenes.HEIGHT;
    static final int R = 3;

    /** Coverage of one mode. */
    static final class Coverage {
        final SceneIntersector si;
        final Camera camera;
        final ThreadLocal<TraceContext> ctx;
        final ThreadLocal<Hit> hit = ThreadLocal.withInitial(Hit::new);
        final ThreadLocal<double[]> ray = ThreadLocal.withInitial(() -> new double[6]);

        Coverage(Scene scene, Camera camera, int tessellate) {
            this.si = SceneIntersector.build(scene, IntersectOptions.defaults().withTessellate(tessellate));
            this.camera = camera;
            this.ctx = ThreadLocal.withInitial(si::newContext);
        }

        boolean covered(double x, double y) {
            double[] r = ray.get();
            camera.generateRay(x, y, W, H, r);
            return si.closestHit(ctx.get(), r[0], r[1], r[2], r[3], r[4], r[5], 0, Double.POSITIVE_INFINITY, hit.get());
        }

        /** Coverage at every pixel centre. */
        boolean[] centres() {
            boolean[] m = new boolean[W * H];
            IntStream.range(0, H).parallel().forEach(y -> {
                for (int x = 0; x < W; x++) {
                    m[y * W + x] = covered(x + 0.5, y + 0.5);
                }
            });
            return m;
        }

        /** {@code S×S} samples of pixel {@code p}, row-major, at ((i + 0.5)/S, (j + 0.5)/S). */
        boolean[] samples(int p, int s) {
            int px = p % W, py = p / W;
            boolean[] m = new boolean[s * s];
            for (int j = 0; j < s; j++) {
                for (int i = 0; i < s; i++) {
                    m[j * s + i] = covered(px + (i + 0.5) / s, py + (j + 0.5) / s);
                }
            }
            return m;
        }
    }

    public record Result(int k, double maxPx, double p99Px, double areaPx2, int outsideBand, long triangles) {}

    public static void main(String[] args) {
        int s = 8;
        String name = "teapot";
        boolean first = false;
        java.util.List<Integer> ks = new java.util.ArrayList<>();
        for (int a = 0; a < args.length; a++) {
            switch (args[a]) {
                case "-s" -> s = Integer.parseInt(args[++a]);
                case "--scene" -> name = args[++a];
                case "--first" -> first = true;
                default -> ks.add(Integer.parseInt(args[a]));
            }
        }
        if (ks.isEmpty()) {
            ks = java.util.List.of(8, 12, 16, 24, 32, 48, 64);
        }
        Scene scene = FrameScenes.scene(name);
        Camera camera = FrameScenes.job(name, 1, 0).camera();
        long t0 = System.nanoTime();
        Coverage exact = new Coverage(scene, camera, 0);
        boolean[] centres = exact.centres();
        int[] band = band(centres);
        boolean[][] exactSamples = new boolean[W * H][];
        final int ss = s;
        IntStream.of(band).parallel().forEach(p -> exactSamples[p] = exact.samples(p, ss));
        System.out.printf(Locale.ROOT, "%s view %dx%d, %dx%d samples per band pixel, band R=%d px: %d pixels (%.1f s)%n",
                name, W, H, s, s, R, band.length, (System.nanoTime() - t0) / 1e9);
        System.out.println("K  triangles  max px  p99 px  mismatch px^2  outside band");
        for (int k : ks) {
            Result r = measure(scene, camera, k, s, centres, band, exactSamples);
            System.out.printf(Locale.ROOT, "%-3d %9d  %6.3f  %6.3f  %13.2f  %d%n", r.k(), r.triangles(), r.maxPx(),
                    r.p99Px(), r.areaPx2(), r.outsideBand());
            if (first && r.maxPx() <= 0.5 && r.outsideBand() == 0) {
                System.out.printf(Locale.ROOT, "smallest K within 0.5 px: %s %d%n", name, k);
                break;
            }
        }
    }

    static int[] band(boolean[] m) {
        boolean[] edge = new boolean[W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                boolean c = m[y * W + x];
                if ((x > 0 && m[y * W + x - 1] != c) || (x + 1 < W && m[y * W + x + 1] != c)
                        || (y > 0 && m[(y - 1) * W + x] != c) || (y + 1 < H && m[(y + 1) * W + x] != c)) {
                    edge[y * W + x] = true;
                }
            }
        }
        IntStream.Builder b = IntStream.builder();
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                boolean near = false;
                for (int dy = -R; dy <= R && !near; dy++) {
                    for (int dx = -R; dx <= R && !near; dx++) {
                        int xx = x + dx, yy = y + dy;
                        near = xx >= 0 && yy >= 0 && xx < W && yy < H && edge[yy * W + xx];
                    }
                }
                if (near) {
                    b.add(y * W + x);
                }
            }
        }
        return b.build().toArray();
    }

    static Result measure(Scene scene, Camera camera, int k, int s, boolean[] exactCentres, int[] band,
                          boolean[][] exactSamples) {
        Coverage tess = new Coverage(scene, camera, k);
        boolean[] tc = tess.centres();
        boolean[] inBand = new boolean[W * H];
        for (int p : band) {
            inBand[p] = true;
        }
        int outside = 0;
        for (int p = 0; p < W * H; p++) {
            if (!inBand[p] && tc[p] != exactCentres[p]) {
                outside++;
            }
        }
        java.util.List<Double> displacements = java.util.Collections.synchronizedList(new java.util.ArrayList<>());
        IntStream.of(band).parallel().forEach(p -> {
            boolean[] t = tess.samples(p, s);
            boolean[] e = exactSamples[p];
            for (int q = 0; q < s * s; q++) {
                if (t[q] != e[q]) {
                    displacements.add(distanceToOpposite(p, q % s, q / s, e[q], s, exactSamples));
                }
            }
        });
        double[] d = displacements.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        double max = d.length == 0 ? 0 : d[d.length - 1];
        double p99 = d.length == 0 ? 0 : d[(int) Math.min(d.length - 1, Math.floor(0.99 * d.length))];
        return new Result(k, max, p99, d.length / (double) (s * s), outside, tess.si.triangleCount());
    }

    /** Distance in px from sample (i, j) of pixel p to the nearest band sample whose exact coverage is not {@code c}. */
    static double distanceToOpposite(int p, int i, int j, boolean c, int s, boolean[][] exactSamples) {
        int px = p % W, py = p / W;
        double x0 = px + (i + 0.5) / s, y0 = py + (j + 0.5) / s;
        double best = Double.POSITIVE_INFINITY;
        for (int dy = -R; dy <= R; dy++) {
            for (int dx = -R; dx <= R; dx++) {
                int xx = px + dx, yy = py + dy;
                if (xx < 0 || yy < 0 || xx >= W || yy >= H) {
                    continue;
                }
                boolean[] e = exactSamples[yy * W + xx];
                if (e == null) {
                    continue;
                }
                for (int jj = 0; jj < s; jj++) {
                    for (int ii = 0; ii < s; ii++) {
                        if (e[jj * s + ii] != c) {
                            double x = xx + (ii + 0.5) / s - x0, y = yy + (jj + 0.5) / s - y0;
                            best = Math.min(best, x * x + y * y);
                        }
                    }
                }
            }
        }
        return Math.sqrt(best);
    }
}
