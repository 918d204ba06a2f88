package org.beziertracer.cli;

import java.io.PrintWriter;

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
        err.println("beziertracer " + command + ": " + Failures.describe(e));
        if (System.getenv(Failures.DEBUG_VARIABLE) != null) {
            e.printStackTrace(err);
        }
        err.flush();
        return 1;
    }
}
