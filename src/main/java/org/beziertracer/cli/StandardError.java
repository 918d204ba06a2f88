package org.beziertracer.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.jline.terminal.spi.SystemStream;
import org.jline.terminal.spi.TerminalProvider;

/**
 * Whether this process's standard error is a terminal, and how wide it is. Java 17 has no
 * {@code isatty}: on Linux the link {@code /proc/self/fd/2} tells at once; elsewhere jline's
 * {@code exec} provider asks the shell ({@code test -t 2}), which costs a process start, so it is
 * only the fallback. Any doubt answers "not a terminal".
 */
final class StandardError {
    /** Columns assumed when the terminal does not say. */
    static final int DEFAULT_COLUMNS = 80;

    private StandardError() {}

    /** The width of the terminal on standard error, or 0 when standard error is not a terminal. */
    static int terminalColumns() {
        return isTerminal() ? columns() : 0;
    }

    static boolean isTerminal() {
        try {
            Path fd = Path.of("/proc/self/fd/2");
            if (Files.isSymbolicLink(fd)) {
                String target = Files.readSymbolicLink(fd).toString();
                return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
            }
            return TerminalProvider.load("exec").isSystemStream(SystemStream.Error);
        } catch (IOException | RuntimeException | LinkageError e) {
            return false;
        }
    }

    /** The terminal's width in columns (call only when {@link #isTerminal()}). */
    private static int columns() {
        try {
            int columns = TerminalProvider.load("exec").systemStreamWidth(SystemStream.Error);
            return columns > 0 ? columns : DEFAULT_COLUMNS;
        } catch (IOException | RuntimeException | LinkageError e) {
            return DEFAULT_COLUMNS;
        }
    }
}
