package org.beziertracer.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.function.Consumer;

import picocli.CommandLine;

/** Output, errors and exit code of one command-line run, for the CLI tests. */
record Run(int code, String out, String err) {

    /** Runs {@code beziertracer ARGS} in this JVM with captured output. */
    static Run of(String... args) {
        return with(cl -> { }, args);
    }

    /** As {@link #of}, after {@code setup} adjusted the command tree (e.g. a sub-command's test seam). */
    static Run with(Consumer<CommandLine> setup, String... args) {
        StringWriter out = new StringWriter(), err = new StringWriter();
        CommandLine cl = BezierTracerCommand.commandLine(args.length > 0 ? args[0] : null); // as the program builds it
        setup.accept(cl);
        int code = BezierTracerCommand.run(cl, args, new PrintWriter(out), new PrintWriter(err));
        return new Run(code, out.toString(), err.toString());
    }

    /** Runs {@code beziertracer ARGS} with standard output going to {@code out} (the result's {@code out} is empty). */
    static Run writingTo(PrintWriter out, String... args) {
        StringWriter err = new StringWriter();
        int code = BezierTracerCommand.run(BezierTracerCommand.commandLine(args.length > 0 ? args[0] : null), args, out,
                new PrintWriter(err));
        return new Run(code, "", err.toString());
    }
}
