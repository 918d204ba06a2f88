package org.beziertracer.render;

import java.io.IOException;
import java.io.UncheckedIOException;

import org.beziertracer.intersect.HeapBudget;
import org.beziertracer.model.io.Echo;

/**
 * One line that tells a user why work failed, for the command line and the app: the message of an
 * input or I/O problem (those are written for users: {@link IllegalArgumentException},
 * {@link IOException}), a sentence for running out of heap or stack, and for anything else (a
 * bug) a sentence that names no Java class and says how to see the details. Stateless.
 */
public final class Failures {
    private Failures() {}

    /** The environment variable that makes the command line print stack traces too. */
    public static final String DEBUG_VARIABLE = "BEZIERTRACER_DEBUG";

    /** One line for {@code e}. */
    public static String describe(Throwable e) {
        Throwable t = e instanceof UncheckedIOException u && u.getCause() != null ? u.getCause() : e;
        if (t instanceof OutOfMemoryError) {
            return HeapBudget.outOfMemory();
        }
        if (t instanceof StackOverflowError) {
            return "the work nested too deeply for the thread stack (run java -Xss16m … or simplify the input)";
        }
        String message = t.getMessage();
        if ((t instanceof IllegalArgumentException || t instanceof IOException) && message != null
                && !message.isBlank()) {
            return Echo.cutQuoted(message.replace('\r', ' ').replace('\n', ' '));
        }
        return "an internal error stopped this work (set " + DEBUG_VARIABLE + "=1 to see where)";
    }
}
