package org.beziertracer.bench.report;

import java.util.List;
import java.util.Locale;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.Tessellator;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.io.Models;

/**
 * How far the uniform K×K tessellation of the teapot is from the surface: for every triangle,
 * the distance between the triangle point and {@code S(u,v)} at the interpolated parameters,
 * sampled at the centroid and the three edge midpoints; the maximum over the model. Used to pick
 * the K of "equal silhouette accuracy". Run:
 * {@code java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.TessellationError 4 8 16 32 64}
 */
public final class TessellationError {
    private TessellationError() {}

    private static final double[][] SAMPLES = {{1 / 3.0, 1 / 3.0}, {0.5, 0}, {0, 0.5}, {0.5, 0.5}};

    public static void main(String[] args) {
        List<BezierPatch> patches = Models.teapot().patches();
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        double[] s = new double[3];
        for (String arg : args) {
            int k = Integer.parseInt(arg);
            Mesh mesh = Tessellator.tessellate(patches, k);
            double max = 0;
            for (int t = 0; t < mesh.triangleCount(); t++) {
                BezierPatch p = patches.get(mesh.patchOfTriangle(t));
                double[] net = p.copyNet();
                for (double[] w : SAMPLES) {
                    double w1 = w[0], w2 = w[1], w0 = 1 - w1 - w2;
                    double[] x = new double[3];
                    double u = 0, v = 0;
                    for (int corner = 0; corner < 3; corner++) {
                        double wc = corner == 0 ? w0 : corner == 1 ? w1 : w2;
                        int vert = mesh.triangleVertex(t, corner);
                        for (int c = 0; c < 3; c++) {
                            x[c] += wc * mesh.position(vert, c);
                        }
                        u += wc * mesh.uv(vert, 0);
                        v += wc * mesh.uv(vert, 1);
                    }
                    DeCasteljau.evaluate(net, 0, p.degreeU(), p.degreeV(), 3, u, v, s, 0, scratch);
                    double d = Math.sqrt((x[0] - s[0]) * (x[0] - s[0]) + (x[1] - s[1]) * (x[1] - s[1])
                            + (x[2] - s[2]) * (x[2] - s[2]));
                    max = Math.max(max, d);
                }
            }
            System.out.printf(Locale.ROOT, "K=%d triangles=%d maxError=%.4f units%n", k, mesh.triangleCount(), max);
        }
    }
}
