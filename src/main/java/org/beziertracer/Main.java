package org.beziertracer;

import org.beziertracer.cli.BezierTracerCommand;
import org.beziertracer.cli.CommandArguments;
import org.beziertracer.cli.ConsoleEncoding;
import org.beziertracer.ui.BezierTracerApp;

/**
 * Entry point. With no arguments it launches the desktop app (or, on a machine without a display,
 * prints how to use the command line), with one model file or built-in name the app on that model;
 * with a command it runs a command-line tool. The root
 * package is the only one that sees both {@code cli} and {@code ui}, so it hands the app's
 * launcher to the command line.
 */
public final class Main {
    private Main() {}

    public static void main(String[] args) {
        // Names intact under LANG=C: messages in UTF-8 where Java chose ASCII, arguments as typed
        ConsoleEncoding.install();
        int code = BezierTracerCommand.run(CommandArguments.asTyped(args), BezierTracerApp::launch);
        if (code != BezierTracerCommand.APP_RUNNING) {
            System.exit(code);
        }
    }
}
