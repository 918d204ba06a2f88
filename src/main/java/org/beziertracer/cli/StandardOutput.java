package org.beziertracer.cli;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.nio.charset.Charset;

import org.beziertracer.model.io.IoReasons;

/**
 * Standard output for the commands: a {@link PrintWriter} straight over file descriptor 1 that
 * remembers why a write failed. {@code System.out} and picocli's default writer swallow errors
 * (a full disk, a closed pipe) and the command would exit 0 having written nothing; after a
 * command, {@link #failure} turns the writer's error flag into one line that says so,
 * {@code standard output: write failed (disk full)}. Not thread-safe beyond {@link PrintWriter}'s
 * own locking.
 */
final class StandardOutput extends PrintWriter {

    private final Recorder recorder;

    private StandardOutput(Recorder recorder, Charset charset) {
        super(new OutputStreamWriter(recorder, charset));
        this.recorder = recorder;
    }

    /** Standard output of this process, in the encoding {@link ConsoleEncoding#stdout()} chooses. */
    static StandardOutput system() {
        return over(new FileOutputStream(FileDescriptor.out), ConsoleEncoding.stdout());
    }

    /** A writer over {@code out} (for tests: a stream that fails). */
    static StandardOutput over(OutputStream out, Charset charset) {
        return new StandardOutput(new Recorder(out), charset);
    }

    /**
     * Null when everything written to {@code out} so far arrived (after a flush), else the line
     * {@code standard output: write failed (REASON)}; the reason is known when {@code out} is a
     * {@link StandardOutput}.
     */
    static String failure(PrintWriter out) {
        if (!out.checkError()) {
            return null;
        }
        IOException cause = out instanceof StandardOutput s ? s.recorder.first : null;
        return "standard output: write failed (" + (cause == null ? "input/output error" : IoReasons.of(cause)) + ")";
    }

    /** The exit code of a process the reader of its output has left: 128 + SIGPIPE, as a shell reports one the signal ended. */
    static final int EXIT_CLOSED_PIPE = 141;

    /**
     * True when writing to {@code out} failed because its reader has gone ({@code info … | head -1}):
     * the command then ends quietly, as Unix tools do (the signal SIGPIPE ends them), not with an
     * error line. "Broken pipe" on Linux and macOS, "The pipe is being closed" or "The pipe has been
     * ended" on Windows.
     */
    static boolean closedPipe(PrintWriter out) {
        if (!out.checkError() || !(out instanceof StandardOutput s) || s.recorder.first == null) {
            return false;
        }
        String m = String.valueOf(s.recorder.first.getMessage());
        return m.contains("Broken pipe") || m.contains("pipe is being closed") || m.contains("pipe has been ended");
    }

    /** Passes bytes through whole (not one by one, as {@link FilterOutputStream} would) and keeps the first failure. */
    private static final class Recorder extends FilterOutputStream {
        private IOException first;

        Recorder(OutputStream out) {
            super(out);
        }

        @Override
        public void write(int b) throws IOException {
            try {
                out.write(b);
            } catch (IOException e) {
                throw record(e);
            }
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            try {
                out.write(b, off, len);
            } catch (IOException e) {
                throw record(e);
            }
        }

        @Override
        public void flush() throws IOException {
            try {
                out.flush();
            } catch (IOException e) {
                throw record(e);
            }
        }

        private IOException record(IOException e) {
            if (first == null) {
                first = e;
            }
            return e;
        }
    }
}
