package org.beziertracer.cli;

import picocli.CommandLine;
import picocli.CommandLine.ParseResult;

/**
 * Turns an exception thrown by a command into one line on stderr (no stack trace) and exit code 1.
 * Set {@code BEZIERTRACER_DEBUG=1} to see the stack trace as well.
 */
final class CliErrors {
    private CliErrors() {}

    static int handle(Exception ex, CommandLine cl, ParseResult parsed) {
        String msg = ex.getMessage();
        if (msg == null || msg.isBlank()) {
            msg = ex.getClass().getSimpleName();
        }
        cl.getErr().println("beziertracer " + cl.getCommandName() + ": " + msg.replace('\n', ' '));
        if (System.getenv("BEZIERTRACER_DEBUG") != null) {
            ex.printStackTrace(cl.getErr());
        }
        return 1;
    }
}
