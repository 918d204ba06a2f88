package org.beziertracer.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.model.io.FilePaths;
import org.beziertracer.intersect.HeapBudget;
import org.beziertracer.model.io.HeapEstimates;
import org.beziertracer.render.Failures;

import picocli.CommandLine;
import picocli.CommandLine.ParseResult;

/**
 * Turns whatever a command throws — an exception, or an {@link Error} such as running out of
 * memory — into one line on stderr (no stack trace) and exit code 1 ({@link Failures}). Set
 * {@code BEZIERTRACER_DEBUG=1} to see the stack trace as well.
 */
final class CliErrors {
    private CliErrors() {}

    /** picocli's handler for exceptions thrown by a command. */
    static int handle(Exception ex, CommandLine cl, ParseResult parsed) {
        return report(ex, cl.getCommandName(), cl.getErr());
    }

    /** Prints {@code beziertracer COMMAND: what went wrong} and returns exit code 1. */
    static int report(Throwable e, String command, PrintWriter err) {
        return report(e, command, err, null);
    }

    /**
     * As {@link #report(Throwable, String, PrintWriter)}; running out of memory on {@code model}
     * (the command's MODEL_OR_SCENE, or null) names it and suggests a heap from what reading it
     * takes ({@link HeapEstimates#forFile}).
     */
    static int report(Throwable e, String command, PrintWriter err, String model) {
        String line = e instanceof OutOfMemoryError && model != null ? model + ": " + outOfMemory(model)
                : Failures.describe(e);
        err.println("beziertracer " + command + ": " + line);
        if (System.getenv(Failures.DEBUG_VARIABLE) != null) {
            e.printStackTrace(err);
        }
        err.flush();
        return 1;
    }

    private static String outOfMemory(String model) {
        long estimate = 0;
        Path file = FilePaths.find(model).orElse(null);
        if (file != null && Files.isRegularFile(file)) { // else a built-in name: no file to measure
            estimate = HeapEstimates.forFile(file);
        }
        return HeapBudget.outOfMemory(estimate);
    }

    /** The MODEL_OR_SCENE argument of the sub-command {@code cl} ran, or null. */
    static String modelArgument(CommandLine cl) {
        ParseResult parsed = cl.getParseResult();
        if (parsed == null || !parsed.hasSubcommand()) {
            return null;
        }
        Object model = parsed.subcommand().matchedPositionalValue(0, null);
        return model instanceof String s ? s : null;
    }
}
