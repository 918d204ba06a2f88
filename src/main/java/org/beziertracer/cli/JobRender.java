package org.beziertracer.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import org.beziertracer.intersect.HeapBudget;
import org.beziertracer.intersect.Method;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.AtomicFiles;
import org.beziertracer.model.io.FramePattern;
import org.beziertracer.model.io.JobDocument;
import org.beziertracer.model.io.JobFiles;
import org.beziertracer.render.FrameSink;
import org.beziertracer.render.JobFrames;
import org.beziertracer.render.TilePixels;
import org.beziertracer.render.PixelWindow;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderOptions;
import org.beziertracer.render.RenderProgress;
import org.beziertracer.render.RenderSession;

/**
 * {@code render JOB.json} (issue 37): reads the job file, checks everything (frames, pieces, output,
 * every frame's camera) before the first ray, builds the intersector once and renders each frame of
 * the job (or of {@code --frames}), each to its numbered PNG and the linear {@code .pfm} beside it
 * ({@link FramePattern#pfmName}), each atomically and byte for byte the files the Spark module assembles
 * ({@code render.Png}, {@code render.Pfm}). {@code --crop}/{@code --tile} render the same piece of every frame. Settings options ({@code --size}, {@code --spp}, …) override the
 * job's; camera options, {@code --pixel}, {@code --difference-to}, {@code --repeat} and {@code --stats}
 * do not go with a job.
 */
final class JobRender {
    private final RenderCommand cmd;

    JobRender(RenderCommand cmd) {
        this.cmd = cmd;
    }

    int run() throws IOException, InterruptedException {
        checkOptions();
        Path file = Path.of(cmd.model);
        JobDocument doc = JobFiles.load(file, Method::parse);
        ReadNotes.show(doc.scene(), cmd.spec.commandLine().getErr());
        if (cmd.pieceOptions.frames != null) {
            int[] ab = FramePattern.range(cmd.pieceOptions.frames, "--frames");
            if (ab[0] < doc.firstFrame() || ab[1] > doc.lastFrame()) {
                throw new IllegalArgumentException("--frames " + ab[0] + "-" + ab[1] + ": the job has frames "
                        + doc.firstFrame() + "-" + doc.lastFrame());
            }
            doc = doc.withFrames(ab[0], ab[1]);
        }
        if (cmd.output != null) {
            doc = doc.withOutput(cmd.output);
        }
        if (doc.output() == null) {
            throw new IllegalArgumentException(file + ": no \"output\" in the job file and no -o OUT.png");
        }
        if (doc.lastFrame() > doc.firstFrame() && !FramePattern.numbered(doc.output())) {
            throw new IllegalArgumentException(doc.output() + ": several frames need a # in the file name for the "
                    + "frame number (e.g. frame-####.png)");
        }
        if (cmd.seed != null) {
            doc = doc.withSeed(cmd.seed);
        }
        cmd.jobTracer = doc.tracer();
        doc = doc.withTracer(cmd.tracer());
        RenderSettings settings = cmd.settings(doc.scene().settings());
        RenderCommand.checkMemory(settings);
        PixelWindow window = cmd.pieceOptions.window(settings.width(), settings.height());
        Scene scene = cmd.withLights(doc.scene().scene());
        int threadCount = cmd.threadCount();
        RenderOptions options = cmd.options(threadCount).withSeed(doc.seed());
        JobFrames.cameras(doc, scene, settings, file.toString());
        HeapBudget.require(cmd.model, scene, RenderJob.intersectOptions(settings, options));
        JobFrames frames = new JobFrames(doc, scene, settings, options, file.toString());
        try (ProgressBarDisplay bar = cmd.progressBar(frames.frameCount());
             RenderSession session = new RenderSession(threadCount, FrameSink.NONE,
                     bar == null ? RenderProgress.NONE : bar)) {
            for (int f = doc.firstFrame(); f <= doc.lastFrame(); f++) {
                TilePixels piece = frames.render(session, f, window);
                Path out = doc.outputOf(f);
                Path parent = out.toAbsolutePath().getParent();
                if (parent != null) {
                    Files.createDirectories(parent);
                }
                // the same files, byte for byte, as the Spark module's assembly: the linear .pfm, then the PNG
                AtomicFiles.writeBytes(FramePattern.pfmOf(out), o -> o.write(piece.pfm()));
                AtomicFiles.writeBytes(out, o -> o.write(piece.png()));
            }
        }
        return 0;
    }

    /** Options that do not go with a job file: one line naming the first. */
    private void checkOptions() {
        String[][] refused = {{"--pixel", cmd.pixel}, {"--difference-to", cmd.differenceTo}, {"--eye", cmd.eye},
                {"--target", cmd.target}, {"--up", cmd.up}, {"--fov", cmd.fov == null ? null : ""},
                {"--repeat", cmd.repeat == 1 ? null : ""}, {"--stats", cmd.stats ? "" : null}};
        for (String[] r : refused) {
            if (r[1] != null) {
                throw new IllegalArgumentException(r[0] + " does not go with a job file (" + cmd.model
                        + "): the job sets the camera and the frames");
            }
        }
        if (cmd.output != null && !cmd.output.toString().toLowerCase(Locale.ROOT).endsWith(".png")) {
            throw new IllegalArgumentException(org.beziertracer.model.io.FilePaths.text(cmd.output) + ": the output must be a .png file");
        }
        if (cmd.method != null) {
            Method.parse(cmd.method);
        }
        cmd.pieceOptions.check();
    }
}
