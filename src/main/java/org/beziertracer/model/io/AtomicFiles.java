package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * Saves a file atomically: the content goes to a temporary file in the target's directory, which
 * then replaces the target with {@link StandardCopyOption#ATOMIC_MOVE} (falling back to a plain
 * replacing move where the file system cannot do that). A reader never sees a half-written file,
 * and a failed save leaves the old file untouched and no temporary file behind.
 */
public final class AtomicFiles {
    private AtomicFiles() {}

    /** Writes the content into a {@link Writer}; may throw {@link IOException}. */
    @FunctionalInterface
    public interface Content {
        void writeTo(Writer out) throws IOException;
    }

    /** Writes {@code content} as UTF-8 to {@code target}, atomically replacing any existing file. */
    public static void write(Path target, Content content) throws IOException {
        Path absolute = target.toAbsolutePath();
        Path dir = absolute.getParent();
        Path temp = Files.createTempFile(dir, "." + absolute.getFileName() + ".", ".tmp");
        boolean moved = false;
        try {
            try (Writer out = Files.newBufferedWriter(temp, StandardCharsets.UTF_8)) {
                content.writeTo(out);
            }
            try {
                Files.move(temp, absolute, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, absolute, StandardCopyOption.REPLACE_EXISTING);
            }
            moved = true;
        } finally {
            if (!moved) {
                Files.deleteIfExists(temp);
            }
        }
    }

    /** The text {@code content} writes, for writers that also offer a {@code toString} form. */
    public static String toText(Content content) {
        java.io.StringWriter out = new java.io.StringWriter();
        try {
            content.writeTo(out);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        return out.toString();
    }
}
