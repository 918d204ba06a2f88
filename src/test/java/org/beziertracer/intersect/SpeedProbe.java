package org.beziertracer.intersect;
import org.beziertracer.model.*;
import org.beziertracer.geometry.*;
import org.beziertracer.model.io.Models;
public class SpeedProbe {
  public static void main(String[] a) {
    NewtonSolver.LOOSE = Double.parseDouble(System.getProperty("loose", "1e5"));
    NewtonSolver.OVERLAP = Double.parseDouble(System.getProperty("overlap", "1"));
    NewtonSolver.WANDER = Double.parseDouble(System.getProperty("wander", "1"));
    NewtonSolver.MAX_STEPS = Integer.getInteger("steps", 10);
    NewtonRefinement.TILT_DEG = Double.parseDouble(System.getProperty("tilt", "60"));
    NewtonSolver.TOL_SCALE = Double.parseDouble(System.getProperty("tolscale", "1"));
    Scene scene = Models.load("teapot");
    double[] rays = AccuracyProbe.teapotRays(scene.controlBounds(), 20000, 1);
    String[] configs = a;
    SceneIntersector[] sis = new SceneIntersector[configs.length];
    for (int c = 0; c < configs.length; c++) {
      String[] f = configs[c].split(":");
      Method m = Method.parse(f[0]);
      SplitOptions so = f.length > 1 ? new SplitOptions(true, Double.parseDouble(f[1]), Integer.parseInt(f[2]), f[3].equals("p") ? new NewtonRefinement() : org.beziertracer.geometry.LeafCriterion.NONE) : SplitOptions.defaults();
      sis[c] = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(m).withSplit(so));
    }
    double[][] best = new double[configs.length][1];
    for (double[] b : best) b[0] = Double.POSITIVE_INFINITY;
    Hit hit = new Hit();
    for (int round = 0; round < 12; round++) {
      for (int c = 0; c < configs.length; c++) {
        String[] f = configs[c].split(":");
        NewtonSolver.LEGACY = f.length > 4 && f[4].equals("legacy");
        NewtonSolver.STARTS = f.length > 5 ? Integer.parseInt(f[5]) : 6;
        TraceContext ctx = sis[c].newContext(); NewtonSolver.NON_UNIQUE = 0; NewtonSolver.EVALS = 0;
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean(); long t0 = mx.getCurrentThreadCpuTime(); int hits = 0;
        for (int k = 0; k < 20000; k++) { int o = 6*k; if (sis[c].closestHit(ctx, rays[o],rays[o+1],rays[o+2],rays[o+3],rays[o+4],rays[o+5],0,Double.POSITIVE_INFINITY,hit)) hits++; }
        double ns = (mx.getCurrentThreadCpuTime() - t0) / 20000.0;
        best[c][0] = Math.min(best[c][0], ns);
        if (round == 11) System.out.printf("%-40s %8.0f ns/ray (best of 12)  hits %d leaves %d solverCalls/ray %.2f evals/ray %.2f nonunique/ray %.2f%n", configs[c], best[c][0], hits, sis[c].subPatchCount(), ctx.solverCalls / 20000.0, NewtonSolver.EVALS/20000.0, NewtonSolver.NON_UNIQUE/20000.0);
      }
    }
  }
}
