package org.beziertracer.model.io.fuzz;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;

import org.beziertracer.UserMessages;
import org.beziertracer.model.io.FileFormat;
import org.beziertracer.model.io.FileFormats;
import org.beziertracer.model.io.ModelFormatException;
import org.beziertracer.model.io.SceneFiles;

/**
 * Loads one file on a worker thread with a {@value #TIMEOUT_SECONDS} s limit and judges the
 * outcome: it loads, or it fails with one {@link ModelFormatException} line that names the file
 * and passes {@link UserMessages}. Anything else — another exception, an {@link Error}, a
 * timeout — is a failure, described in one line for the report. Mutants are read from memory by
 * the format the registry finds for their name ({@link FileFormat#read(java.io.InputStream,
 * String, Path)}: writing thousands of files costs more than reading them); kept regressions are
 * read from disk the way a user's command does ({@link SceneFiles#load}). The work folder holds a
 * copy of the seed tree, so relative model references in scene seeds resolve.
 */
final class FuzzHarness implements AutoCloseable {

    static final int TIMEOUT_SECONDS = 5;

    /** Longest message after the file name: the longest fixed text plus a few 60-character echoes. */
    static final int MAX_DETAIL_CHARS = 400;

    /** Classpath root of the seed folders ({@code bpt/}, {@code obj/}, {@code json/}). */
    static final String SEEDS = "/fuzz/seeds";
    /** Classpath root of the kept failures, one folder per format like the seeds. */
    static final String REGRESSIONS = "/fuzz/regressions";

    private final Path work;
    private ExecutorService worker = newWorker();

    FuzzHarness(Path work) throws IOException {
        this.work = work;
        Path seeds = resource(SEEDS);
        try (Stream<Path> all = Files.walk(seeds)) {
            for (Path p : (Iterable<Path>) all::iterator) {
                Path to = work.resolve(seeds.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(to);
                } else {
                    Files.copy(p, to);
                }
            }
        }
    }

    /** The folder of a classpath resource folder (tests run from {@code target/test-classes}). */
    static Path resource(String folder) {
        try {
            var url = FuzzHarness.class.getResource(folder);
            if (url == null) {
                throw new IllegalStateException("test resource folder " + folder + " is missing");
            }
            return Path.of(url.toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Files of {@code folder/format}, sorted; none when the folder does not exist. */
    static List<Path> files(String folder, String format) {
        Path dir = resource(folder).resolve(format);
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(Files::isRegularFile).sorted().toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Reads {@code bytes} as if they were the file {@code work/format/name}.
     *
     * @return null when it loaded or failed properly; otherwise one line saying what went wrong
     */
    String judge(String format, String name, byte[] bytes) throws InterruptedException {
        Path file = work.resolve(format).resolve(name);
        FileFormat reader = FileFormats.find(name).orElseThrow();
        return within(file.toString(), () -> reader.read(new ByteArrayInputStream(bytes), file.toString(),
                file.getParent()));
    }

    /**
     * Writes {@code bytes} as {@code work/format/name} and opens it as a user's command does.
     *
     * @return null when it loaded or failed properly; otherwise one line saying what went wrong
     */
    String judgeFile(String format, String name, byte[] bytes) throws IOException, InterruptedException {
        Path file = work.resolve(format).resolve(name);
        Files.write(file, bytes);
        return within(file.toString(), () -> SceneFiles.load(file.toString()));
    }

    private String within(String path, Runnable load) throws InterruptedException {
        Future<String> outcome = worker.submit(() -> judged(path, load));
        try {
            return outcome.get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            worker.shutdownNow();
            worker = newWorker();
            return "took longer than " + TIMEOUT_SECONDS + " s";
        } catch (ExecutionException e) {
            return "the harness failed: " + e.getCause();
        }
    }

    private static String judged(String path, Runnable load) {
        try {
            load.run();
            return null;
        } catch (ModelFormatException e) {
            String message = e.getMessage();
            String problem = UserMessages.gather(message);
            if (problem != null) {
                return "message " + problem + ": " + message;
            }
            if (!message.startsWith(path + ":")) {
                return "message does not start with the file: " + message;
            }
            // Echoed input is cut to 60 characters, so a message stays short whatever the file holds
            return message.length() <= path.length() + MAX_DETAIL_CHARS ? null
                    : "message of " + message.length() + " characters: " + message.substring(0, 300) + "…";
        } catch (Throwable t) {
            return "escaped as " + t + (t.getStackTrace().length > 0 ? " at " + t.getStackTrace()[0] : "");
        }
    }

    /** Keeps a failing mutant (and what happened) under {@code target/fuzz-failures/format/}. */
    static Path keep(String format, String name, byte[] bytes, String what) throws IOException {
        Path dir = Files.createDirectories(Path.of("target", "fuzz-failures", format));
        Path file = dir.resolve(name);
        Files.write(file, bytes);
        Files.writeString(dir.resolve(name + ".txt"), what + "\n");
        return file;
    }

    private static ExecutorService newWorker() {
        return Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "fuzz-worker");
            t.setDaemon(true);
            return t;
        });
    }

    @Override
    public void close() {
        worker.shutdownNow();
    }

    /** Collected failures of one run, reported together. */
    static final class Failures {
        private final List<String> lines = new ArrayList<>();

        void add(String line) { lines.add(line); }

        boolean isEmpty() { return lines.isEmpty(); }

        String report(String what) {
            return lines.size() + " " + what + " failed (kept under target/fuzz-failures/; copy each into"
                    + " src/test/resources" + REGRESSIONS + "/FORMAT/ so it is replayed for ever):\n"
                    + String.join("\n", lines.subList(0, Math.min(lines.size(), 20)));
        }
    }
}
