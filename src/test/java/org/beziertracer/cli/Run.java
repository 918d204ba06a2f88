package org.beziertracer.cli;

import java.io.PrintWriter;
import java.io.StringWriter;

/** Output, errors and exit code of one command-line run, for the CLI tests. */
record Run(int code, String out, String err) {

    /** Runs {@code beziertracer ARGS} in this JVM with captured output. */
    static Run of(String... args) {
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code = BezierTracerCommand.run(args, new PrintWriter(out), new PrintWriter(err));
        return new Run(code, out.toString(), err.toString());
    }
}
