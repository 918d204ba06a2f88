package org.beziertracer.spark;

import static org.beziertracer.spark.SparkJobs.assertSameFrames;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.apache.spark.SparkConf;
import org.beziertracer.intersect.Method;
import org.beziertracer.model.io.JobFiles;
import org.beziertracer.render.FrameSink;
import org.beziertracer.render.JobFrames;
import org.beziertracer.render.Pfm;
import org.beziertracer.render.PixelWindow;
import org.beziertracer.render.RenderSession;
import org.beziertracer.render.TilePixels;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Spark application on an embedded {@code local[2]} master (issue 37): 2 frames × 4 tiles assemble into
 * the one-machine render byte for byte; a task that fails once is retried; a stopped run resumes with only
 * the missing tiles; a bad job fails on the driver with the CLI's one line.
 */
class SparkRenderTest {

    @TempDir
    Path dir;

    @Test
    void twoFramesOfFourTilesOnLocalTwoAreTheOneMachineRenderByteForByte() throws Exception {
        Path job = SparkJobs.job(dir, "");
        SparkJobs.renderOnOneMachine(job, dir);
        Path out = dir.resolve("out");
        int loadsBefore = JobSource.loadCount(), assembledBefore = FrameAssembler.assembledCount();
        SparkJobs.Result r = SparkJobs.run(job.toString(), out.toUri().toString(), "--tiles", "4", "--master", "local[2]");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("tiles 8 / 8 done"), r.out());
        assertTrue(r.out().contains("8 tiles rendered, 0 already there; 2 frames assembled"), r.out());
        assertEquals(1, JobSource.loadCount() - loadsBefore, "the one executor (this JVM) loaded the job once");
        assertEquals(2, FrameAssembler.assembledCount() - assembledBefore, "the one executor (this JVM) assembled both frames");
        SparkJobs.assertExecutorsUseThisJvmsKernel(r.out());
        assertTrue(r.out().contains("executor driver: kernel "), r.out());
        assertFalse(r.out().contains("Spark UI at"), "an embedded master starts no web UI by default: " + r.out());
        assertSameFrames(dir, out, "local[2]");
        JobFrames one = JobFrames.of(JobFiles.load(job, Method::parse), 1, "spin.json");
        try (RenderSession session = new RenderSession(1, FrameSink.NONE)) {
            for (int f = 1; f <= 2; f++) {
                TilePixels whole = one.render(session, f, PixelWindow.whole(37, 27));
                assertArrayEquals(Pfm.encode(37, 27, whole.rgb()), Files.readAllBytes(out.resolve("spin-0" + f + ".pfm")),
                        "the .pfm floats of frame " + f);
            }
        }
        try (Stream<Path> tiles = Files.list(out.resolve("tiles"))) {
            List<String> names = tiles.map(p -> p.getFileName().toString()).filter(n -> !n.endsWith(".crc")).sorted()
                    .toList(); // Hadoop's local file system keeps a .NAME.crc checksum beside each file
            assertEquals(8, names.size(), "no temporary file left: " + names);
            assertEquals("spin-f000001-t0001of0004.tile", names.get(0));
        }
    }

    @Test
    void aTaskThatThrowsOnceIsRetriedAndThePathTracedFrameIsStillExact() throws Exception {
        Path job = SparkJobs.job(dir, ", \"integrator\": \"path\", \"pathDepth\": 3");
        SparkJobs.renderOnOneMachine(job, dir);
        Path flag = Files.writeString(dir.resolve("fail-once"), "x");
        System.setProperty(SparkRender.FAIL_ONCE_KEY, flag.toString());
        SparkJobs.Result r;
        try {
            r = SparkJobs.run(job.toString(), dir.resolve("out").toString(), "--tiles", "4", "--master", "local[2,2]",
                    "--ui");
        } finally {
            System.clearProperty(SparkRender.FAIL_ONCE_KEY);
        }
        assertEquals(0, r.code(), r.err());
        assertFalse(Files.exists(flag), "the injected failure happened");
        assertTrue(r.out().matches("(?s)Spark UI at http://[^\\s]+:\\d+\n.*"), "--ui starts the web UI: " + r.out());
        assertTrue(r.out().contains("a tile task failed (Spark retries it up to spark.task.maxFailures): "
                + "java.lang.IllegalStateException: injected failure (test hook) in tile TileTask["), r.out());
        assertSameFrames(dir, dir.resolve("out"), "after a retry");
    }

    @Test
    void aRunStoppedHalfWayWritesOnlyTheMissingTilesWhenStartedAgain() throws Exception {
        Path job = SparkJobs.job(dir, "");
        SparkJobs.renderOnOneMachine(job, dir);
        Path out = dir.resolve("out");
        assertEquals(0, SparkJobs.run(job.toString(), out.toString(), "--tiles", "4", "--master", "local[2]").code());
        // "stop" the run half-way: three tiles and the frames never got written
        Path tiles = out.resolve("tiles");
        List<String> missing = List.of("spin-f000001-t0002of0004.tile", "spin-f000002-t0001of0004.tile",
                "spin-f000002-t0004of0004.tile");
        for (String m : missing) {
            Files.delete(tiles.resolve(m));
        }
        for (String f : List.of("spin-01.png", "spin-01.pfm", "spin-02.png", "spin-02.pfm")) {
            Files.delete(out.resolve(f));
        }
        Map<String, FileTime> before = new HashMap<>();
        FileTime old = FileTime.fromMillis(1_000_000_000_000L);
        try (Stream<Path> s = Files.list(tiles)) {
            for (Path p : s.filter(SparkRenderTest::isTile).toList()) {
                Files.setLastModifiedTime(p, old);
                before.put(p.getFileName().toString(), old);
            }
        }
        SparkJobs.Result r = SparkJobs.run(job.toString(), out.toString(), "--tiles", "4", "--master", "local[2]");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("tiles 5 / 8 done"), "the resumed run starts at 5 of 8: " + r.out());
        assertTrue(r.out().contains("3 tiles rendered, 5 already there; 2 frames assembled"), r.out());
        try (Stream<Path> s = Files.list(tiles)) {
            int fresh = 0;
            for (Path p : s.filter(SparkRenderTest::isTile).toList()) {
                String name = p.getFileName().toString();
                if (before.containsKey(name)) {
                    assertEquals(old, Files.getLastModifiedTime(p), name + " was not written again");
                } else {
                    assertTrue(missing.contains(name), "unexpected file " + name);
                    fresh++;
                }
            }
            assertEquals(3, fresh, "exactly the missing tiles were written");
        }
        assertSameFrames(dir, out, "resumed");
    }

    @Test
    void anEmbeddedMasterStartsNoWebUiUnlessAskedForAndOtherMastersKeepSparksDefaults() {
        SparkConf local = SparkRender.configure(new SparkConf(false), "local[2]", false);
        assertEquals("false", local.get("spark.ui.enabled"));
        assertEquals("127.0.0.1", local.get("spark.driver.bindAddress"));
        assertEquals("WARN", local.get("spark.log.level"));
        assertEquals("false", SparkRender.configure(new SparkConf(false), "local-cluster[2,1,1024]", false)
                .get("spark.ui.enabled"));
        assertEquals("local[*]", SparkRender.configure(new SparkConf(false), null, false).get("spark.master"));
        assertEquals("true", SparkRender.configure(new SparkConf(false), "local[2]", true).get("spark.ui.enabled"),
                "--ui");
        assertEquals("true", SparkRender.configure(new SparkConf(false).set("spark.ui.enabled", "true"), "local[2]",
                false).get("spark.ui.enabled"), "the user's spark.ui.enabled stays");
        assertEquals("ERROR", SparkRender.configure(new SparkConf(false).set("spark.log.level", "ERROR"), null, false)
                .get("spark.log.level"), "the user's log level stays");
        SparkConf submitted = SparkRender.configure(new SparkConf(false).setMaster("spark://farm:7077"), null, false);
        assertEquals("spark://farm:7077", submitted.get("spark.master"));
        assertFalse(submitted.contains("spark.ui.enabled"), "a cluster keeps Spark's default UI");
        assertFalse(submitted.contains("spark.driver.bindAddress"));
        assertTrue(SparkRender.Arguments.parse(new String[] {"j.json", "out", "--ui"}).ui());
        assertFalse(SparkRender.Arguments.parse(new String[] {"j.json", "out"}).ui());
    }

    /** A tile file (not Hadoop's checksum beside it). */
    private static boolean isTile(Path p) {
        return p.getFileName().toString().endsWith(".tile");
    }

    @Test
    void aBadJobFailsOnTheDriverWithTheClisOneLineBeforeSparkStarts() throws IOException {
        Path job = dir.resolve("bad.json");
        Files.writeString(job, "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"integrator\": \"photon\"},"
                + " \"output\": \"f.png\"}");
        SparkJobs.Result r = SparkJobs.run(job.toString(), dir.resolve("out").toString());
        assertEquals(1, r.code());
        SparkJobs.Result cli = SparkJobs.cli("render", job.toString(), "-q");
        assertEquals(1, cli.code());
        String expected = cli.err().strip().replaceFirst("^beziertracer render: ", "");
        assertTrue(expected.startsWith(job + ": settings.integrator: unknown integrator"), expected);
        assertEquals(SparkRender.PREFIX + expected, r.err().strip(), "one line, the CLI's message");
        assertEquals("", r.out(), "no progress: Spark never started");
        assertFalse(Files.exists(dir.resolve("out")), "nothing written");
        SparkJobs.Result usage = SparkJobs.run(job.toString());
        assertEquals(2, usage.code());
        assertEquals(SparkRender.PREFIX + "expected JOB.json and OUT_URI, got 1 arguments (" + SparkRender.USAGE + ")",
                usage.err().strip());
        Files.writeString(job, "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"height\": 3}}");
        assertEquals(SparkRender.PREFIX + "--tiles must be 1..3 (the image height), got 4",
                SparkJobs.run(job.toString(), dir.toString(), "--tiles", "4").err().strip());
    }
}
