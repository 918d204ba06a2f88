package org.beziertracer.model.io;

import java.util.Locale;

import ch.randelshofer.fastdoubleparser.JavaDoubleParser;

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

    /** How overflow messages end: what the largest {@code double} is. */
    static final String BEYOND = "beyond the largest number, about 1.8e308";

    /** Shortest round-trip text of {@code v}; whole numbers below 1e15 without a fraction. */
    static String format(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15 && !(v == 0 && 1 / v < 0)) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }

    /**
     * True for plain decimal or scientific notation, {@code [+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?}
     * with ASCII digits (scanned by hand: the readers call it for every number, and a regex
     * {@code Matcher} a call was most of what reading a large OBJ allocated).
     */
    static boolean isDecimal(String token) {
        return isDecimal(token, 0, token.length());
    }

    /** {@link #isDecimal(String)} of the characters {@code [from, to)} of {@code s}. */
    static boolean isDecimal(String s, int from, int to) {
        int i = sign(s, from, to);
        int whole = digits(s, i, to);
        i += whole;
        int fraction = 0;
        if (i < to && s.charAt(i) == '.') {
            fraction = digits(s, i + 1, to);
            i += 1 + fraction;
        }
        if (whole == 0 && fraction == 0) {
            return false;
        }
        if (i < to && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
            i = sign(s, i + 1, to);
            int exponent = digits(s, i, to);
            if (exponent == 0) {
                return false;
            }
            i += exponent;
        }
        return i == to;
    }

    /** True for an optionally signed run of ASCII digits, {@code [+-]?\d+}. */
    static boolean isWhole(String token) {
        int i = sign(token, 0, token.length());
        int d = digits(token, i, token.length());
        return d > 0 && i + d == token.length();
    }

    /** {@code i} past an optional sign at {@code i} (before {@code n}). */
    private static int sign(String s, int i, int n) {
        return i < n && (s.charAt(i) == '+' || s.charAt(i) == '-') ? i + 1 : i;
    }

    /** How many ASCII digits start at {@code i} (before {@code n}). */
    private static int digits(String s, int i, int n) {
        int j = i;
        while (j < n && s.charAt(j) >= '0' && s.charAt(j) <= '9') {
            j++;
        }
        return j - i;
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

    /**
     * The value of the plain decimal {@code [from, to)} of {@code s} when it is one and finite, else
     * NaN; parsed in place, correctly rounded as {@link Double#parseDouble} (FastDoubleParser, after
     * Lemire 2021, "Number parsing at a gigabyte per second").
     */
    static double finiteOrNaN(String s, int from, int to) {
        if (from >= to || !isDecimal(s, from, to)) {
            return Double.NaN;
        }
        double v = JavaDoubleParser.parseDouble(s, from, to - from);
        return Double.isFinite(v) ? v : Double.NaN;
    }

    /** {@link #finiteOrNaN(String, int, int)} of the characters {@code [from, to)} of {@code s}. */
    static double finiteOrNaN(char[] s, int from, int to) {
        if (from >= to || !isDecimal(s, from, to)) {
            return Double.NaN;
        }
        double v = JavaDoubleParser.parseDouble(s, from, to - from);
        return Double.isFinite(v) ? v : Double.NaN;
    }

    /** {@link #isDecimal(String, int, int)} of a character array. */
    static boolean isDecimal(char[] s, int from, int to) {
        int i = from < to && (s[from] == '+' || s[from] == '-') ? from + 1 : from;
        int whole = digits(s, i, to);
        i += whole;
        int fraction = 0;
        if (i < to && s[i] == '.') {
            fraction = digits(s, i + 1, to);
            i += 1 + fraction;
        }
        if (whole == 0 && fraction == 0) {
            return false;
        }
        if (i < to && (s[i] == 'e' || s[i] == 'E')) {
            i = i + 1 < to && (s[i + 1] == '+' || s[i + 1] == '-') ? i + 2 : i + 1;
            int exponent = digits(s, i, to);
            if (exponent == 0) {
                return false;
            }
            i += exponent;
        }
        return i == to;
    }

    private static int digits(char[] s, int i, int n) {
        int j = i;
        while (j < n && s[j] >= '0' && s[j] <= '9') {
            j++;
        }
        return j - i;
    }

    /**
     * The whole number {@code [+-]?\d{1,18}} that is {@code s[from..to)}, else
     * {@link Long#MIN_VALUE} (which no index resolves to): an OBJ index read in place.
     */
    static long wholeOrMin(char[] s, int from, int to) {
        int i = from < to && (s[from] == '+' || s[from] == '-') ? from + 1 : from;
        if (i == to || to - i > 18) {
            return Long.MIN_VALUE;
        }
        long v = 0;
        for (int k = i; k < to; k++) {
            char d = s[k];
            if (d < '0' || d > '9') {
                return Long.MIN_VALUE;
            }
            v = 10 * v + (d - '0');
        }
        return s[from] == '-' ? -v : v;
    }

    /** The value of a plain decimal token when it is finite, else NaN (the caller then reports why). */
    static double finiteOrNaN(String token) {
        return token == null ? Double.NaN : finiteOrNaN(token, 0, token.length());
    }

    /** A whole number: an optional sign and up to 18 digits in place, else {@link Long#parseLong} (which also reports). */
    static Long whole(CharSequence sb) {
        int n = sb.length(), i = 0;
        boolean negative = n > 0 && sb.charAt(0) == '-';
        if (n > 0 && (negative || sb.charAt(0) == '+')) {
            i++;
        }
        if (i < n && n - i <= 18) {
            long v = 0;
            for (; i < n; i++) {
                char d = sb.charAt(i);
                if (d < '0' || d > '9') {
                    return Long.parseLong(sb.toString());
                }
                v = 10 * v + (d - '0');
            }
            return negative ? -v : v;
        }
        return Long.parseLong(sb.toString());
    }
}
