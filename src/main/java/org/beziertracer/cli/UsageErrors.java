package org.beziertracer.cli;

import java.util.Arrays;
import java.util.Locale;
import java.nio.file.Path;

import org.beziertracer.model.io.Echo;

import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.ParameterException;

/**
 * A wrong command line — an option's value of the wrong type, an unknown option, a missing one —
 * as one line in the project's words and a pointer to the command's help, instead of picocli's
 * message and the whole usage text: {@code beziertracer render: --threads: expected a whole
 * number, found "abc" (see beziertracer render --help)}. The exit code stays picocli's for invalid
 * input (2).
 */
final class UsageErrors {
    private UsageErrors() {}

    /** The parameter exception handler of the command tree. */
    static int handle(ParameterException e, String[] args) {
        CommandLine cmd = e.getCommandLine();
        String name = cmd.getCommandSpec().qualifiedName();
        cmd.getErr().println(name + ": " + message(e) + " (see " + name + " --help)");
        cmd.getErr().flush();
        return cmd.getCommandSpec().exitCodeOnInvalidInput();
    }

    /** The one-line description of {@code e}. */
    static String message(ParameterException e) {
        ArgSpec arg = e.getArgSpec();
        String value = e.getValue();
        if (arg != null && value != null && e.getCause() instanceof CommandLine.TypeConversionException t) {
            String why = arg.type() == Path.class && t.getMessage() != null && t.getMessage().contains("locale")
                    ? ": " + t.getMessage() : ""; // FilePaths.invalidName(): what to change
            return label(arg) + ": expected " + expected(arg.type()) + ", found " + Echo.quote(value) + why;
        }
        String first = String.valueOf(e.getMessage()).lines().findFirst().orElse("").strip();
        return first.isEmpty() ? "invalid command line" : lowerFirst(first.replace("'", "\""));
    }

    private static String label(ArgSpec arg) {
        return arg instanceof OptionSpec o ? o.longestName() : arg.paramLabel();
    }

    private static String expected(Class<?> type) {
        if (type == int.class || type == Integer.class || type == long.class || type == Long.class) {
            return "a whole number";
        }
        if (type == double.class || type == Double.class || type == float.class || type == Float.class) {
            return "a number";
        }
        if (type == Path.class || type == java.io.File.class) {
            return "a file name";
        }
        if (type.isEnum()) {
            return "one of " + String.join(", ", Arrays.stream(type.getEnumConstants())
                    .map(c -> c.toString().toLowerCase(Locale.ROOT)).toList());
        }
        return "a " + type.getSimpleName().toLowerCase(Locale.ROOT);
    }

    private static String lowerFirst(String s) {
        return s.length() > 1 && Character.isUpperCase(s.charAt(0)) && Character.isLowerCase(s.charAt(1))
                ? Character.toLowerCase(s.charAt(0)) + s.substring(1) : s;
    }
}
