package org.beziertracer.spark;

import java.io.IOException;
import java.io.PrintStream;
import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;
import org.beziertracer.model.io.FramePattern;
import org.beziertracer.model.io.JobDocument;
import org.beziertracer.render.Failures;

/**
 * The Spark application of a render job (issue 37, {@code docs/spark.md}):
 * {@code JOB.json OUT_URI [--tiles N] [--frames A-B] [--master URL]}. The driver reads and checks the
 * whole job first (the one-line errors of {@code render JOB.json}, exit code 1, before Spark starts),
 * splits it into (frame, tile) tasks, skips the tiles already in {@code OUT_URI/tiles/} (resume),
 * broadcasts the job so each executor loads the scene once, renders the rest ({@link RenderTile}), prints
 * {@code tiles done / total} with an ETA ({@link TileProgress}) and one line per executor (its kernel), then
 * assembles the frames in parallel, one Spark task each, into each frame's PNG and
 * {@code .pfm} ({@link FrameAssembler}). Without a master (no {@code --master}, no {@code spark.master}
 * from {@code spark-submit}) it runs on an embedded {@code local[*]} master, without Spark's web UI unless
 * {@code --ui} ({@link #configure}).
 */
public final class SparkRender {
    private SparkRender() {}

    static final String PREFIX = "beziertracer spark: ";
    static final String USAGE = "usage: JOB.json OUT_URI [--tiles N] [--frames A-B] [--master URL] [--ui]";
    /** Test hook: a file whose deletion makes one tile task fail once ({@link RenderTile}). */
    static final String FAIL_ONCE_KEY = "spark.beziertracer.failOnceFile";
    /** Tiles per frame unless {@code --tiles}: at most this, at most the image height. */
    static final int DEFAULT_TILES = 16;

    public static void main(String[] args) {
        int code = run(args, System.out, System.err);
        if (code != 0) {
            System.exit(code);
        }
    }

    /** Runs the application; returns the exit code (0, 1 for a bad job or a failed run, 2 for bad usage). */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        if (args.length == 1 && (args[0].equals("--help") || args[0].equals("-h"))) {
            out.println(USAGE + "\nRenders a job file as (frame, tile) Spark tasks into OUT_URI (docs/spark.md).");
            return 0;
        }
        Arguments a;
        try {
            a = Arguments.parse(args);
        } catch (IllegalArgumentException e) {
            err.println(PREFIX + e.getMessage() + " (" + USAGE + ")");
            return 2;
        }
        JobSource source;
        JobDocument doc;
        OutputFolder folder;
        int tiles;
        try {
            source = JobSource.read(Path.of(a.job()));
            if (a.frames() != null) {
                int[] ab = FramePattern.range(a.frames(), "--frames");
                if (ab[0] < source.firstFrame() || ab[1] > source.lastFrame()) {
                    throw new IllegalArgumentException("--frames " + ab[0] + "-" + ab[1] + ": the job has frames "
                            + source.firstFrame() + "-" + source.lastFrame());
                }
                source = source.withFrames(ab[0], ab[1]);
            }
            doc = source.document();
            int h = doc.scene().settings().height();
            tiles = a.tiles() != null ? a.tiles() : Math.min(DEFAULT_TILES, h);
            if (tiles < 1 || tiles > h) {
                throw new IllegalArgumentException("--tiles must be 1.." + h + " (the image height), got " + tiles);
            }
            folder = new OutputFolder(a.output());
        } catch (RuntimeException | IOException e) {
            err.println(PREFIX + Failures.describe(e));
            return 1;
        }
        SparkConf conf = configure(new SparkConf().setAppName("beziertracer " + jobName(a.job())), a.master(), a.ui());
        try (JavaSparkContext sc = new JavaSparkContext(conf)) {
            if (sc.sc().uiWebUrl().isDefined()) {
                out.println("Spark UI at " + sc.sc().uiWebUrl().get());
            }
            return render(sc, source, doc, folder, a.output(), jobName(a.job()), tiles, out);
        } catch (Exception e) { // Spark's SparkException (a failed stage) is checked but thrown undeclared
            err.println(PREFIX + failure(e));
            return 1;
        }
    }

    /**
     * The Spark configuration of a run: {@code --master} (else {@code spark.master} as {@code spark-submit} or a
     * system property set it, else {@code local[*]}). An embedded master ({@code local…}, {@code local-cluster…})
     * needs no network, so the driver listens on the loopback address only, logs warnings only and starts no
     * web UI (about 2 CPU-s of start-up, docs/spark.md) unless {@code --ui} or {@code spark.ui.enabled} asks for
     * it; each of these stays as the user set it. Any other master keeps Spark's defaults (the UI on).
     */
    static SparkConf configure(SparkConf conf, String master, boolean ui) {
        if (master != null) {
            conf.setMaster(master);
        } else if (!conf.contains("spark.master")) {
            conf.setMaster("local[*]");
        }
        if (ui) {
            conf.set("spark.ui.enabled", "true");
        }
        if (conf.get("spark.master").startsWith("local")) {
            conf.setIfMissing("spark.driver.host", "127.0.0.1").setIfMissing("spark.driver.bindAddress", "127.0.0.1")
                    .setIfMissing("spark.log.level", "WARN").setIfMissing("spark.ui.enabled", "false");
        }
        return conf;
    }

    /** One line for a failed run: our own messages as the CLI gives them, Spark's first line otherwise. */
    static String failure(Exception e) {
        if (e instanceof IllegalArgumentException || e instanceof IOException || e.getMessage() == null) {
            return Failures.describe(e);
        }
        String first = e.getMessage().lines().findFirst().orElse("").strip();
        return "the Spark job failed (see the executors' logs): "
                + (first.length() > 300 ? first.substring(0, 300) + "…" : first);
    }

    private static int render(JavaSparkContext sc, JobSource source, JobDocument doc, OutputFolder folder,
                              String output, String job, int tiles, PrintStream out) throws IOException {
        List<TileTask> todo = new ArrayList<>();
        int total = 0;
        for (int f = doc.firstFrame(); f <= doc.lastFrame(); f++) {
            for (int i = 1; i <= tiles; i++) {
                TileTask t = new TileTask(f, i, tiles);
                total++;
                if (!folder.exists(folder.tile(t.fileName(job)))) {
                    todo.add(t);
                }
            }
        }
        TileProgress progress = new TileProgress(out, total, total - todo.size());
        sc.sc().addSparkListener(progress);
        int rendered = 0;
        if (!todo.isEmpty()) {
            Broadcast<JobSource> broadcast = sc.broadcast(source);
            int threads = sc.getConf().getInt("spark.task.cpus", 1);
            RenderTile task = new RenderTile(broadcast, job, output, threads, sc.getConf().get(FAIL_ONCE_KEY, null));
            sc.setJobDescription(TileProgress.TILES);
            List<TileDone> done = sc.parallelize(todo, todo.size()).map(task).collect();
            rendered = (int) done.stream().filter(TileDone::rendered).count();
            printExecutors(done, out);
        }
        progress.finish(todo.size());
        // the frames, one task each, assembled in parallel on the executors now that every tile is written
        String pattern = doc.output() != null ? doc.output().getFileName().toString() : FrameAssembler.defaultPattern(job);
        FrameAssembler assembler = new FrameAssembler(output, job, pattern, doc.scene().settings().width(),
                doc.scene().settings().height(), tiles);
        List<Integer> missing = new ArrayList<>();
        for (int f = doc.firstFrame(); f <= doc.lastFrame(); f++) {
            if (!assembler.written(folder, f)) {
                missing.add(f);
            }
        }
        int frames = 0;
        if (!missing.isEmpty()) {
            sc.setJobDescription("beziertracer frames");
            frames = sc.parallelize(missing, missing.size()).map(assembler).reduce(Integer::sum);
        }
        out.printf(Locale.ROOT, "%d tiles rendered, %d already there; %d frames assembled in %s (%.2f tiles/s)%n",
                rendered, total - todo.size(), frames, output, progress.tilesPerSecond());
        out.flush();
        return 0;
    }

    /** One line per executor that rendered tiles: its kernel and the seconds it took to load the job. */
    private static void printExecutors(List<TileDone> done, PrintStream out) {
        Map<String, TileDone> first = new TreeMap<>();
        for (TileDone d : done) {
            if (d.rendered()) {
                first.putIfAbsent(d.executor(), d);
            }
        }
        for (TileDone d : first.values()) {
            out.printf(Locale.ROOT, "executor %s: kernel %s; job loaded in %.2f s%n", d.executor(), d.kernel(),
                    d.loadSeconds());
        }
    }

    /** The job's name in tile names: the job file's name without {@code .json}. */
    static String jobName(String jobFile) {
        String name = Path.of(jobFile).getFileName().toString();
        return name.toLowerCase(Locale.ROOT).endsWith(".json") ? name.substring(0, name.length() - 5) : name;
    }

    /** The command line. */
    record Arguments(String job, String output, Integer tiles, String frames, String master, boolean ui) {
        static Arguments parse(String[] args) {
            List<String> positional = new ArrayList<>();
            Integer tiles = null;
            String frames = null, master = null;
            boolean ui = false;
            for (int k = 0; k < args.length; k++) {
                String arg = args[k];
                if (arg.equals("--ui")) {
                    ui = true;
                } else if (arg.equals("--tiles") || arg.equals("--frames") || arg.equals("--master")) {
                    if (k + 1 >= args.length) {
                        throw new IllegalArgumentException(arg + " needs a value");
                    }
                    String v = args[++k];
                    switch (arg) {
                        case "--tiles" -> {
                            try {
                                tiles = Integer.parseInt(v.trim());
                            } catch (NumberFormatException e) {
                                throw new IllegalArgumentException("--tiles: expected a whole number, found \"" + v + "\"");
                            }
                        }
                        case "--frames" -> frames = v;
                        default -> master = v;
                    }
                } else if (arg.startsWith("--")) {
                    throw new IllegalArgumentException("unknown option " + arg);
                } else {
                    positional.add(arg);
                }
            }
            if (positional.size() != 2) {
                throw new IllegalArgumentException("expected JOB.json and OUT_URI, got " + positional.size()
                        + " arguments");
            }
            return new Arguments(positional.get(0), outputUri(positional.get(1)), tiles, frames, master, ui);
        }

        /** A URI with a scheme as it is; a plain path as a {@code file:} URI of its absolute form. */
        private static String outputUri(String text) {
            try {
                URI u = URI.create(text);
                if (u.getScheme() != null && u.getScheme().length() > 1) {
                    return text;
                }
            } catch (IllegalArgumentException e) {
                // not a URI: a local path
            }
            return Path.of(text).toAbsolutePath().toUri().toString();
        }
    }
}
