package org.beziertracer.model.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;

/**
 * One file format the program reads, and perhaps writes: its name, its extensions, what its files
 * hold, its reader and (when it has one) its writer. Every format is declared once, in
 * {@link FileFormats}; everything that opens or saves a file asks the registry.
 *
 * <p>A reader gets a {@link TextSource} (UTF-8 decoded with errors reported, a byte-order mark
 * skipped, lines and file size capped) and returns a {@link SceneDocument}; a model format's
 * reader and writer work on a {@link Scene}, and its files open with
 * {@link RenderSettings#defaults()}. Reading and writing through this class turn every failure
 * into one line naming the file: {@link ModelFormatException} on read, an {@link IOException}
 * naming the target and the reason on write ({@link AtomicFiles}). Immutable and thread-safe.
 */
public final class FileFormat {

    /** What a file of a format holds. */
    public enum Holds {
        /** Surfaces only (no lights, camera or settings): BPT, OBJ. */
        MODEL,
        /** A whole scene: models, materials, lights, camera, render settings. */
        SCENE
    }

    /** Reads a whole document; {@code baseDir} resolves relative references (null = working directory). */
    @FunctionalInterface
    public interface Reader {
        SceneDocument read(TextSource text, Path baseDir) throws IOException;
    }

    /** Writes a whole document as text to {@code out} (not closed), telling {@code progress} how far it got. */
    @FunctionalInterface
    public interface Writer {
        void write(java.io.Writer out, SceneDocument doc, WriteProgress progress) throws IOException;
    }

    /**
     * A model format's reader: surfaces only. {@code baseDir} resolves the files a file names
     * (OBJ {@code call}; null = the working directory). It adds to {@code notes} one line for each
     * thing worth telling that is not an error (what it read past without drawing, naming the file).
     */
    @FunctionalInterface
    public interface ModelReader {
        Scene read(TextSource text, Path baseDir, List<String> notes) throws IOException;
    }

    /** A model format's writer: the scene's surfaces only, telling {@code progress} the patches done. */
    @FunctionalInterface
    public interface ModelWriter {
        void write(java.io.Writer out, Scene scene, WriteProgress progress) throws IOException;
    }

    private final String name;
    private final String description;
    private final List<String> extensions;
    private final Holds holds;
    private final Reader reader;
    private final Writer writer;

    /**
     * @param name        short name shown to users ({@code BPT})
     * @param description what the files are, for file-dialog filters ({@code Bézier patch text})
     * @param extensions  lower-case extensions without the dot, the first the default
     * @param writer      null for a format that is only read
     */
    public FileFormat(String name, String description, List<String> extensions, Holds holds, Reader reader,
                      Writer writer) {
        if (extensions.isEmpty() || reader == null || holds == null) {
            throw new IllegalArgumentException("a format needs an extension, what it holds and a reader");
        }
        this.name = name;
        this.description = description;
        this.extensions = List.copyOf(extensions);
        this.holds = holds;
        this.reader = reader;
        this.writer = writer;
    }

    /** A model format (surfaces only): files open with default settings, no lights and no camera. */
    public static FileFormat model(String name, String description, List<String> extensions, ModelReader reader,
                                   ModelWriter writer) {
        return new FileFormat(name, description, extensions, Holds.MODEL,
                (text, baseDir) -> {
                    List<String> notes = new ArrayList<>();
                    Scene scene = reader.read(text, baseDir, notes);
                    return new SceneDocument(scene, RenderSettings.defaults(), notes);
                },
                writer == null ? null : (out, doc, progress) -> writer.write(out, doc.scene(), progress));
    }

    public String name() { return name; }

    public String description() { return description; }

    /** Lower-case extensions without the dot; the first is the one a save adds. */
    public List<String> extensions() { return extensions; }

    public Holds holds() { return holds; }

    public boolean canWrite() { return writer != null; }

    /** A file-dialog label: {@code Bézier patch text (*.bpt)}. */
    public String filterLabel() {
        return description + " (" + FileFormats.patterns(List.of(this)) + ")";
    }

    /** True when {@code path} ends in one of the extensions (any case). */
    public boolean matches(String path) {
        String lower = path.toLowerCase(Locale.ROOT);
        for (String ext : extensions) {
            if (lower.endsWith("." + ext)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Reads a file; errors name it as given ({@link FilePaths#text}), and relative references
     * resolve against its folder.
     *
     * @throws ModelFormatException one line naming the file, for any problem
     */
    public SceneDocument read(Path file) {
        String fileName = FilePaths.text(file);
        if (Files.isDirectory(file)) {
            throw new ModelFormatException(fileName, "is a folder, not a file");
        }
        if (!Files.exists(file)) {
            throw new ModelFormatException(fileName, "no such file");
        }
        // A pipe or a device (<(…), /dev/stdin) is read as it comes, its size unknown
        boolean regular = Files.isRegularFile(file);
        try {
            if (regular && this == FileFormats.OBJ) {
                HeapEstimates.requireObjVertexCount(file, fileName, ReadLimits.DEFAULT);
            }
        } catch (IOException e) {
            throw new ModelFormatException(fileName, "cannot read: " + IoReasons.of(e));
        }
        try (InputStream in = Files.newInputStream(file)) {
            return read(new TextSource(in, fileName, ReadLimits.DEFAULT, regular ? Files.size(file) : -1),
                    file.toAbsolutePath().getParent());
        } catch (IOException e) {
            throw new ModelFormatException(fileName, "cannot read: " + IoReasons.of(e));
        }
    }

    /**
     * Reads a stream (not closed).
     *
     * @param fileName shown at the start of every error message
     * @param baseDir  folder for relative references; null = the working directory
     * @throws ModelFormatException one line naming the file, for any problem
     */
    public SceneDocument read(InputStream in, String fileName, Path baseDir) {
        return read(new TextSource(in, fileName), baseDir);
    }

    private SceneDocument read(TextSource text, Path baseDir) {
        String fileName = text.fileName();
        try {
            SceneDocument doc = reader.read(text, baseDir);
            Extents.requireFinite(doc.scene());
            return doc;
        } catch (ModelFormatException e) {
            throw e;
        } catch (IOException e) {
            throw new ModelFormatException(fileName, "cannot read: " + IoReasons.of(e));
        } catch (InvalidPathException e) {
            throw new ModelFormatException(fileName, "not a valid file name: " + Echo.quote(e.getInput()));
        } catch (IllegalArgumentException e) {
            // A model record refused the data (e.g. a scene without patches)
            throw new ModelFormatException(fileName, e.getMessage());
        }
    }

    /** Saves {@code doc} atomically ({@link AtomicFiles}); errors name {@code file} and the reason. */
    public void write(Path file, SceneDocument doc) throws IOException {
        write(file, doc, WriteProgress.NONE);
    }

    /**
     * As {@link #write(Path, SceneDocument)}, telling {@code progress} the patches written; when it
     * throws, the save stops and the old file stays.
     */
    public void write(Path file, SceneDocument doc, WriteProgress progress) throws IOException {
        Writer w = requireWriter();
        AtomicFiles.write(file, out -> w.write(out, doc, progress));
    }

    /** The text a save would write. */
    public String toText(SceneDocument doc) {
        Writer w = requireWriter();
        return AtomicFiles.toText(out -> w.write(out, doc, WriteProgress.NONE));
    }

    private Writer requireWriter() {
        if (writer == null) {
            throw new IllegalArgumentException(name + " files can be read but not written");
        }
        return writer;
    }

    @Override
    public String toString() { return name; }
}
