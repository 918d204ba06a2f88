package org.beziertracer.model.io;

import java.io.IOException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryIteratorException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * The path a file name given by the user (an argument, a dialog's choice, a recent file) stands
 * for, also under a locale whose encoding is not UTF-8.
 *
 * <p>Under {@code LANG=C} Java 17 decodes file names and command-line arguments as ASCII
 * ({@code sun.jnu.encoding}, which {@code -D} cannot change): {@code théière.bpt} arrives as
 * {@code th\uFFFD\uFFFDi\uFFFD\uFFFDre.bpt}, which {@link Path#of} refuses, since it cannot encode it
 * back. Listing the folder decodes the names on disk the same way, and the listed path keeps the
 * name's real bytes, so an <em>existing</em> file is found by comparing names as listed
 * (the only such entry; with two that read alike, none). A new file of such a name cannot be made:
 * {@link #invalidName()} says why and what to change. Stateless and thread-safe.
 */
public final class FilePaths {
    private FilePaths() {}

    /**
     * The path {@code name} stands for.
     *
     * @throws ModelFormatException {@code name: not a valid file name …} ({@link #invalidName()})
     */
    public static Path of(String name) {
        return find(name).orElseThrow(() -> new ModelFormatException(name, invalidName()));
    }

    /** The path {@code name} stands for, or empty when it is none (see {@link #of}). */
    public static Optional<Path> find(String name) {
        return find(null, name);
    }

    /**
     * The path {@code name} stands for relative to {@code dir} (a name read from a file: a scene's
     * model, an OBJ {@code call}); {@code dir} null: the working directory. Empty when it is none.
     */
    public static Optional<Path> find(Path dir, String name) {
        try {
            return Optional.of(dir == null ? Path.of(name) : dir.resolve(name));
        } catch (InvalidPathException e) {
            String listed = asListed(name);
            Path start = listed.startsWith("/") ? Path.of("/") : dir == null ? Path.of("") : dir;
            return existing(start, listed);
        }
    }

    /**
     * The existing file whose path reads {@code listed} when its folders are listed, found one
     * part at a time; empty when a part matches no entry or more than one.
     */
    private static Optional<Path> existing(Path start, String listed) {
        Path at = start;
        for (String part : listed.split("/")) {
            if (part.isEmpty()) {
                continue;
            }
            Path next;
            try {
                next = at.resolve(part);
            } catch (InvalidPathException e) {
                next = onlyEntry(at, part);
            }
            if (next == null) {
                return Optional.empty();
            }
            at = next;
        }
        return Files.exists(at) ? Optional.of(at) : Optional.empty();
    }

    /** {@code dir}'s one entry whose name reads {@code listed}, or null. */
    private static Path onlyEntry(Path dir, String listed) {
        Path found = null;
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(dir.toString().isEmpty() ? Path.of(".") : dir)) {
            for (Path entry : entries) {
                if (entry.getFileName().toString().equals(listed)) {
                    if (found != null) {
                        return null; // two names read alike: refuse rather than guess
                    }
                    found = dir.resolve(entry.getFileName());
                }
            }
        } catch (IOException | DirectoryIteratorException e) {
            return null;
        }
        return found;
    }

    /**
     * {@code name} as a folder listing shows it: unchanged when it already came through the
     * locale's encoding (an argument: it holds U+FFFD), else its UTF-8 bytes decoded in that
     * encoding (a name read from a UTF-8 file, such as a scene's model path).
     */
    private static String asListed(String name) {
        if (name.indexOf('\uFFFD') >= 0) {
            return name;
        }
        try {
            return new String(name.getBytes(StandardCharsets.UTF_8), Charset.forName(encoding()));
        } catch (IllegalArgumentException e) {
            return name;
        }
    }

    private static String encoding() {
        return System.getProperty("sun.jnu.encoding", "UTF-8");
    }

    /**
     * The file name of {@code p} as its owner wrote it, for titles and messages: under a non-UTF-8
     * locale a listed name reads {@code th\uFFFD\uFFFDi\uFFFD\uFFFDre.bpt}, but the path's URI keeps
     * the real bytes, so their UTF-8 reading gives back {@code théière.bpt} (bytes that are not
     * UTF-8 keep the listed name). The whole path when it has no file name.
     */
    public static String name(Path p) {
        Path file = p.getFileName();
        if (file == null) {
            return p.toString();
        }
        String listed = file.toString();
        if (listed.indexOf('\uFFFD') < 0) {
            return listed;
        }
        String raw = p.toAbsolutePath().toUri().getRawPath();
        raw = raw.substring(raw.lastIndexOf('/', raw.length() - 2) + 1).replaceAll("/$", "");
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        for (int k = 0; k < raw.length(); k++) {
            char c = raw.charAt(k);
            if (c == '%' && k + 2 < raw.length()) {
                bytes.write(Integer.parseInt(raw.substring(k + 1, k + 3), 16));
                k += 2;
            } else {
                bytes.write(c);
            }
        }
        try {
            return StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(bytes.toByteArray())).toString();
        } catch (java.nio.charset.CharacterCodingException e) {
            return listed;
        }
    }

    /**
     * The whole path {@code p} as its owner wrote it, for messages: {@link Path#toString()} where
     * that holds no U+FFFD, else each part read back as {@link #name} reads a file name, so that
     * under a non-UTF-8 locale a message says {@code modèles/tépot.bpt}, not
     * {@code mod\uFFFD\uFFFDles/t\uFFFD\uFFFDpot.bpt}.
     */
    public static String text(Path p) {
        String listed = p.toString();
        if (listed.indexOf('\uFFFD') < 0) {
            return listed;
        }
        StringBuilder sb = new StringBuilder(p.getRoot() == null ? "" : p.getRoot().toString());
        for (int k = 0; k < p.getNameCount(); k++) {
            if (k > 0) {
                sb.append(p.getFileSystem().getSeparator());
            }
            sb.append(name(p.getName(k)));
        }
        return sb.toString();
    }

    /**
     * Why a name is no valid path: under a locale whose encoding is not UTF-8 ({@code LANG=C}),
     * Java can neither make nor (except for existing files, see {@link #find}) name a file with
     * other than ASCII letters; that is what to change, not the name.
     */
    public static String invalidName() {
        String encoding = encoding();
        if (!encoding.equalsIgnoreCase("UTF-8") && !encoding.equalsIgnoreCase("UTF8")) {
            return "not a valid file name in this locale's encoding (" + encoding + "): Java cannot pass on a name"
                    + " with other than ASCII characters; run with a UTF-8 locale, e.g. LC_ALL=C.UTF-8";
        }
        return "not a valid file name";
    }
}
