package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Reader;

/**
 * Splits a BPT stream into whitespace-separated tokens, dropping {@code #} comments (to the end
 * of the line) and remembering the 1-based line of each token. Streams; never reads the whole
 * file into memory.
 */
final class BptTokenizer {

    private final Reader in;
    private int line = 1;
    private int tokenLine = 1;
    private int pushedBack = -2;

    BptTokenizer(Reader in) {
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
                while (c != -1 && c != '\n') {
                    c = read();
                }
            } else if (Character.isWhitespace(c)) {
                c = read();
            } else {
                break;
            }
        }
        tokenLine = line;
        StringBuilder sb = new StringBuilder();
        while (c != -1 && c != '#' && !Character.isWhitespace(c)) {
            if (sb.length() < 1024) {
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
        int c = in.read();
        if (c == '\n') {
            line++;
        }
        return c;
    }
}
