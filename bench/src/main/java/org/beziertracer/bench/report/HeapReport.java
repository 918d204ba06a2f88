package org.beziertracer.bench.report;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.util.List;
import java.util.Locale;

import org.beziertracer.bench.BigModels;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneFiles;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderOptions;
import org.beziertracer.render.RenderResult;
import org.beziertracer.render.Renderer;

/**
 * Retained heap of a big model and of its acceleration data, measured as the JVM sees it (used
 * heap after full collections, before and after), next to what the structures report
 * ({@code leafBytes + accelBytes}, the figure {@code info} prints), plus the build time and the
 * time of one 800×600 frame (1 spp, Phong, shadows, 2 threads; the intersector built again for it)
 * and the heap after that frame. A report, not a benchmark: timings are single wall-clock runs.
 *
 * <pre>java -Xmx4g -cp bench/target/benchmarks.jar org.beziertracer.bench.report.HeapReport body 100000 [render]
 * java -Xmx4g -cp bench/target/benchmarks.jar org.beziertracer.bench.report.HeapReport FILE.obj [render]</pre>
 */
public final class HeapReport {
    private HeapReport() {}

    public static void main(String[] args) throws Exception {
        if (args.length < 1) {
            System.err.println("usage: HeapReport body|soup COUNT [render] | HeapReport FILE [render]");
            System.exit(2);
        }
        boolean generated = args[0].equals("body") || args[0].equals("soup");
        boolean render = args[args.length - 1].equals("render");
        long before = settledHeap();
        List<BezierPatch> patches = generated ? BigModels.of(args[0], Integer.parseInt(args[1]), 1)
                : SceneFiles.load(args[0]).scene().patches();
        Scene scene = Scene.builder().patches(patches).build();
        int n = scene.patchCount();
        long model = settledHeap() - before;
        SceneIntersector si = SceneIntersector.build(scene, org.beziertracer.intersect.IntersectOptions.defaults());
        long accel = settledHeap() - before - model;
        long reported = si.leafBytes() + si.accelBytes();
        System.out.printf(Locale.ROOT, "model: %s, %,d patches, %,d sub-patches, %,d BVH nodes%n", args[0], n,
                si.subPatchCount(), si.nodeCount());
        System.out.printf(Locale.ROOT, "build (split + BVH): %.0f ms%n", si.buildMillis());
        System.out.printf(Locale.ROOT, "retained heap: model %,d B (%,d a patch), acceleration data %,d B (%,d a patch),"
                + " together %,d a patch%n", model, model / n, accel, accel / n, (model + accel) / n);
        System.out.printf(Locale.ROOT, "reported by the structures (info): %,d B (%,d a patch)%n", reported, reported / n);
        if (render) {
            si = null;
            Aabb box = scene.controlBounds();
            Vec3 c = box.center();
            Scene lit = scene.toBuilder().lights(List.of(new PointLight(
                    new Vec3(c.x() - box.diagonal(), c.y() - box.diagonal(), c.z() + box.diagonal())))).build();
            RenderSettings settings = RenderSettings.defaults();
            var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
            long t0 = System.nanoTime(), c0 = os.getProcessCpuTime();
            RenderJob job = RenderJob.prepare(lit, settings, RenderOptions.defaults().withThreads(2).withProgressive(false));
            long t1 = System.nanoTime(), c1 = os.getProcessCpuTime();
            RenderResult r = Renderer.renderOnce(job);
            long t2 = System.nanoTime(), c2 = os.getProcessCpuTime();
            System.out.printf(Locale.ROOT, "first frame 800x600: build %.0f ms + frame %.0f ms = %.0f ms (%,d rays);"
                    + " CPU time build %.0f ms, frame %.0f ms%n", (t1 - t0) / 1e6, (t2 - t1) / 1e6, (t2 - t0) / 1e6,
                    r.stats().totalRays(), (c1 - c0) / 1e6, (c2 - c1) / 1e6);
            long after = settledHeap() - before - model;
            System.out.printf(Locale.ROOT, "retained after the frame: acceleration data %,d B (%,d a patch)%n", after, after / n);
            if (job.width() < 0) {
                System.out.println(job); // keeps the job reachable until here
            }
        }
        if (si != null && si.subPatchCount() < 0) {
            System.out.println(si); // keeps the intersector reachable until the measurement
        }
    }

    /** Used heap after the collector has settled (several full collections). */
    static long settledHeap() throws InterruptedException {
        MemoryMXBean bean = ManagementFactory.getMemoryMXBean();
        long used = Long.MAX_VALUE;
        for (int i = 0; i < 5; i++) {
            System.gc();
            Thread.sleep(50);
            used = Math.min(used, bean.getHeapMemoryUsage().getUsed());
        }
        return used;
    }
}
