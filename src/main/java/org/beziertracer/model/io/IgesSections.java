package org.beziertracer.model.io;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The five sections of an IGES 5.3 file in its fixed ASCII form (§2.1): 80-column lines whose
 * column 73 names the section (S start, G global, D directory entry, P parameter data,
 * T terminate) and whose columns 74–80 number the lines of each section from 1. Checks the
 * section order, the sequence numbers, the directory entries' pairs and the parameter lines'
 * back pointers; a corrupt file is one line naming the file and the line. Reads the global
 * section's delimiters, model scale and units.
 *
 * <p>Reference: US PRO, <i>Initial Graphics Exchange Specification 5.3</i> (1996), §2.
 */
final class IgesSections {

    /** One directory entry (§2.2.4): its two lines' fields, with the parameter data it points to. */
    record Entry(int sequence, int type, int paramStart, int transform, int status, int colour, int paramLines,
                 int form, int line) {

        /** Blank status (01 = blanked): not shown in the CAD tool. */
        boolean blanked() { return status / 1_000_000 == 1; }

        /** Subordinate switch: 0 independent; 1, 2, 3 dependent on a parent (drawn through it). */
        int subordinate() { return status / 10_000 % 100; }
    }

    final TextSource source;
    char delimiter = ',', end = ';';
    /** Model space scale (global field 13) and the unit's size in millimetres (fields 14, 15). */
    double scale = 1, unitMillimetres = 1;
    String unitName = "MM";
    final Map<Integer, Entry> entries = new HashMap<>();
    final List<Entry> order = new ArrayList<>();
    private final Map<Integer, StringBuilder> params = new HashMap<>();
    private final Map<Integer, Integer> paramLine = new HashMap<>();

    private IgesSections(TextSource source) {
        this.source = source;
    }

    /** Reads and checks the whole file. */
    static IgesSections read(TextSource source) throws IOException {
        IgesSections s = new IgesSections(source);
        s.readLines();
        return s;
    }

    /** The parameters of {@code e}, split by the file's delimiters. */
    IgesParams params(Entry e) {
        StringBuilder text = params.get(e.sequence);
        if (text == null) {
            throw source.error(e.line, "entity " + e.type + " (directory line " + e.sequence
                    + "): its parameter data (line " + e.paramStart + " of the P section) is missing");
        }
        char[] chars = new char[text.length()];
        text.getChars(0, chars.length, chars, 0);
        IgesParams p = IgesParams.parse(chars, chars.length, delimiter, end, source, paramLine.get(e.sequence),
                "entity " + e.type + " (directory line " + e.sequence + ")");
        if (p.integer(0) != e.type) {
            throw p.error("its parameter data starts with entity type " + p.string(0) + ", expected " + e.type);
        }
        return p;
    }

    private static final String ORDER = "SGDPT";

    private void readLines() throws IOException {
        StringBuilder global = new StringBuilder();
        int globalLine = 0;
        int section = 0, expected = 1;
        String firstDe = null;
        int firstDeLine = 0;
        int[] counts = new int[5];
        boolean terminated = false;
        for (String raw = source.readLine(); raw != null; raw = source.readLine()) {
            int line = source.lineNumber();
            if (raw.isBlank() && terminated) {
                continue;
            }
            if ((line & 1023) == 0 && Thread.currentThread().isInterrupted()) {
                throw new java.io.InterruptedIOException("the read was cancelled");
            }
            if (terminated) {
                throw source.error(line, "text after the terminate (T) line");
            }
            if (raw.length() < 73) {
                if (line == 1 && raw.length() > 0) {
                    throw source.error(line, "not an IGES file in its fixed 80-column form: the line has "
                            + raw.length() + " columns, no section letter in column 73");
                }
                throw source.error(line, "expected 80 columns with a section letter in column 73, found "
                        + raw.length() + " columns");
            }
            char letter = raw.charAt(72);
            if (line == 1 && (letter == 'C' || letter == 'B')) {
                throw source.error(line, (letter == 'C' ? "compressed" : "binary")
                        + " IGES is not supported; save the file as fixed-format ASCII IGES");
            }
            int s = ORDER.indexOf(letter);
            if (s < 0) {
                throw source.error(line, "expected a section letter S, G, D, P or T in column 73, found "
                        + Echo.quote(String.valueOf(letter)));
            }
            if (s < section) {
                throw source.error(line, "a " + letter + " line after the " + ORDER.charAt(section)
                        + " section (the sections run S, G, D, P, T)");
            }
            if (s > section) {
                section = s;
                expected = 1;
            }
            int seq = number(raw, 73, Math.min(raw.length(), 80), line, "sequence number");
            if (seq != expected) {
                throw source.error(line, "expected sequence number " + expected + " in the " + letter
                        + " section, found " + seq);
            }
            expected++;
            counts[s]++;
            switch (letter) {
                case 'G' -> {
                    if (globalLine == 0) {
                        globalLine = line;
                    }
                    global.append(raw, 0, 72);
                }
                case 'D' -> {
                    if (seq % 2 == 1) {
                        firstDe = raw;
                        firstDeLine = line;
                    } else {
                        entry(firstDe, raw, firstDeLine, seq - 1);
                        firstDe = null;
                    }
                }
                case 'P' -> {
                    parameterLine(raw, line, seq);
                }
                case 'T' -> terminated = true;
                default -> { }
            }
        }
        if (firstDe != null) {
            throw source.error(firstDeLine, "a directory entry has only its first line (they come in pairs)");
        }
        if (!terminated) {
            throw source.error(source.lineNumber(), "the file ends without its terminate (T) line: cut short?");
        }
        if (global.length() == 0) {
            throw source.error(source.lineNumber(), "the file has no global (G) section");
        }
        readGlobal(global.toString(), globalLine);
    }

    private void entry(String a, String b, int line, int sequence) {
        int type = field(a, 0, line), type2 = field(b, 0, line + 1);
        if (type != type2) {
            throw source.error(line + 1, "directory entry " + sequence + ": entity type " + type
                    + " on its first line but " + type2 + " on its second");
        }
        String status = a.substring(64, 72).replace(' ', '0');
        int statusNumber;
        try {
            statusNumber = Integer.parseInt(status);
        } catch (NumberFormatException e) {
            throw source.error(line, "directory entry " + sequence + ": expected an 8-digit status number, found "
                    + Echo.quote(a.substring(64, 72)));
        }
        Entry e = new Entry(sequence, type, field(a, 1, line), field(a, 6, line), statusNumber, field(b, 2, line + 1),
                field(b, 3, line + 1), field(b, 4, line + 1), line);
        if (e.paramStart < 1 && type != 0) {
            throw source.error(line, "directory entry " + sequence + ": its parameter data pointer "
                    + e.paramStart + " is not a line number");
        }
        entries.put(sequence, e);
        order.add(e);
    }

    private int field(String raw, int index, int line) {
        return number(raw, 8 * index, 8 * index + 8, line, "field " + (index + 1) + " of the directory entry");
    }

    private int number(String raw, int from, int to, int line, String what) {
        // in place: blanks, an optional sign, at most 9 digits, blanks (what fixed columns hold)
        int i = from;
        while (i < to && raw.charAt(i) == ' ') {
            i++;
        }
        boolean negative = i < to && raw.charAt(i) == '-';
        if (i < to && (negative || raw.charAt(i) == '+')) {
            i++;
        }
        int start = i, v = 0;
        while (i < to && i - start < 9 && raw.charAt(i) >= '0' && raw.charAt(i) <= '9') {
            v = 10 * v + (raw.charAt(i++) - '0');
        }
        int end = i;
        while (i < to && raw.charAt(i) == ' ') {
            i++;
        }
        if (i == to && end > start) {
            return negative ? -v : v;
        }
        return slowNumber(raw, from, to, line, what);
    }

    /** {@link #number} for what the fast form does not cover: empty fields, other blanks, errors. */
    private int slowNumber(String raw, int from, int to, int line, String what) {
        String f = raw.substring(from, to).trim();
        if (f.isEmpty()) {
            return 0;
        }
        try {
            return Integer.parseInt(f.startsWith("+") ? f.substring(1) : f);
        } catch (NumberFormatException e) {
            throw source.error(line, "expected a whole number as the " + what + ", found " + Echo.quote(f));
        }
    }

    /** The entry and text of the parameter line before (an entity's lines come together): no map look-up for the rest. */
    private Entry lastEntry;
    private StringBuilder lastText;

    private void parameterLine(String raw, int line, int seq) {
        int owner = number(raw, 65, 72, line, "directory pointer (columns 66–72) of the parameter line");
        if (lastEntry != null && lastEntry.sequence == owner && seq > lastEntry.paramStart
                && seq < lastEntry.paramStart + Math.max(1, lastEntry.paramLines)) {
            appendParameters(lastText, raw, line, owner);
            return;
        }
        Entry e = entries.get(owner);
        if (e == null) {
            throw source.error(line, "the parameter line points to directory entry " + owner + ", which does not exist");
        }
        if (seq < e.paramStart || seq >= e.paramStart + Math.max(1, e.paramLines)) {
            throw source.error(line, "parameter line " + seq + " points to directory entry " + owner
                    + ", whose data is lines " + e.paramStart + "–" + (e.paramStart + Math.max(1, e.paramLines) - 1));
        }
        StringBuilder sb = params.computeIfAbsent(owner,
                k -> new StringBuilder(64 * Math.max(1, Math.min(e.paramLines, 1024))));
        if (sb.length() == 0) {
            paramLine.put(owner, line);
        }
        lastEntry = e;
        lastText = sb;
        appendParameters(sb, raw, line, owner);
    }

    private void appendParameters(StringBuilder sb, String raw, int line, int owner) {
        sb.append(raw, 0, 64);
        if (sb.length() > source.limits().lineChars() * 64L) {
            throw source.error(line, "the parameter data of directory entry " + owner + " is too long");
        }
    }

    /** The global section (§2.2.3): delimiters first, then fields 13–15 (scale, units). */
    private void readGlobal(String text, int line) {
        int k = 0;
        char d = ',', e = ';';
        if (text.startsWith("1H")) {
            d = text.charAt(2);
            k = 3;
        }
        if (k >= text.length() || text.charAt(k) != d) {
            throw source.error(line, "the global section: expected its parameter delimiter after field 1, found "
                    + Echo.quote(text.substring(k, Math.min(text.length(), k + 8))));
        }
        k++;
        if (text.startsWith("1H", k) && text.length() > k + 2) {
            e = text.charAt(k + 2);
            k += 3;
        }
        delimiter = d;
        end = e;
        if (delimiter == end) {
            throw source.error(line, "the global section gives the same character "
                    + Echo.quote(String.valueOf(end)) + " as parameter and record delimiter");
        }
        if (delimiter == ' ' || end == ' ') {
            throw source.error(line, "the global section gives a blank delimiter");
        }
        // fields 1 and 2 are read; parse the rest behind two empty fields so indices match the standard's
        IgesParams g = IgesParams.parse("" + delimiter + text.substring(k), delimiter, end, source, line,
                "the global section");
        scale = g.has(12) ? g.real(12) : 1;
        if (!(scale > 0)) {
            throw g.error("field 13: expected a positive model space scale, found " + g.string(12));
        }
        int flag = g.has(13) ? g.integer(13) : 2;
        unitMillimetres = switch (flag) {
            case 1 -> 25.4;
            case 2 -> 1;
            case 3 -> unitByName(g, g.string(14));
            case 4 -> 304.8;
            case 5 -> 1_609_344;
            case 6 -> 1000;
            case 7 -> 1_000_000;
            case 8 -> 0.0254;
            case 9 -> 0.001;
            case 10 -> 10;
            case 11 -> 0.0000254;
            default -> throw g.error("field 14: expected a units flag 1..11, found " + flag);
        };
        unitName = g.string(14).isEmpty() ? "MM" : g.string(14);
    }

    private static double unitByName(IgesParams g, String name) {
        return switch (name.toUpperCase(java.util.Locale.ROOT)) {
            case "IN", "INCH" -> 25.4;
            case "MM" -> 1;
            case "FT" -> 304.8;
            case "MI" -> 1_609_344;
            case "M" -> 1000;
            case "KM" -> 1_000_000;
            case "MIL" -> 0.0254;
            case "UM" -> 0.001;
            case "CM" -> 10;
            case "UIN" -> 0.0000254;
            default -> throw g.error("field 15: unknown unit name " + Echo.quote(name));
        };
    }
}
