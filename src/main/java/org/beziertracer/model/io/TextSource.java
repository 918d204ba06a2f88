package org.beziertracer.model.io;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.InterruptedIOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * The text of one file, as every reader (BPT, OBJ, scene JSON, ray files) sees it: UTF-8 decoded
 * with errors reported, not replaced — a file that is not UTF-8 is
 * {@code file: not a text file (invalid UTF-8 at byte N)}, N counting from 0 — a leading
 * byte-order mark skipped, lines ending in LF, CRLF or a lone CR, and the caps of
 * {@link ReadLimits}: no line longer than {@link ReadLimits#lineChars()} is held in memory and
 * no file larger than {@link ReadLimits#bytesInMemory()} is read whole. Every problem is a one-line
 * {@link ModelFormatException} naming the file.
 *
 * <p>A read whose thread is interrupted (Cancel in the app) ends with an
 * {@link InterruptedIOException} before the next {@value #BUFFER} bytes are taken from the stream.
 *
 * <p>Read it one way: characters ({@link #read()}), lines ({@link #readLine()}, {@link #nextLine()}) or all at once
 * ({@link #readAll}). Does not close the stream. Not thread-safe.
 */
public final class TextSource {

    private static final int BUFFER = 1 << 14;

    private final InputStream in;
    private final String fileName;
    private final ReadLimits limits;
    private final long knownSize;
    private final CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
            .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
    private final ByteBuffer bytes = ByteBuffer.allocate(BUFFER).flip();
    private final CharBuffer chars = CharBuffer.allocate(BUFFER).flip();
    /** File offset of {@code bytes.array()[0]}. */
    private long offset;
    private boolean endOfInput;
    private boolean flushed;
    private boolean started;
    private int line = 1;
    private boolean afterCr;
    private int lineNumber;
    /** The line {@link #nextLine()} moved to: {@code lineChars[lineStart..lineEnd)}. */
    private char[] lineChars;
    private int lineStart, lineEnd;
    /** The characters of a line that crosses the end of {@link #chars}, joined. */
    private char[] spill = new char[256];

    /** Text of {@code in}, named {@code fileName} in messages, with the default caps. */
    public TextSource(InputStream in, String fileName) {
        this(in, fileName, ReadLimits.DEFAULT, -1);
    }

    /** Text of {@code in} with the given caps. */
    public TextSource(InputStream in, String fileName, ReadLimits limits) {
        this(in, fileName, limits, -1);
    }

    /** @param knownSize the file's size in bytes when known (so {@link #readAll} can refuse before reading), else -1 */
    TextSource(InputStream in, String fileName, ReadLimits limits, long knownSize) {
        this.in = in;
        this.fileName = fileName;
        this.limits = limits;
        this.knownSize = knownSize;
    }

    /** In-memory text (tests, built-in resources already in memory). */
    public static TextSource of(String text, String fileName) {
        return new TextSource(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), fileName);
    }

    /** The name every message starts with. */
    public String fileName() { return fileName; }

    public ReadLimits limits() { return limits; }

    /** The file's size in bytes when known, else -1. */
    public long knownSize() { return knownSize; }

    /** An error at {@code line} (0 = the whole file) of this file. */
    public ModelFormatException error(int line, String detail) {
        return new ModelFormatException(fileName, line, detail);
    }

    /**
     * The next character, or -1 at the end. Counts lines (see {@link #line()}); no line cap
     * applies, as nothing is held.
     */
    public int read() throws IOException {
        if (!chars.hasRemaining() && !fill()) {
            return -1;
        }
        char c = chars.get();
        count(c);
        return c;
    }

    /** Counts a line at each LF, CR or CR LF. */
    private void count(char c) {
        if (c == '\n') {
            if (!afterCr) {
                line++;
            }
            afterCr = false;
        } else if (c == '\r') {
            line++;
            afterCr = true;
        } else {
            afterCr = false;
        }
    }

    /**
     * The next characters into {@code dst}, as many as are decoded and fit (at least one), or -1
     * at the end: what as many {@link #read()} calls would give, lines counted alike, without a
     * call a character (the STEP tokenizer scans them as an array).
     */
    public int read(char[] dst) throws IOException {
        if (!chars.hasRemaining() && !fill()) {
            return -1;
        }
        int n = Math.min(dst.length, chars.remaining());
        chars.get(dst, 0, n);
        for (int k = 0; k < n; k++) {
            count(dst[k]);
        }
        return n;
    }

    /** 1-based line of the next character {@link #read()} returns (the line just started after a line end). */
    public int line() {
        return line;
    }

    /**
     * The next line without its end, or null at the end of the file.
     *
     * @throws ModelFormatException for a line longer than {@link ReadLimits#lineChars()}
     */
    public String readLine() throws IOException {
        return nextLine() ? new String(lineChars, lineStart, lineEnd - lineStart) : null;
    }

    /**
     * Moves to the next line without making a {@code String} of it: its characters, without the
     * line end, are then {@link #lineChars()}{@code [}{@link #lineStart()}{@code ..}{@link #lineEnd()}{@code )},
     * valid until the next read. What {@link #readLine()} does for readers of millions of lines
     * (an OBJ model's vertices), which parse the line where it lies.
     *
     * @return false at the end of the file
     * @throws ModelFormatException for a line longer than {@link ReadLimits#lineChars()}
     */
    public boolean nextLine() throws IOException {
        int spilled = -1; // characters of a line that crosses the buffer's end, copied to spill
        lineNumber = line;
        while (chars.hasRemaining() || fill()) {
            char[] a = chars.array();
            int start = chars.position(), end = start, limit = chars.limit();
            if (afterCr) {
                afterCr = false;
                if (a[start] == '\n') {
                    chars.position(start + 1); // the LF of a CRLF
                    continue;
                }
            }
            while (end < limit && a[end] != '\n' && a[end] != '\r') {
                end++;
            }
            if (spilled < 0 && end < limit && end - start <= limits.lineChars()) {
                chars.position(end + 1); // the whole line is in the buffer: read where it lies
                line++;
                afterCr = a[end] == '\r';
                return lineAt(a, start, end);
            }
            spilled = Math.max(spilled, 0);
            if (spilled + (end - start) > limits.lineChars()) {
                throw error(lineNumber, "line longer than " + limits.lineChars()
                        + " characters, the most a line may hold");
            }
            if (spilled + (end - start) > spill.length) {
                spill = Arrays.copyOf(spill, Math.max(spilled + (end - start), 2 * spill.length));
            }
            System.arraycopy(a, start, spill, spilled, end - start);
            spilled += end - start;
            if (end < limit) {
                chars.position(end + 1);
                line++;
                afterCr = a[end] == '\r';
                return lineAt(spill, 0, spilled);
            }
            chars.position(end);
        }
        return spilled >= 0 && lineAt(spill, 0, spilled);
    }

    private boolean lineAt(char[] a, int start, int end) {
        lineChars = a;
        lineStart = start;
        lineEnd = end;
        return true;
    }

    /** The array holding the line {@link #nextLine()} moved to (not a copy: read, never keep). */
    public char[] lineChars() { return lineChars; }

    /** Where that line starts in {@link #lineChars()}. */
    public int lineStart() { return lineStart; }

    /** Where that line ends (exclusive) in {@link #lineChars()}. */
    public int lineEnd() { return lineEnd; }

    /** 1-based line of the line {@link #readLine()} returned (or {@link #nextLine()} moved to) last. */
    public int lineNumber() {
        return lineNumber;
    }

    /**
     * The whole (rest of the) text.
     *
     * @param what what the file is, for the message when it is too large ({@code a scene file})
     * @throws ModelFormatException for a file larger than {@link ReadLimits#bytesInMemory()}
     */
    public String readAll(String what) throws IOException {
        long cap = limits.bytesInMemory();
        String capText = (cap >> 20) + " MB " + what + " may hold";
        if (knownSize > cap) {
            throw error(0, "the file holds " + knownSize + " bytes, more than the " + capText);
        }
        StringBuilder sb = new StringBuilder((int) Math.min(Math.max(knownSize, BUFFER), cap));
        while (chars.hasRemaining() || fill()) {
            if (offset + bytes.position() > cap) {
                throw error(0, "the file holds more than the " + capText);
            }
            sb.append(chars);
            chars.position(chars.limit());
        }
        return sb.toString();
    }

    /** Decodes more characters; false at the end of the input. */
    private boolean fill() throws IOException {
        if (flushed) {
            return false;
        }
        chars.clear();
        try {
            while (chars.position() == 0) {
                CoderResult r = decoder.decode(bytes, chars, endOfInput);
                if (r.isError()) {
                    throw notText(offset + bytes.position());
                }
                if (chars.position() > 0) {
                    break;
                }
                if (endOfInput) {
                    if (!flushed) {
                        flushed = true;
                        if (decoder.flush(chars).isError()) {
                            throw notText(offset + bytes.position());
                        }
                    }
                    break;
                }
                readBytes();
            }
        } finally {
            chars.flip();
        }
        if (!started && chars.hasRemaining()) {
            started = true;
            if (chars.get(chars.position()) == '\uFEFF') {
                chars.get(); // byte-order mark
                return chars.hasRemaining() || fill();
            }
        }
        return chars.hasRemaining();
    }

    private void readBytes() throws IOException {
        // A cancelled read (its thread interrupted) stops here, within one buffer, whatever the
        // stream: a file channel closes on interrupt, but a pipe, a socket or a generator does not
        if (Thread.currentThread().isInterrupted()) {
            throw new InterruptedIOException("the read was cancelled");
        }
        offset += bytes.position();
        bytes.compact();
        int n = in.read(bytes.array(), bytes.position(), bytes.remaining());
        if (n < 0) {
            endOfInput = true;
        } else {
            bytes.position(bytes.position() + n);
        }
        bytes.flip();
    }

    private ModelFormatException notText(long at) {
        return error(0, "not a text file (invalid UTF-8 at byte " + at + ")");
    }
}
