package org.beziertracer.model.io;

import java.nio.file.Path;

import org.beziertracer.model.CameraPath;

/**
 * A render job read from a job file (issue 37, {@code docs/jobs.md}): the scene with its render
 * settings (the job's {@code settings} already applied), the sampler seed, the camera's path (null: the
 * scene's camera in every frame), the frames to render and the output pattern. Immutable; every value
 * was checked when read, so any machine can run it and gets the same pixels.
 *
 * @param scene      the scene and the settings to render it with
 * @param tracer     the integrator and the path tracer's settings ({@link JobTracer#NONE}: {@code render}'s)
 * @param seed       seed of the jittered and adaptive samplers
 * @param camera     the camera of each frame; null: the scene's (or the fitted default) in every frame
 * @param firstFrame first frame to render
 * @param lastFrame  last frame to render, {@code >= firstFrame}
 * @param output     PNG path pattern, resolved against the job file's folder; a run of {@code #} stands for
 *                   the frame number padded with zeros to the run's length; null when the file names none
 */
public record JobDocument(SceneDocument scene, JobTracer tracer, long seed, CameraPath camera, int firstFrame, int lastFrame,
                          Path output) {

    public JobDocument {
        if (scene == null) {
            throw new IllegalArgumentException("a job needs a scene");
        }
        if (tracer == null) {
            throw new IllegalArgumentException("a job needs its tracer settings (JobTracer.NONE for none)");
        }
        if (lastFrame < firstFrame) {
            throw new IllegalArgumentException("the last frame " + lastFrame + " is before the first " + firstFrame);
        }
    }

    /** The same job rendering frames {@code first..last} only. */
    public JobDocument withFrames(int first, int last) {
        return new JobDocument(scene, tracer, seed, camera, first, last, output);
    }

    /** The same job writing to {@code pattern}. */
    public JobDocument withOutput(Path pattern) {
        return new JobDocument(scene, tracer, seed, camera, firstFrame, lastFrame, pattern);
    }

    /** The same job with the integrator settings {@code t}. */
    public JobDocument withTracer(JobTracer t) {
        return new JobDocument(scene, t, seed, camera, firstFrame, lastFrame, output);
    }

    /** The same job with the sampler seed {@code s}. */
    public JobDocument withSeed(long s) {
        return new JobDocument(scene, tracer, s, camera, firstFrame, lastFrame, output);
    }

    /** The file of {@code frame}: each run of {@code #} in the file name replaced by the zero-padded number. */
    public Path outputOf(int frame) {
        return FramePattern.fileOf(output, frame);
    }
}
