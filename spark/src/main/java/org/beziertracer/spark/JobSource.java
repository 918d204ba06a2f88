package org.beziertracer.spark;

import java.io.IOException;
import java.io.Serializable;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;

import org.beziertracer.intersect.Method;
import org.beziertracer.model.io.JobDocument;
import org.beziertracer.model.io.JobFiles;
import org.beziertracer.model.io.ModelFormatException;
import org.beziertracer.render.JobFrames;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A render job as data the driver broadcasts (issue 37): the job file's text, its name (for messages)
 * and its folder (scene files named by a relative path are read from there, so executors need the same
 * path: a shared folder, or an inline or built-in scene). Each executor JVM parses it and builds the
 * intersector once ({@link #frames}), however many tiles it renders.
 *
 * @param json     the job file's text
 * @param fileName the job file as the user named it
 * @param baseDir  the job file's absolute folder
 * @param frames   first and last frame to render (the job's, or {@code --frames})
 */
public record JobSource(String json, String fileName, String baseDir, int firstFrame, int lastFrame)
        implements Serializable {

    private static final long serialVersionUID = 1L;

    private static final Logger LOG = LoggerFactory.getLogger(JobSource.class);
    /** Each executor's jobs, by the job's text and frames; built once per JVM. */
    private static final Map<JobSource, Loaded> LOADED = new ConcurrentHashMap<>();
    private static final AtomicInteger LOAD_COUNT = new AtomicInteger();

    /**
     * Reads the job file on the driver and checks all of it (keys, scene, frames, every frame's camera)
     * before anything starts.
     *
     * @throws ModelFormatException one line naming the file and the key, as {@code render JOB.json} gives
     */
    public static JobSource read(Path file) {
        JobDocument doc = JobFiles.load(file, Method::parse);
        String json;
        try {
            json = Files.readString(file);
        } catch (IOException e) {
            throw new ModelFormatException(file.toString(), "cannot read: " + e.getMessage());
        }
        JobSource s = new JobSource(json, file.toString(), file.toAbsolutePath().getParent().toString(),
                doc.firstFrame(), doc.lastFrame());
        JobFrames.cameras(doc, doc.scene().scene(), doc.scene().settings(), file.toString());
        return s;
    }

    /** The job as read from the text (its frames narrowed to this source's). */
    public JobDocument document() {
        return JobFiles.parse(json, fileName, Path.of(baseDir), Method::parse).withFrames(firstFrame, lastFrame);
    }

    /** The same job rendering frames {@code first..last}. */
    public JobSource withFrames(int first, int last) {
        return new JobSource(json, fileName, baseDir, first, last);
    }

    /** This JVM's frames of the job, built on first use (the scene is read and the BVH built once per JVM). */
    public JobFrames frames(int threads) {
        return load(threads).frames();
    }

    /**
     * This JVM's frames of the job and the seconds their loading took, loaded on first use; the first load
     * logs (INFO, once per executor JVM) the time and the kernel the tiles render with.
     */
    Loaded load(int threads) {
        return LOADED.computeIfAbsent(this, s -> {
            LOAD_COUNT.incrementAndGet();
            long t0 = System.nanoTime();
            JobFrames frames = JobFrames.of(s.document(), threads, s.fileName());
            Loaded loaded = new Loaded(frames, (System.nanoTime() - t0) / 1e9);
            LOG.info("beziertracer: {} loaded in {} s (scene read, intersector built); kernel: {}", s.fileName(),
                    String.format(Locale.ROOT, "%.2f", loaded.seconds()), frames.kernel());
            return loaded;
        });
    }

    /** A job loaded in this JVM: its frames, and the seconds reading the scene and building the intersector took. */
    record Loaded(JobFrames frames, double seconds) {}

    /** How many times this JVM loaded a job (the tests check: once per executor). */
    public static int loadCount() { return LOAD_COUNT.get(); }

    /** Forgets the jobs loaded in this JVM (tests). */
    static void forgetLoaded() { LOADED.clear(); }
}
