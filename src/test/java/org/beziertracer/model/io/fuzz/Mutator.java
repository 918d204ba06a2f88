package org.beziertracer.model.io.fuzz;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.BiFunction;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Seeded mutations of a file's bytes, the kinds real files suffer and hand-written tests miss:
 * byte flips, truncation, duplicated / deleted / swapped lines, numbers replaced by extremes
 * (1e308, 1e400, NaN, -0, huge counts), inserted tokens, bytes that are not UTF-8, a byte-order
 * mark, CRLF or lone CR line ends, very long lines and NUL bytes. Each mutant applies one to three
 * of them. Deterministic for a given {@link Random}.
 */
public final class Mutator {

    /** Length of an inserted "very long line": past the line cap, so the cap's message is exercised. */
    private final int longLineChars;

    /** @param longLineChars length of the rare very long line (the reader's line cap + 1 is a good choice) */
    public Mutator(int longLineChars) {
        this.longLineChars = longLineChars;
    }

    static final String[] EXTREMES = {"1e308", "-1e308", "1e400", "-1e400", "NaN", "nan", "-0", "-0.0", "Infinity",
        "4.9e-324", "1e-400", "0", "-1", "2147483647", "2147483648", "-2147483649", "9223372036854775807",
        "9223372036854775808", "99999999999999999999999999", "1000000", "1000001", "65536", "16", "15"};

    static final String[] TOKENS = {"v", "deg", "surf", "end", "parm", "parm u", "cstype bezier", "cstype rat bezier",
        "curv2", "trim", "bmat", "#", "\\", "/", "//", "-", "{", "}", "[", "]", ",", ":", "\"", "\"\"", "null", "true",
        "false", "\"version\"", "\"models\"", "\"builtin\"", "\"file\"", "\"patch\"", "\"teapot\"", "\"../x.bpt\"",
        "\"transform\"", "\"scale\"", "1e308", "NaN", "0x1F", "1d", "\t", " ", "\u00e9", "\u20ac", "\ud83d\ude00",
        "\u2028", "\u0085"};

    static final byte[][] NOT_UTF8 = {{(byte) 0xFF}, {(byte) 0xC3, 0x28}, {(byte) 0xE2, (byte) 0x82},
        {(byte) 0xF0, 0x28, (byte) 0x8C, (byte) 0xBC}, {(byte) 0xC0, (byte) 0xAF}, {(byte) 0xED, (byte) 0xA0,
        (byte) 0x80}, {(byte) 0x80}, {(byte) 0xFE, (byte) 0xFF}};

    private static final byte[] BOM = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
    private static final Pattern NUMBER = Pattern.compile("-?\\d+(\\.\\d+)?([eE][+-]?\\d+)?");

    /** The mutation kinds, by name (for reproduction notes). */
    private final List<Kind> kinds = List.of(
            new Kind("flip byte", Mutator::flipByte),
            new Kind("truncate", (b, r) -> Arrays.copyOf(b, b.length == 0 ? 0 : r.nextInt(b.length))),
            new Kind("duplicate line", (b, r) -> lines(b, r, 0)),
            new Kind("delete line", (b, r) -> lines(b, r, 1)),
            new Kind("swap lines", (b, r) -> lines(b, r, 2)),
            new Kind("extreme number", Mutator::extremeNumber),
            new Kind("insert token", (b, r) -> insert(b, r, utf8(" " + TOKENS[r.nextInt(TOKENS.length)] + " "))),
            new Kind("not UTF-8", (b, r) -> insert(b, r, NOT_UTF8[r.nextInt(NOT_UTF8.length)])),
            new Kind("byte-order mark", (b, r) -> r.nextInt(4) == 0 ? insert(b, r, BOM) : concat(BOM, b)),
            new Kind("CRLF", (b, r) -> latin1(new String(b, StandardCharsets.ISO_8859_1)
                    .replace("\n", r.nextBoolean() ? "\r\n" : "\r"))),
            new Kind("long line", this::longLine),
            new Kind("NUL bytes", (b, r) -> insert(b, r, new byte[1 + r.nextInt(3)])));

    private record Kind(String name, BiFunction<byte[], Random, byte[]> apply) {}

    /** A mutant of {@code seed}; {@code applied} receives the names of the mutations, in order. */
    public byte[] mutate(byte[] seed, Random rnd, List<String> applied) {
        byte[] b = seed;
        int count = 1 + rnd.nextInt(3);
        for (int k = 0; k < count; k++) {
            Kind kind = kinds.get(rnd.nextInt(kinds.size()));
            if (kind.name().equals("long line") && rnd.nextInt(8) != 0) {
                kind = kinds.get(0); // very long lines are slow to read: keep them rare
            }
            b = kind.apply().apply(b, rnd);
            applied.add(kind.name());
        }
        return b;
    }

    private static byte[] flipByte(byte[] b, Random r) {
        if (b.length == 0) {
            return b;
        }
        byte[] out = b.clone();
        int at = r.nextInt(out.length);
        out[at] = r.nextBoolean() ? (byte) (out[at] ^ (1 << r.nextInt(8))) : (byte) r.nextInt(256);
        return out;
    }

    /** 0 duplicates, 1 deletes, 2 swaps a random line (lines split at {@code \n}). */
    private static byte[] lines(byte[] b, Random r, int op) {
        List<String> lines = new ArrayList<>(Arrays.asList(new String(b, StandardCharsets.ISO_8859_1).split("\n", -1)));
        int i = r.nextInt(lines.size());
        switch (op) {
            case 0 -> lines.add(i, lines.get(i));
            case 1 -> lines.remove(i);
            default -> {
                int j = r.nextInt(lines.size());
                String t = lines.get(i);
                lines.set(i, lines.get(j));
                lines.set(j, t);
            }
        }
        return latin1(String.join("\n", lines));
    }

    private static byte[] extremeNumber(byte[] b, Random r) {
        String text = new String(b, StandardCharsets.ISO_8859_1);
        Matcher m = NUMBER.matcher(text);
        List<int[]> spans = new ArrayList<>();
        while (m.find()) {
            spans.add(new int[] {m.start(), m.end()});
        }
        if (spans.isEmpty()) {
            return insert(b, r, utf8(EXTREMES[r.nextInt(EXTREMES.length)]));
        }
        int[] s = spans.get(r.nextInt(spans.size()));
        String replaced = text.substring(0, s[0]) + EXTREMES[r.nextInt(EXTREMES.length)] + text.substring(s[1]);
        return latin1(replaced);
    }

    private byte[] longLine(byte[] b, Random r) {
        int length = r.nextBoolean() ? longLineChars : 1000 + r.nextInt(100_000);
        byte[] line = new byte[length + 2];
        Arrays.fill(line, (byte) (r.nextBoolean() ? '9' : 'x'));
        line[0] = '\n';
        line[line.length - 1] = '\n';
        return insert(b, r, line);
    }

    private static byte[] insert(byte[] b, Random r, byte[] piece) {
        int at = b.length == 0 ? 0 : r.nextInt(b.length + 1);
        ByteArrayOutputStream out = new ByteArrayOutputStream(b.length + piece.length);
        out.write(b, 0, at);
        out.writeBytes(piece);
        out.write(b, at, b.length - at);
        return out.toByteArray();
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] out = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    private static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    /** Bytes of text decoded as ISO-8859-1 (one char per byte), so any byte survives the round trip. */
    private static byte[] latin1(String s) {
        return s.getBytes(StandardCharsets.ISO_8859_1);
    }
}
