package org.beziertracer.cli;

import java.awt.GraphicsEnvironment;
import java.io.PrintWriter;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The top-level {@code beziertracer} command: dispatches to the sub-commands, or with no
 * arguments launches the desktop app.
 */
@Command(name = "beziertracer", mixinStandardHelpOptions = true, version = "Bézier Tracer 0.1.0",
        description = "Ray traces Bézier surfaces directly (no triangles).%n"
                + "With no command, opens the desktop app.",
        subcommands = {InfoCommand.class, TraceCommand.class, RenderCommand.class})
public final class BezierTracerCommand implements java.util.concurrent.Callable<Integer> {

    /** Exit code for a headless machine asked to open the app. */
    public static final int EXIT_NO_DISPLAY = 3;

    /** Returned by {@link #run(String[], Runnable)} when the desktop app is open: do not exit. */
    public static final int APP_RUNNING = -1;

    /** Runs the command line (without a desktop app) and returns the process exit code. */
    public static int run(String[] args) {
        return run(args, null);
    }

    /**
     * Runs the command line and returns the process exit code; with no arguments opens the
     * desktop app through {@code desktopApp} (supplied by {@code org.beziertracer.Main}, as this
     * layer may not import {@code ui}) and returns {@link #APP_RUNNING}.
     */
    public static int run(String[] args, Runnable desktopApp) {
        if (args.length == 0) {
            return launchApp(desktopApp);
        }
        return commandLine().execute(args);
    }

    /**
     * Runs a command with its output and errors going to the given writers (for tests and
     * embedding); never launches the app. Returns the exit code.
     */
    public static int run(String[] args, PrintWriter out, PrintWriter err) {
        return run(commandLine(), args, out, err);
    }

    /** As {@link #run(String[], PrintWriter, PrintWriter)} on a command tree the caller set up. */
    static int run(CommandLine cl, String[] args, PrintWriter out, PrintWriter err) {
        cl.setOut(out);
        cl.setErr(err);
        int code = cl.execute(args);
        out.flush();
        err.flush();
        return code;
    }

    /** The configured command tree: sub-commands plus the one-line error handler. */
    static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new BezierTracerCommand());
        cl.setExecutionExceptionHandler(CliErrors::handle);
        return cl;
    }

    static int launchApp(Runnable desktopApp) {
        if (GraphicsEnvironment.isHeadless()) {
            System.err.println("beziertracer: no display available, so the desktop app cannot open; "
                    + "use the command line instead: " + howToRun() + " --help");
            return EXIT_NO_DISPLAY;
        }
        if (desktopApp == null) {
            System.err.println("beziertracer: no desktop app in this build; "
                    + "use the command line: " + howToRun() + " --help");
            return EXIT_NO_DISPLAY;
        }
        desktopApp.run();
        return APP_RUNNING;
    }

    /**
     * How the user started this program: the launcher of the desktop package ({@code -Pdist}; its
     * path is in {@code jpackage.app-path}) or the jar.
     */
    static String howToRun() {
        String launcher = System.getProperty("jpackage.app-path");
        return launcher != null && !launcher.isBlank() ? launcher : "java -jar target/beziertracer.jar";
    }

    @Override
    public Integer call() {
        new CommandLine(this).usage(new PrintWriter(System.out, true));
        return 0;
    }
}
