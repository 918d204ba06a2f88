package org.beziertracer;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.regex.Pattern;

import org.junit.jupiter.api.function.Executable;

/**
 * The one place every error-case test routes its expected error through: {@link #of} (an
 * expected exception) or {@link #check} (a message read from elsewhere, e.g. a command's standard
 * error). Each message is checked at once — one line, no Java class name, no {@code null} — and
 * kept, with the test class that produced it, for {@code UserMessagesTest}, which runs last and
 * checks the whole collection.
 *
 * <p>Thread-safe (the fuzzer reports from a worker thread).
 */
public final class UserMessages {
    private UserMessages() {}

    /** One gathered message and the test class it came from. */
    public record Gathered(String message, String testClass) {}

    private static final List<Gathered> GATHERED = Collections.synchronizedList(new ArrayList<>());

    /** Words and patterns that betray a leaked Java exception or a missing value. */
    private static final List<Pattern> FORBIDDEN = List.of(
            Pattern.compile("\\b\\w*(Exception|Error)\\b"),
            Pattern.compile("\\b(java|javax|sun|jdk|com\\.google|picocli|org\\.beziertracer)\\.[a-z]"),
            Pattern.compile("(?i)\\bnull\\b"),
            Pattern.compile("\\bat [\\w$.]+\\("),
            Pattern.compile("Cannot invoke|because the return value|because \"[\\w.]+\" is"));

    /** Input echoed in double or single quotes, as the readers and settings quote it (at most 60 characters and an ellipsis). */
    private static final Pattern ECHO = Pattern.compile("\"[^\"]{0,61}\"|'[^']{0,61}'");

    /**
     * Runs {@code body}, expects it to throw {@code type}, checks and gathers the message.
     *
     * @return the message
     */
    public static <T extends Throwable> String of(Class<T> type, Executable body) {
        T e = assertThrows(type, body);
        return check(e.getMessage());
    }

    /** Checks and gathers {@code message}; returns it. */
    public static String check(String message) {
        String problem = gather(message);
        if (problem != null) {
            fail("user message " + problem + ": " + message.substring(0, Math.min(message.length(), 500)));
        }
        return message;
    }

    /** Checks {@code stderr} of a command: exactly one line, which {@link #check} accepts; returns it. */
    public static String checkOneLineOutput(String stderr) {
        List<String> lines = stderr.lines().toList();
        if (lines.size() != 1) {
            fail("expected exactly one error line, found " + lines.size() + ":\n" + stderr);
        }
        return check(lines.get(0));
    }

    /**
     * Gathers {@code message} without failing (for the fuzzer, which reports all failures at the
     * end); returns {@link #problem}.
     */
    public static String gather(String message) {
        String caller = StackWalker.getInstance(StackWalker.Option.RETAIN_CLASS_REFERENCE)
                .walk(frames -> frames.map(f -> f.getDeclaringClass().getName())
                        .filter(c -> !c.equals(UserMessages.class.getName()))
                        .findFirst().orElse("?"));
        GATHERED.add(new Gathered(message, caller));
        return problem(message);
    }

    /** Why {@code message} is not fit for a user, or null when it is. */
    public static String problem(String message) {
        if (message == null || message.isBlank()) {
            return "is empty";
        }
        if (message.contains("\n") || message.contains("\r") || message.contains("\u2028")
                || message.contains("\u2029") || message.contains("\u0085")) {
            return "is more than one line";
        }
        // Input echoed in quotes (at most 60 characters) is the user's, not a leak
        String own = ECHO.matcher(message).replaceAll("\"…\"");
        for (Pattern p : FORBIDDEN) {
            if (p.matcher(own).find()) {
                return "contains a Java name or the word null (" + p.pattern() + ")";
            }
        }
        return null;
    }

    /** Everything gathered so far, in order. */
    public static List<Gathered> gathered() {
        synchronized (GATHERED) {
            return List.copyOf(GATHERED);
        }
    }
}
