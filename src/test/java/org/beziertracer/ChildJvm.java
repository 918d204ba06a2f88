package org.beziertracer;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Runs a main class in a fresh JVM with this test run's class path, for tests that need their own
 * heap size (out-of-memory paths) or a clean process (exit codes, standard error as a user sees it).
 */
public final class ChildJvm {
    private ChildJvm() {}

    /** Exit code, standard output and standard error of a finished child. */
    public record Result(int code, String out, String err) {}

    /**
     * Runs {@code mainClass args} with the given JVM options (e.g. {@code -Xmx64m}) in {@code dir};
     * fails after 120 s.
     */
    public static Result run(Path dir, List<String> jvmOptions, String mainClass, String... args)
            throws IOException, InterruptedException {
        List<String> options = new ArrayList<>(jvmOptions);
        options.add("-Djava.awt.headless=true");
        return run(dir, options, new ProcessBuilder(), mainClass, args);
    }

    /**
     * Runs {@code mainClass args} as a desktop program would start: {@code java.awt.headless}
     * unset and {@code DISPLAY} set to {@code display} (removed when null).
     */
    public static Result runWithDisplay(Path dir, String display, String mainClass, String... args)
            throws IOException, InterruptedException {
        return runWithDisplay(dir, display, List.of(), mainClass, args);
    }

    /** As {@link #runWithDisplay(Path, String, String, String...)}, with JVM options. */
    public static Result runWithDisplay(Path dir, String display, List<String> jvmOptions, String mainClass,
                                        String... args) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder();
        pb.environment().remove("JAVA_TOOL_OPTIONS");
        pb.environment().remove("_JAVA_OPTIONS");
        if (display == null) {
            pb.environment().remove("DISPLAY");
        } else {
            pb.environment().put("DISPLAY", display);
        }
        return run(dir, jvmOptions, pb, mainClass, args);
    }

    private static Result run(Path dir, List<String> jvmOptions, ProcessBuilder pb, String mainClass, String... args)
            throws IOException, InterruptedException {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(jvmOptions);
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add(mainClass);
        command.addAll(List.of(args));
        Path out = dir.resolve("child.out"), err = dir.resolve("child.err");
        Process p = pb.command(command).directory(dir.toFile())
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("child JVM did not finish in 120 s: " + command);
        }
        return new Result(p.exitValue(), java.nio.file.Files.readString(out, StandardCharsets.UTF_8),
                java.nio.file.Files.readString(err, StandardCharsets.UTF_8));
    }
}
