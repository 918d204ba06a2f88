package org.beziertracer.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.util.function.Consumer;

import org.beziertracer.model.io.FilePaths;
import org.beziertracer.model.io.BuiltIns;
import org.beziertracer.model.io.Echo;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The top-level {@code beziertracer} command: dispatches to the sub-commands; with no arguments
 * launches the desktop app, and with one argument that names no command — a model or scene file,
 * or a built-in name — launches the desktop app on it.
 */
@Command(name = "beziertracer", mixinStandardHelpOptions = true, versionProvider = BezierTracerCommand.Version.class,
        description = "Ray traces Bézier surfaces directly (no triangles).%n"
                + "With no command, opens the desktop app; beziertracer FILE_OR_BUILTIN opens the app on a model.")
public final class BezierTracerCommand implements java.util.concurrent.Callable<Integer> {

    /** {@code --version}: the release, the Java that runs it, and which evaluation kernel runs. */
    static final class Version implements picocli.CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {"Bézier Tracer 0.1.0",
                    "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vm.name") + ")",
                    "kernel: " + org.beziertracer.math.Kernels.best().description()};
        }
    }

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    /** Exit code for a headless machine asked to open the app. */
    public static final int EXIT_NO_DISPLAY = 3;

    /** Returned by {@link #run(String[], Runnable)} when the desktop app is open: do not exit. */
    public static final int APP_RUNNING = -1;

    /** Exit code for a model argument that names no file and no built-in model. */
    public static final int EXIT_USAGE = 2;

    /** Runs the command line (without a desktop app) and returns the process exit code. */
    public static int run(String[] args) {
        return run(args, null);
    }

    /**
     * Runs the command line and returns the process exit code. With no arguments, or with one
     * that is not a command or an option (a model file or a built-in name), opens the desktop app
     * through {@code desktopApp} — which takes the model to open, or null — and returns
     * {@link #APP_RUNNING}; {@code desktopApp} is supplied by {@code org.beziertracer.Main}, as
     * this layer may not import {@code ui}.
     */
    public static int run(String[] args, Consumer<String> desktopApp) {
        if (args.length == 0) {
            return launchApp(desktopApp, null);
        }
        CommandLine cl = commandLine(args[0]);
        cl.setOut(StandardOutput.system());
        // picocli's own writer would encode in Java's choice, ASCII under LANG=C: names would print as ?
        cl.setErr(new PrintWriter(new java.io.OutputStreamWriter(System.err, ConsoleEncoding.stderr()), true));
        if (args.length == 1 && !args[0].startsWith("-") && !cl.getSubcommands().containsKey(args[0])) {
            String problem = modelProblem(args[0]);
            if (problem != null) {
                cl.getErr().println("beziertracer: " + problem);
                cl.getErr().flush();
                return EXIT_USAGE;
            }
            return launchApp(desktopApp, args[0]);
        }
        return execute(cl, args);
    }

    /** Why {@code arg} cannot be opened in the app (one line), or null when it names a file or a built-in. */
    static String modelProblem(String arg) {
        if (BuiltIns.find(arg).isPresent()) {
            return null;
        }
        if (FilePaths.find(arg).filter(Files::isRegularFile).isPresent()) {
            return null;
        }
        return Echo.quote(arg) + " is not a command, a file or a built-in model (commands: info, trace, render, analyze; "
                + "built-ins: " + String.join(", ", BuiltIns.names()) + ")";
    }

    /**
     * Runs a command with its output and errors going to the given writers (for tests and
     * embedding); never launches the app. Returns the exit code.
     */
    public static int run(String[] args, PrintWriter out, PrintWriter err) {
        return run(commandLine(args.length > 0 ? args[0] : null), args, out, err);
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
     * through, becomes one line too ({@link CliErrors}), and so does output that could not be
     * written ({@link StandardOutput#failure}): exit code 1 instead of 0.
     */
    private static int execute(CommandLine cl, String[] args) {
        boolean sub = args.length > 0 && cl.getSubcommands().containsKey(args[0]);
        String command = sub ? args[0] : cl.getCommandName();
        int code;
        try {
            code = cl.execute(args);
        } catch (Error e) {
            return CliErrors.report(e, command, cl.getErr(), CliErrors.modelArgument(cl));
        }
        // A command that wrote to a full disk or a closed pipe did not succeed
        String failed = StandardOutput.failure(cl.getOut());
        return failed != null && code == 0 ? CliErrors.report(new IOException(failed), command, cl.getErr()) : code;
    }

    /** The sub-commands' names, in the order {@code --help} lists them, and how to make each. */
    private static final String[] NAMES = {"info", "trace", "render", "analyze", "convert"};

    private static Object subcommand(String name) {
        return switch (name) {
            case "info" -> new InfoCommand();
            case "trace" -> new TraceCommand();
            case "render" -> new RenderCommand();
            case "analyze" -> new AnalyzeCommand();
            case "convert" -> new ConvertCommand();
            default -> throw new IllegalArgumentException(name);
        };
    }

    /** The configured command tree: every sub-command plus the one-line error handler. */
    static CommandLine commandLine() {
        return commandLine(null);
    }

    /**
     * The command tree for a command line whose first argument is {@code first}: when that names a
     * sub-command, the tree holds that one only (picocli builds a command's model by reflection
     * over its annotated fields: the other four cost a short command a third of its start-up);
     * otherwise — an option, a model to open, a mistyped name, none — every sub-command, so help,
     * suggestions and errors are as they were.
     */
    static CommandLine commandLine(String first) {
        CommandLine cl = new CommandLine(new BezierTracerCommand());
        boolean one = first != null && java.util.Arrays.asList(NAMES).contains(first);
        for (String name : NAMES) {
            if (!one || name.equals(first)) {
                cl.addSubcommand(name, subcommand(name));
            }
        }
        cl.setResourceBundle(new CliText());
        // File names as FilePaths reads them: an existing non-ASCII name works under LANG=C too
        cl.registerConverter(java.nio.file.Path.class, name -> FilePaths.find(name).orElseThrow(() ->
                new CommandLine.TypeConversionException(FilePaths.invalidName())));
        cl.setExecutionExceptionHandler(CliErrors::handle);
        cl.setParameterExceptionHandler(UsageErrors::handle);
        return cl;
    }

    static int launchApp(Consumer<String> desktopApp, String model) {
        if (!DisplayCheck.displayReachable()) {
            System.err.println(DisplayCheck.noDisplay());
            return EXIT_NO_DISPLAY;
        }
        if (desktopApp == null) {
            System.err.println("beziertracer: no desktop app in this build; "
                    + "use the command line: " + DisplayCheck.launcher() + " --help");
            return EXIT_NO_DISPLAY;
        }
        desktopApp.accept(model);
        return APP_RUNNING;
    }

    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getOut());
        return 0;
    }
}
