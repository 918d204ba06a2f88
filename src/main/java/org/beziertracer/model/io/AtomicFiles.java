package org.beziertracer.model.io;

import java.io.BufferedOutputStream;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * Saves a file atomically: the content goes to a temporary file {@code .NAME.DIGITS.tmp} in the
 * target's directory, which then replaces the target with {@link StandardCopyOption#ATOMIC_MOVE}
 * (falling back to a plain replacing move where the file system cannot do that). A reader never
 * sees a half-written file, and a failed save leaves the old file untouched and no temporary file
 * behind; a save first removes the temporary files a killed save of the same target left. A
 * symbolic link stays a link: the file it names is replaced. A target that is neither a file nor
 * a folder (a device such as {@code /dev/null}, a pipe) is written in place.
 *
 * <p>Every failure is one {@link IOException} line naming the target and the reason,
 * {@code teapot.bpt: cannot write: permission denied} ({@link IoReasons}), never the temporary file.
 */
public final class AtomicFiles {
    private AtomicFiles() {}

    /** Writes the content into a {@link Writer}; may throw {@link IOException}. */
    @FunctionalInterface
    public interface Content {
        void writeTo(Writer out) throws IOException;
    }

    /** Writes bytes to an {@link OutputStream}; may throw {@link IOException}. */
    @FunctionalInterface
    public interface BinaryContent {
        void writeTo(OutputStream out) throws IOException;
    }

    /** Writes {@code content} as UTF-8 to {@code target}, atomically replacing any existing file. */
    public static void write(Path target, Content content) throws IOException {
        writeBytes(target, out -> {
            Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8));
            content.writeTo(w);
            w.flush();
        });
    }

    /**
     * Writes {@code content} to a temporary file beside {@code target}, then moves it over the
     * target (atomically where the file system can). The target keeps its POSIX permissions; a
     * new file gets {@code rw-r--r--}. On failure the old file is untouched and the temporary
     * file removed. A missing folder is a one-line {@link IOException} naming it.
     */
    public static void writeBytes(Path target, BinaryContent content) throws IOException {
        Path absolute = target.toAbsolutePath();
        Path dir = absolute.getParent();
        if (dir == null || absolute.getFileName() == null) {
            throw cannotWrite(target, "not a file name");
        }
        if (!Files.isDirectory(dir)) {
            throw cannotWrite(target, "the folder " + dir + " does not exist");
        }
        if (Files.isDirectory(absolute)) {
            throw cannotWrite(target, "is a folder");
        }
        if (Files.exists(absolute) && !Files.isRegularFile(absolute)) {
            writeInPlace(target, absolute, content);
            return;
        }
        if (Files.isSymbolicLink(absolute)) {
            // Replace the file the link names, not the link
            absolute = realPath(target, absolute);
            dir = absolute.getParent();
        }
        // A name that came through a non-UTF-8 locale (FilePaths) holds U+FFFD, which that locale
        // cannot encode in a new name: the temporary file replaces it
        String name = absolute.getFileName().toString().replace('\uFFFD', '_');
        Path temp = null;
        boolean moved = false;
        try {
            removeStaleTemporaries(dir, name);
            temp = Files.createTempFile(dir, "." + name + ".", ".tmp");
            try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(temp))) {
                content.writeTo(out);
            }
            keepPermissions(absolute, temp);
            try {
                Files.move(temp, absolute, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, absolute, StandardCopyOption.REPLACE_EXISTING);
            }
            moved = true;
        } catch (IOException e) {
            throw cannotWrite(target, IoReasons.of(e));
        } finally {
            if (!moved && temp != null) {
                deleteQuietly(temp);
            }
        }
    }

    /**
     * A device or a pipe ({@code /dev/null}, {@code /dev/stdout}, a FIFO): there is no old file to
     * keep and moving a file over it would replace the device itself, so the content goes straight in.
     */
    private static void writeInPlace(Path target, Path absolute, BinaryContent content) throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(absolute, StandardOpenOption.WRITE))) {
            content.writeTo(out);
        } catch (IOException e) {
            throw cannotWrite(target, IoReasons.of(e));
        }
    }

    private static Path realPath(Path target, Path link) throws IOException {
        try {
            return link.toRealPath();
        } catch (IOException e) {
            throw cannotWrite(target, "a link to a file that does not exist");
        }
    }

    /** {@code target: cannot write: reason}. */
    private static IOException cannotWrite(Path target, String reason) {
        return new IOException(FilePaths.text(target) + ": cannot write: " + reason);
    }

    /** Deletes {@code .NAME.DIGITS.tmp} files in {@code dir}: what a killed save of NAME left. */
    private static void removeStaleTemporaries(Path dir, String name) throws IOException {
        Pattern stale = Pattern.compile("\\." + Pattern.quote(name) + "\\.\\d+\\.tmp");
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir,
                p -> stale.matcher(p.getFileName().toString()).matches())) {
            for (Path p : files) {
                deleteQuietly(p);
            }
        }
    }

    private static void deleteQuietly(Path p) {
        try {
            Files.deleteIfExists(p);
        } catch (IOException e) {
            // Left for the next save of the same target to remove
        }
    }

    /** Temporary files are created private; give the new file the old file's (or ordinary) permissions. */
    private static void keepPermissions(Path target, Path temp) throws IOException {
        if (!Files.getFileStore(temp).supportsFileAttributeView(PosixFileAttributeView.class)) {
            return;
        }
        Set<PosixFilePermission> perms = Files.exists(target) ? Files.getPosixFilePermissions(target)
                : PosixFilePermissions.fromString("rw-r--r--");
        Files.setPosixFilePermissions(temp, perms);
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
