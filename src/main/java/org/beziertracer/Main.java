package org.beziertracer;

import org.beziertracer.cli.BezierTracerCommand;

/**
 * Entry point. With no arguments it launches the desktop app (or, on a machine without a display,
 * prints how to use the command line); with arguments it runs a command-line tool.
 */
public final class Main {
    private Main() {}

    public static void main(String[] args) {
        System.exit(BezierTracerCommand.run(args));
    }
}
