package org.beziertracer.model.io;

import java.io.IOException;

/**
 * Splits BPT text into whitespace-separated tokens, dropping {@code #} comments (to the end of
 * the line) and remembering the 1-based line of each token. Streams: holds one token (at most
 * {@value #MAX_TOKEN_CHARS} characters are kept; a longer one is reported by its start), never a
 * line or the file.
 */
final class BptTokenizer {

    /** Characters of a token kept for its message; more are read but dropped. */
    static final int MAX_TOKEN_CHARS = 1024;

    private final TextSource in;
    private int tokenLine = 1;
    private int pushedBack = -2;

    BptTokenizer(TextSource in) {
        this.in = in;
    }

    /** The next token, or null at the end of the input. */
    String next() throws IOException {
        int c = read();
        while (true) {
            if (c == -1) {
                return null;
            }
            if (c == '#') {
                while (c != -1 && c != '\n' && c != '\r') {
                    c = read();
                }
            } else if (Character.isWhitespace(c)) {
                c = read();
            } else {
                break;
            }
        }
        tokenLine = in.line();
        StringBuilder sb = new StringBuilder();
        while (c != -1 && c != '#' && !Character.isWhitespace(c)) {
            if (sb.length() < MAX_TOKEN_CHARS) {
                sb.append((char) c);
            }
            c = read();
        }
        if (c == '#') {
            pushedBack = c;
        }
        return sb.toString();
    }

    /** Line of the token last returned by {@link #next()} (1 before any token). */
    int line() {
        return tokenLine;
    }

    private int read() throws IOException {
        if (pushedBack != -2) {
            int c = pushedBack;
            pushedBack = -2;
            return c;
        }
        return in.read();
    }
}
