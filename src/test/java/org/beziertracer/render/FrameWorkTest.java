package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.GeneratedModels;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;
import org.junit.jupiter.api.Test;

/**
 * The work of fixed frames, pinned to the unit (issue 32, "the work is pinned"): four small
 * reference views (those of {@code bench/FrameScenes} at 160×120: the curved bicubic arch that
 * shadows its own inside, the teapot, the wavy degree-9 grid lit from the side so it casts
 * shadows, the default patch lit from the eye), rendered on one thread, each with its exact counts
 * of rays, leaf-solver calls, clip steps, evaluations, lane evaluations and one count per
 * work-only shortcut ({@link org.beziertracer.intersect.TraceContext#shortcutCounts}). The
 * shortcuts never change a picture, only the work: switching any of them off changes one of these
 * counts (docs/testing.md, "Pinned frame work (issue 32)", lists the mutants tried). The counts
 * repeat exactly on every machine (one thread, no fused multiply-add anywhere).
 *
 * <p><b>Updating the pins.</b> They change only when the intersector's work changes on purpose:
 * run this test, check that the moved counts are the ones the change meant to move, paste the
 * printed table over {@link #EXPECTED}, and say in the commit message why the work moved.
 */
class FrameWorkTest {

    private static final int W = 160, H = 120;

    /** The pinned work of each frame (paste the failure message's table here when it moves on purpose). */
    private static final Map<String, String> EXPECTED = Map.of(
            "curved", "primaryRays=19200 shadowRays=5214 secondaryRays=0 solverCalls=23235 "
                    + "clipSteps=1396 evaluations=23420 laneEvaluations=20239 recordMisses=9336 "
                    + "slabMisses=930 windingMisses=869 quadraticStarts=0 besideFirst=0 "
                    + "singleRootLeaves=7784 quarterLeaves=0 quarterWindings=0 extrapolations=2450 "
                    + "laneExtrapolations=4246 originBehind=4099 originQuarters=0 originCannotMeet=0 "
                    + "originStarts=3 nearOriginStarts=165 anyRootsByNewton=320 originEvaluations=3 "
                    + "hitEvaluations=5795",
            "teapot", "primaryRays=19200 shadowRays=3983 secondaryRays=0 solverCalls=14980 "
                    + "clipSteps=569 evaluations=14099 laneEvaluations=12601 recordMisses=5277 "
                    + "slabMisses=884 windingMisses=504 quadraticStarts=0 besideFirst=0 "
                    + "singleRootLeaves=5145 quarterLeaves=0 quarterWindings=0 extrapolations=2515 "
                    + "laneExtrapolations=1195 originBehind=3715 originQuarters=0 originCannotMeet=206 "
                    + "originStarts=5 nearOriginStarts=70 anyRootsByNewton=11 originEvaluations=5 "
                    + "hitEvaluations=4080",
            "wavy10", "primaryRays=19200 shadowRays=4103 secondaryRays=0 solverCalls=12406 clipSteps=72 "
                    + "evaluations=9347 laneEvaluations=8394 recordMisses=3366 slabMisses=421 "
                    + "windingMisses=334 quadraticStarts=3853 besideFirst=635 singleRootLeaves=4507 "
                    + "quarterLeaves=478 quarterWindings=120 extrapolations=1098 "
                    + "laneExtrapolations=2693 originBehind=3903 originQuarters=199 originCannotMeet=0 "
                    + "originStarts=1 nearOriginStarts=0 anyRootsByNewton=0 originEvaluations=1 "
                    + "hitEvaluations=4090",
            "patch", "primaryRays=19200 shadowRays=0 secondaryRays=0 solverCalls=7211 clipSteps=0 "
                    + "evaluations=7211 laneEvaluations=6968 recordMisses=0 slabMisses=0 "
                    + "windingMisses=0 quadraticStarts=0 besideFirst=0 singleRootLeaves=7211 "
                    + "quarterLeaves=0 quarterWindings=0 extrapolations=243 laneExtrapolations=6968 "
                    + "originBehind=0 originQuarters=0 originCannotMeet=0 originStarts=0 "
                    + "nearOriginStarts=0 anyRootsByNewton=0 originEvaluations=0 hitEvaluations=7211");

    @Test
    void theCurvedArchShadowingItsOwnInsideDoesItsPinnedWork() {
        pinned("curved", frame("curved", null, new Vec3(-2, -4, 5),
                Camera.lookAt(new Vec3(-4.5, -5, 2.5), new Vec3(0, 0, 0.6), new Vec3(0, 0, 1), 40)));
    }

    @Test
    void theTeapotDoesItsPinnedWork() {
        pinned("teapot", frame("teapot", null, new Vec3(-200, -350, 450),
                Camera.lookAt(new Vec3(-150, -420, 260), new Vec3(10, 0, 55), new Vec3(0, 0, 1), 40)));
    }

    @Test
    void theWavyDegreeNineGridCastingShadowsDoesItsPinnedWork() {
        SceneDocument wavy = new SceneDocument(GeneratedModels.wavy(10), RenderSettings.defaults());
        pinned("wavy10", frame("wavy10", wavy, new Vec3(-3, -4, 6), null));
    }

    @Test
    void theDefaultPatchLitFromTheEyeDoesItsPinnedWork() {
        pinned("patch", frame("patch", null, null, null));
    }

    /**
     * Every shortcut does some work in these frames (a shortcut none of them uses would be pinned
     * at zero, and switching it off would leave every count where it is).
     */
    @Test
    void everyShortcutSavesWorkInOneOfTheFrames() {
        Map<String, Long> total = new LinkedHashMap<>();
        for (String name : List.of("curved", "teapot", "wavy10", "patch")) {
            parse(EXPECTED.get(name)).forEach((k, v) -> total.merge(k, v, Long::sum));
        }
        total.remove("secondaryRays"); // (no mirror or glass in these frames)
        total.forEach((k, v) -> assertTrue(v > 0, k + " is zero in every pinned frame: " + total));
    }

    /**
     * Renders the frame on one thread as the renderer does (its tiles, passes and packets, by a
     * {@link RenderWorker}), and checks that {@link Renderer#renderOnce} does the same work.
     */
    private static Map<String, Long> frame(String model, SceneDocument document, Vec3 light, Camera camera) {
        SceneDocument doc = document != null ? document : SceneFiles.load(model);
        Scene scene = doc.scene();
        if (light != null) {
            scene = scene.toBuilder().lights(List.of(new PointLight(light))).build();
        }
        RenderSettings s = doc.settings();
        RenderSettings settings = new RenderSettings(W, H, 1, s.sampler(), s.method(), s.bvh(), "phong", s.checker(),
                true, s.maxDepth());
        RenderJob job = RenderJob.prepare(scene, settings,
                RenderOptions.defaults().withThreads(1).withProgressive(false));
        if (camera != null) {
            job = job.withCamera(camera);
        }
        List<int[]> tiles = RenderSession.tiles(W, H, job.options().tileSize());
        List<PassPlan.Pass> passes = PassPlan.of(false, job.sampler(), 1);
        RenderState st = new RenderState(0, job, FrameSink.NONE, new AtomicInteger(0),
                new ProgressCounter(RenderProgress.NONE, 0, passes, tiles));
        RenderWorker worker = new RenderWorker(job.intersector());
        for (PassPlan.Pass pass : passes) {
            for (int[] t : tiles) {
                assertTrue(worker.renderTile(st, pass, t[0], t[1], t[2], t[3], false));
            }
        }
        FrameStats stats = st.stats();
        FrameStats rendered = Renderer.renderOnce(job).stats();
        assertEquals(rendered.work(), stats.work(), model + ": the renderer's own frame does the same work");
        assertEquals(rendered.shadowRays(), stats.shadowRays(), model + ": the renderer's own frame's shadow rays");
        Map<String, Long> work = new LinkedHashMap<>();
        work.put("primaryRays", stats.primaryRays());
        work.put("shadowRays", stats.shadowRays());
        work.put("secondaryRays", stats.secondaryRays());
        work.put("solverCalls", stats.work().solverCalls());
        work.put("clipSteps", stats.work().clipSteps());
        work.put("evaluations", stats.work().evaluations());
        work.put("laneEvaluations", stats.work().laneEvaluations());
        work.putAll(worker.context().shortcutCounts());
        return work;
    }

    private static void pinned(String name, Map<String, Long> actual) {
        Map<String, Long> expected = parse(EXPECTED.get(name));
        StringBuilder moved = new StringBuilder();
        for (Map.Entry<String, Long> e : actual.entrySet()) {
            Long want = expected.get(e.getKey());
            if (!e.getValue().equals(want)) {
                moved.append("\n  ").append(e.getKey()).append(": pinned ").append(want).append(", now ")
                        .append(e.getValue());
            }
        }
        for (String key : expected.keySet()) {
            if (!actual.containsKey(key)) {
                moved.append("\n  ").append(key).append(": pinned but no longer counted");
            }
        }
        if (moved.length() > 0) {
            fail(name + " (" + W + "×" + H + ", one thread): the frame's work moved:" + moved
                    + "\nIf on purpose, pin it anew (EXPECTED, \"" + name + "\"):\n    \"" + table(actual) + "\"");
        }
    }

    /** {@code key=value} pairs separated by spaces, the form of {@link #EXPECTED}. */
    private static String table(Map<String, Long> work) {
        StringBuilder b = new StringBuilder();
        work.forEach((k, v) -> b.append(b.length() == 0 ? "" : " ").append(k).append('=').append(v));
        return b.toString();
    }

    private static Map<String, Long> parse(String table) {
        Map<String, Long> out = new LinkedHashMap<>();
        for (String pair : table.trim().split("\\s+")) {
            if (!pair.isEmpty()) {
                int eq = pair.indexOf('=');
                out.put(pair.substring(0, eq), Long.parseLong(pair.substring(eq + 1)));
            }
        }
        return out;
    }
}
