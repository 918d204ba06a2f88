package org.beziertracer.model.io;

import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Number parsing and printing shared by the readers and writers.
 *
 * <p>Printing uses the shortest text that parses back to the same {@code double}
 * ({@link Double#toString(double)}), with whole numbers written without {@code .0}; so every
 * writer round-trips exactly, including {@code -0.0}.
 *
 * <p>Parsing accepts plain decimal and scientific notation only ({@code 12}, {@code -0.5},
 * {@code 1e-3}, {@code .5}); unlike {@link Double#parseDouble} it rejects {@code NaN},
 * {@code Infinity}, hex floats and {@code d}/{@code f} suffixes.
 */
final class NumberText {
    private NumberText() {}

    private static final Pattern DECIMAL = Pattern.compile("[+-]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?");
    /** How overflow messages end: what the largest {@code double} is. */
    static final String BEYOND = "beyond the largest number, about 1.8e308";

    private static final Pattern WHOLE = Pattern.compile("[+-]?\\d+");

    /** Shortest round-trip text of {@code v}; whole numbers below 1e15 without a fraction. */
    static String format(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15 && !(v == 0 && 1 / v < 0)) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }

    /** True for plain decimal or scientific notation. */
    static boolean isDecimal(String token) {
        return DECIMAL.matcher(token).matches();
    }

    /** True for an optionally signed run of digits. */
    static boolean isWhole(String token) {
        return WHOLE.matcher(token).matches();
    }

    /** True for the spellings of NaN and infinity that other tools write. */
    static boolean isNonFiniteWord(String token) {
        String t = token.toLowerCase(Locale.ROOT);
        if (t.startsWith("+") || t.startsWith("-")) {
            t = t.substring(1);
        }
        return t.equals("nan") || t.equals("inf") || t.equals("infinity") || t.startsWith("1.#");
    }

    /**
     * Parses a whole number; values beyond the {@code long} range saturate to
     * {@link Long#MAX_VALUE} / {@link Long#MIN_VALUE} so range checks still report them.
     */
    static long parseWhole(String token) {
        try {
            return Long.parseLong(token.startsWith("+") ? token.substring(1) : token);
        } catch (NumberFormatException e) {
            return token.startsWith("-") ? Long.MIN_VALUE : Long.MAX_VALUE;
        }
    }

    /**
     * Parses a finite coordinate or reports why not, as "expected a … number for WHAT, found …".
     *
     * @return the value, or throws {@link ModelFormatException}
     */
    static double parseFinite(String token, String what, String fileName, int line) {
        if (token == null) {
            throw new ModelFormatException(fileName, line, "expected a number for " + what + ", found " + describe(null));
        }
        if (isDecimal(token)) {
            double v = Double.parseDouble(token);
            if (Double.isFinite(v)) {
                return v;
            }
            throw new ModelFormatException(fileName, line, "expected a finite number for " + what
                    + ", found " + describe(token) + " (too large for a double)");
        }
        if (isNonFiniteWord(token)) {
            throw new ModelFormatException(fileName, line, "expected a finite number for " + what
                    + ", found " + describe(token));
        }
        throw new ModelFormatException(fileName, line, "expected a number for " + what + ", found " + describe(token));
    }

    /** {@code "abc"} in quotes ({@link Echo#quote}: at most 60 characters), or {@code end of file} for null. */
    static String describe(String token) {
        return token == null ? "end of file" : Echo.quote(token);
    }

    /**
     * {@code v} for messages: the shortest round-trip text, in the lower-case scientific form of the
     * files ({@code 1e308}, {@code -1.5e-7}, {@code 0.25}).
     */
    static String show(double v) {
        return format(v).replace(".0E", "e").replace('E', 'e');
    }

    /** The value of a plain decimal token when it is finite, else NaN (the caller then reports why). */
    static double finiteOrNaN(String token) {
        if (token == null || !isDecimal(token)) {
            return Double.NaN;
        }
        double v = Double.parseDouble(token);
        return Double.isFinite(v) ? v : Double.NaN;
    }
}
