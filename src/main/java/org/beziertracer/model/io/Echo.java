package org.beziertracer.model.io;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Input echoed back in a message: cut to {@value #MAX_CHARS} characters and kept on one line, so
 * a 10 MB key or a binary line never floods a message. Stateless.
 */
public final class Echo {
    private Echo() {}

    /** Most characters of input a message shows (a cut text ends in {@code …}). */
    public static final int MAX_CHARS = 60;

    /**
     * {@code text} with line breaks and other control characters shown as escapes such as {@code \\u000A}, cut to
     * at most {@value #MAX_CHARS} characters (code points), the last one {@code …} when cut.
     */
    public static String cut(String text) {
        StringBuilder sb = new StringBuilder(Math.min(text.length(), MAX_CHARS) + 8);
        int shown = 0;
        for (int i = 0; i < text.length(); ) {
            int cp = text.codePointAt(i);
            int next = i + Character.charCount(cp);
            boolean hidden = Character.isISOControl(cp) || cp == 0x2028 || cp == 0x2029 || cp == 0xFEFF;
            String piece = hidden ? String.format(Locale.ROOT, "\\u%04X", cp) : Character.toString(cp);
            int width = hidden ? piece.length() : 1;
            if (shown + width > (next >= text.length() ? MAX_CHARS : MAX_CHARS - 1)) {
                return sb.append('…').toString();
            }
            sb.append(piece);
            shown += width;
            i = next;
        }
        return sb.toString();
    }

    private static final Pattern QUOTED = Pattern.compile("(['\"])([^'\"]{" + (MAX_CHARS + 1) + ",})\\1");

    /**
     * {@code message} with every quoted run ({@code '…'} or {@code "…"}) longer than
     * {@value #MAX_CHARS} characters {@link #cut}: a safety net for messages built by code that
     * echoes input without {@link #quote} (validation in the model records, option parsers).
     */
    public static String cutQuoted(String message) {
        return QUOTED.matcher(message)
                .replaceAll(m -> Matcher.quoteReplacement(m.group(1) + cut(m.group(2)) + m.group(1)));
    }

    /** {@link #cut} in double quotes: {@code "abc"}. */
    public static String quote(String text) {
        return "\"" + cut(text) + "\"";
    }
}
