package org.beziertracer.model.io;

import java.util.Arrays;

/**
 * Splits a statement into its whitespace-separated fields, as {@code s.strip().split("\\s+")}
 * would, without compiling a regex for each line (what {@code String.split} does for a pattern of
 * more than one character): the readers split every line of files of millions of lines.
 */
final class Fields {
    private Fields() {}

    /** The fields of {@code s} between runs of {@code [ \t\n\u000B\f\r]}; {@code [""]} for a blank line, as split gives. */
    static String[] of(String s) {
        char[] t = s.strip().toCharArray(); // scanned as an array: no charAt call a character in a cold read
        int n = t.length;
        String[] out = new String[8];
        int count = 0;
        int i = 0;
        while (i < n) {
            int start = i;
            while (i < n && !separator(t[i])) {
                i++;
            }
            if (count == out.length) {
                out = Arrays.copyOf(out, 2 * count);
            }
            out[count++] = new String(t, start, i - start);
            while (i < n && separator(t[i])) {
                i++;
            }
        }
        return count == 0 ? new String[] {""} : Arrays.copyOf(out, count);
    }

    /** The characters of the regex class {@code \s}. */
    static boolean separator(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == 0x0B || c == '\f' || c == '\r';
    }
}
