package org.beziertracer.cli;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;

/**
 * The encoding of this process's messages on standard output and standard error.
 *
 * <p>Java takes it from the locale, so under {@code LANG=C} (the default of many containers, cron
 * jobs and ssh sessions) Java 17 writes ASCII, and a message naming {@code tépot.bpt} prints
 * {@code t?pot.bpt}. ASCII is the one encoding in which Java loses a name's bytes: where the
 * locale says ASCII, the names on disk are, in practice, UTF-8 (the encoding of every current
 * Linux and macOS desktop, and the one {@link org.beziertracer.model.io.FilePaths} reads them in),
 * and so is the terminal. So where Java picked ASCII we write UTF-8: ASCII text has the same bytes
 * in both, and a name is printed with the bytes it has on disk, which {@code ls} and a copy-paste
 * from the terminal give back. Any other encoding (ISO-8859-1, say) is the user's real choice: the
 * JVM read the names in it, and writing in it gives their bytes back, so it is kept. An encoding set
 * with {@code -Dsun.stdout.encoding} / {@code -Dstdout.encoding} (the launcher's) is taken as Java
 * takes it. Stateless and thread-safe.
 */
public final class ConsoleEncoding {
    private ConsoleEncoding() {}

    /** The charset for standard output: Java's, except UTF-8 where Java's is ASCII. */
    public static Charset stdout() {
        return forMessages(javaCharset("stdout"));
    }

    /** The charset for standard error: Java's, except UTF-8 where Java's is ASCII. */
    public static Charset stderr() {
        return forMessages(javaCharset("stderr"));
    }

    /** {@code java} itself, or UTF-8 when {@code java} is ASCII (see the class comment). */
    static Charset forMessages(Charset java) {
        return java.equals(StandardCharsets.US_ASCII) ? StandardCharsets.UTF_8 : java;
    }

    /**
     * Replaces {@code System.out} and {@code System.err} with streams in {@link #stdout()} and
     * {@link #stderr()} where those differ from Java's own choice, so that every message of the
     * process (the app's on standard error too) prints names intact. Call first in {@code main}.
     */
    public static void install() {
        if (!stdout().equals(javaCharset("stdout"))) {
            System.setOut(stream(FileDescriptor.out, stdout()));
        }
        if (!stderr().equals(javaCharset("stderr"))) {
            System.setErr(stream(FileDescriptor.err, stderr()));
        }
    }

    private static PrintStream stream(FileDescriptor fd, Charset charset) {
        OutputStream out = new FileOutputStream(fd);
        return new PrintStream(new java.io.BufferedOutputStream(out, 8192), true, charset);
    }

    /**
     * The charset Java gives {@code System.out} or {@code System.err} ({@code which} is
     * {@code stdout} or {@code stderr}): {@code stdout.encoding} (Java 19+), else
     * {@code sun.stdout.encoding}, else the default charset (Java 17 without a terminal).
     */
    static Charset javaCharset(String which) {
        for (String key : new String[] {which + ".encoding", "sun." + which + ".encoding"}) {
            String name = System.getProperty(key);
            if (name != null) {
                try {
                    return Charset.forName(name);
                } catch (IllegalArgumentException e) {
                    // Java falls back to the default charset for an unknown name, and so do we
                }
            }
        }
        return Charset.defaultCharset();
    }
}
