package org.beziertracer.model.io;

/**
 * The free-format parameters of one IGES record (a parameter-data entry or the global section):
 * fields separated by the parameter delimiter, ended by the record delimiter, Hollerith strings
 * ({@code 5HHELLO}) read whole, so they may hold either delimiter. An empty field is a default
 * value (0, or the given default). Typed getters turn a bad field into one line naming the
 * file, the line and the field (IGES 5.3 §2.2.3).
 *
 * <pre>
 * IgesParams p = IgesParams.parse("128,1,1,1,1,0,0,1,0,0,0.,0.,1.,1.;", ',', ';', src, 40, "entity 128");
 * p.integer(1) → 1   p.real(10) → 0.0   p.size() → 15
 * </pre>
 */
final class IgesParams {

    /** The record's text; field {@code k} is {@code text[from[k], to[k])}, trimmed (no copy until asked for). */
    private final char[] text;
    private final int[] from, to;
    private final boolean[] hollerith;
    private final int size;
    private final TextSource source;
    private final int line;
    private final String what;

    private IgesParams(char[] text, int[] from, int[] to, boolean[] hollerith, int size, TextSource source, int line,
                       String what) {
        this.text = text;
        this.from = from;
        this.to = to;
        this.hollerith = hollerith;
        this.size = size;
        this.source = source;
        this.line = line;
        this.what = what;
    }

    /** Field bounds as the parse finds them. */
    private static final class Bounds {
        int[] from, to;
        boolean[] hollerith;
        int size;

        /** Room for {@code capacity} fields (grown when a record holds more). */
        Bounds(int capacity) {
            from = new int[capacity];
            to = new int[capacity];
            hollerith = new boolean[capacity];
        }

        void add(int a, int b, boolean h) {
            if (size == from.length) {
                from = java.util.Arrays.copyOf(from, 2 * size);
                to = java.util.Arrays.copyOf(to, 2 * size);
                hollerith = java.util.Arrays.copyOf(hollerith, 2 * size);
            }
            from[size] = a;
            to[size] = b;
            hollerith[size++] = h;
        }
    }

    /**
     * Splits {@code text} into fields up to the record delimiter (the rest is ignored).
     *
     * @param line the file line the record starts on, for messages
     * @param what what the record is, for messages ({@code "entity 128 (directory line 7)"})
     */
    static IgesParams parse(String text, char delimiter, char end, TextSource source, int line, String what) {
        return parse(text.toCharArray(), text.length(), delimiter, end, source, line, what);
    }

    /**
     * {@link #parse(String, char, char, TextSource, int, String)} of the first {@code n} characters
     * of {@code text}, which the result keeps (the caller hands it over). Scanned as an array, not
     * by {@code String.charAt}: a cold read runs this loop in the interpreter and C1, where a
     * {@code charAt} is four calls a character.
     */
    static IgesParams parse(char[] text, int n, char delimiter, char end, TextSource source, int line, String what) {
        Bounds fields = new Bounds(Math.max(16, n / 6)); // an estimate: B-spline records take about 6 characters a field
        int k = 0;
        boolean ended = false;
        while (k <= n && !ended) {
            // skip blanks before a field
            while (k < n && text[k] == ' ') {
                k++;
            }
            int start = k;
            while (k < n && (text[k] >= '0' && text[k] <= '9' || text[k] > 127 && Character.isDigit(text[k]))) {
                k++;
            }
            if (k > start && k < n && (text[k] == 'H' || text[k] == 'h')) {
                int count;
                try {
                    count = Integer.parseInt(new String(text, start, k - start));
                } catch (NumberFormatException e) {
                    throw source.error(line, what + ": a string length " + Echo.quote(new String(text, start, k - start))
                            + " too large");
                }
                if (count > n - k - 1) {
                    throw source.error(line, what + ": a string of " + count + " characters runs past the record's end");
                }
                fields.add(k + 1, k + 1 + count, true);
                k += 1 + count;
                while (k < n && text[k] == ' ') {
                    k++;
                }
            } else {
                k = start;
                while (k < n && text[k] != delimiter && text[k] != end) {
                    k++;
                }
                int a = start, b = k;
                while (a < b && text[a] <= ' ') {
                    a++;
                }
                while (b > a && text[b - 1] <= ' ') {
                    b--;
                }
                fields.add(a, b, false);
            }
            if (k >= n) {
                throw source.error(line, what + ": the record does not end with " + Echo.quote(String.valueOf(end)));
            }
            char c = text[k];
            if (c == end) {
                ended = true;
            } else if (c != delimiter) {
                throw source.error(line, what + ": expected " + Echo.quote(String.valueOf(delimiter)) + " or "
                        + Echo.quote(String.valueOf(end)) + " after field " + fields.size + ", found "
                        + Echo.quote(String.valueOf(c)));
            }
            k++;
        }
        return new IgesParams(text, fields.from, fields.to, fields.hollerith, fields.size, source, line, what);
    }

    int size() { return size; }

    int line() { return line; }

    String what() { return what; }

    /** Whether field {@code k} (0-based) is present and not empty. */
    boolean has(int k) {
        return k < size && to[k] > from[k];
    }

    /** Field {@code k} as a whole number; an empty field is 0. */
    int integer(int k) {
        check(k);
        int a = from[k], b = to[k];
        if (a < b && b - a <= 9) { // up to 9 characters: digits after an optional sign never overflow
            int i = a;
            boolean negative = text[i] == '-';
            if (negative || text[i] == '+') {
                i++;
            }
            int v = 0;
            boolean digits = i < b;
            for (; i < b && digits; i++) {
                char c = text[i];
                digits = c >= '0' && c <= '9';
                v = 10 * v + (c - '0');
            }
            if (digits) {
                return negative ? -v : v;
            }
        }
        String f = field(k);
        if (f.isEmpty()) {
            return 0;
        }
        try {
            return Integer.parseInt(f.startsWith("+") ? f.substring(1) : f);
        } catch (NumberFormatException e) {
            throw error("field " + (k + 1) + ": expected a whole number, found " + Echo.quote(f));
        }
    }

    /** Field {@code k} as a pointer to a directory entry (0 = none): odd and positive, or 0. */
    int pointer(int k) {
        int p = integer(k);
        if (p < 0) {
            p = -p; // a negated pointer (a colour, a back pointer) points as well
        }
        return p;
    }

    /** Field {@code k} as a real; an empty field is {@code otherwise}. Fortran exponents ({@code 1.5D2}) read. */
    double real(int k, double otherwise) {
        check(k);
        if (from[k] == to[k]) {
            return otherwise;
        }
        double fast = NumberText.finiteOrNaN(text, from[k], to[k]); // a plain decimal, parsed in place
        if (!Double.isNaN(fast)) {
            return fast;
        }
        String f = field(k);
        double v;
        try {
            v = Double.parseDouble(f.replace('D', 'E').replace('d', 'e'));
        } catch (NumberFormatException e) {
            throw error("field " + (k + 1) + ": expected a number, found " + Echo.quote(f));
        }
        if (!Double.isFinite(v) || f.indexOf('x') >= 0 || f.indexOf('X') >= 0 || Character.isLetter(f.charAt(f.length() - 1))) {
            throw error("field " + (k + 1) + ": expected a finite number, found " + Echo.quote(f));
        }
        return v;
    }

    double real(int k) {
        return real(k, 0);
    }

    /**
     * Field {@code k}, a percentage, as a fraction: its decimal text divided by 100 and rounded
     * once (not the rounded number divided again), so the text {@code IgesWriter.percent} makes of
     * any {@code double} in [0, 1] gives that {@code double} back.
     */
    double fraction(int k) {
        double v = real(k);
        try {
            return new java.math.BigDecimal(field(k).replace('D', 'E').replace('d', 'e')).movePointLeft(2).doubleValue();
        } catch (NumberFormatException | ArithmeticException e) {
            return v / 100; // a form BigDecimal refuses: the rounded quotient
        }
    }

    /** Field {@code k} as a string (a Hollerith string, or the bare text); empty when absent. */
    String string(int k) {
        return k < size ? new String(text, from[k], to[k] - from[k]) : "";
    }

    /** Whether field {@code k} was written as a Hollerith string. */
    boolean isString(int k) {
        return k < size && hollerith[k];
    }

    /** Fields {@code from .. from+count-1} as reals. */
    double[] reals(int from, int count) {
        double[] out = new double[count];
        for (int k = 0; k < count; k++) {
            out[k] = real(from + k);
        }
        return out;
    }

    /** Requires at least {@code count} fields ({@code naming} them for the message). */
    void require(int count, String naming) {
        if (size < count) {
            throw error("expected " + count + " fields (" + naming + "), found " + size);
        }
    }

    ModelFormatException error(String detail) {
        return source.error(line, what + ": " + detail);
    }

    /** Field {@code k} must be there and not a string. */
    private void check(int k) {
        if (k >= size) {
            throw error("expected at least " + (k + 1) + " fields, found " + size);
        }
        if (hollerith[k]) {
            throw error("field " + (k + 1) + ": expected a number, found the string " + Echo.quote(string(k)));
        }
    }

    private String field(int k) {
        check(k);
        return string(k);
    }
}
