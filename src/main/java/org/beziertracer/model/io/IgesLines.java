package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The fixed 80-column lines of an IGES file (IGES 5.3 §2.1): the section letter in column 73,
 * the line's number in its section in columns 74–80, directory entries as two lines of nine
 * 8-column fields, parameter data in columns 1–64 with the entry's directory pointer in 66–72.
 * Free-format records break between fields (a field longer than a line is split, as the
 * standard allows for strings).
 */
final class IgesLines {
    private final Writer out;
    private int start, global, directory, parameter;

    IgesLines(Writer out) {
        this.out = out;
    }

    void start(String text) throws IOException {
        for (int k = 0; k < text.length(); k += 72) {
            line(text.substring(k, Math.min(text.length(), k + 72)), 'S', ++start);
        }
    }

    void global(List<String> fields) throws IOException {
        for (String l : wrap(fields, 72)) {
            line(l, 'G', ++global);
        }
    }

    /** A directory entry; {@code colour} is field 13 (0, a colour number 1..8, or a negated pointer to a 314). */
    void directory(int type, int paramStart, String status, int colour, int paramLines, int form, String label)
            throws IOException {
        line(String.format(Locale.ROOT, "%8d%8d%8d%8d%8d%8s%8s%8s%8s", type, paramStart, 0, 0, 0, "", "", "", status),
                'D', ++directory);
        line(String.format(Locale.ROOT, "%8d%8d%8d%8d%8d%8s%8s%8s%8d", type, 0, colour, paramLines, form, "", "", label, 0),
                'D', ++directory);
    }

    void parameters(List<String> lines, int pointer) throws IOException {
        for (String l : lines) {
            line(String.format(Locale.ROOT, "%-64s %7d", l, pointer), 'P', ++parameter);
        }
    }

    void terminate() throws IOException {
        line(String.format(Locale.ROOT, "S%7dG%7dD%7dP%7d", start, global, directory, parameter), 'T', 1);
        out.flush();
    }

    /** The fields of one record, delimited by commas and ended by a semicolon, in lines of at most 64 columns. */
    static List<String> wrap(List<String> fields) {
        return wrap(fields, 64);
    }

    private static List<String> wrap(List<String> fields, int width) {
        List<String> lines = new ArrayList<>();
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < fields.size(); k++) {
            String f = fields.get(k) + (k == fields.size() - 1 ? ";" : ",");
            if (sb.length() + f.length() > width && sb.length() > 0) {
                lines.add(sb.toString());
                sb.setLength(0);
            }
            while (f.length() > width) {
                lines.add(f.substring(0, width));
                f = f.substring(width);
            }
            sb.append(f);
        }
        lines.add(sb.toString());
        return lines;
    }

    private void line(String text, char section, int number) throws IOException {
        out.write(String.format(Locale.ROOT, "%-72s%c%7d\n", text, section, number));
    }
}
