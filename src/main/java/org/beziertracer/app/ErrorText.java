package org.beziertracer.app;

import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Turns what went wrong into one line a user can read: the problem's own message when it is a
 * sentence meant for users (model files name file and line), else a plain sentence. No message
 * contains a line break, a Java class name or the word "null". Stateless.
 */
public final class ErrorText {
    private ErrorText() {}

    /** Longest message shown; longer ones are cut with an ellipsis. */
    static final int MAX_LENGTH = 300;

    /** A qualified name ({@code java.nio.file.Path}), an exception or error class, or the word null. */
    private static final Pattern INTERNAL = Pattern.compile(
            "\\b(?:[a-z][a-z0-9_]*\\.)+[A-Z][A-Za-z0-9_$]*\\b|\\b[A-Z][A-Za-z]*(?:Exception|Error)\\b|\\bnull\\b");

    /** One line for {@code e}. */
    public static String oneLine(Throwable e) {
        if (e instanceof OutOfMemoryError) {
            long mb = Runtime.getRuntime().maxMemory() >> 20;
            return "not enough memory: this Java allows " + mb + " MB (start it with a larger -Xmx, e.g. -Xmx"
                    + Math.max(2, 2 * mb / 1024) + "g)";
        }
        if (e instanceof StackOverflowError) {
            return "the computation nested too deeply and was stopped";
        }
        String m = e.getMessage();
        if (isInternal(m)) {
            return "an internal error occurred (details on the console)";
        }
        String line = m.replaceAll("\\s*[\\r\\n]+\\s*", " ").trim();
        return line.length() <= MAX_LENGTH ? line : line.substring(0, MAX_LENGTH - 1) + "…";
    }

    /** True when {@code message} is missing or written for programmers (class names, "null"). */
    public static boolean isInternal(String message) {
        return message == null || message.isBlank() || INTERNAL.matcher(message).find()
                || message.toLowerCase(Locale.ROOT).contains("exception");
    }
}
