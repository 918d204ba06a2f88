package org.beziertracer.cli;

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
        CommandLine cl = commandLine();
        return execute(cl, args);
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
        int code = execute(cl, args);
        out.flush();
        err.flush();
        return code;
    }

    /**
     * Runs the command; an {@link Error} (out of memory, stack overflow), which picocli lets
     * through, becomes one line too ({@link CliErrors}).
     */
    private static int execute(CommandLine cl, String[] args) {
        try {
            return cl.execute(args);
        } catch (Error e) {
            boolean sub = args.length > 0 && cl.getSubcommands().containsKey(args[0]);
            return CliErrors.report(e, sub ? args[0] : cl.getCommandName(), cl.getErr());
        }
    }

    /** The configured command tree: sub-commands plus the one-line error handler. */
    static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new BezierTracerCommand());
        cl.setResourceBundle(new CliText());
        cl.setExecutionExceptionHandler(CliErrors::handle);
        return cl;
    }

    static int launchApp(Runnable desktopApp) {
        if (!DisplayCheck.displayReachable()) {
            System.err.println(DisplayCheck.NO_DISPLAY);
            return EXIT_NO_DISPLAY;
        }
        if (desktopApp == null) {
            System.err.println("beziertracer: no desktop app in this build; "
                    + "use the command line: java -jar target/beziertracer.jar --help");
            return EXIT_NO_DISPLAY;
        }
        desktopApp.run();
        return APP_RUNNING;
    }

    @Override
    public Integer call() {
        new CommandLine(this).usage(new PrintWriter(System.out, true));
        return 0;
    }
}
