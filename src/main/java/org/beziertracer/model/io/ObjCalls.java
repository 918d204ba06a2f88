package org.beziertracer.model.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The OBJ {@code call FILE.obj} statement: the files open in one read, outermost first, and the
 * checks before another is opened. A called file is named relative to the folder of the file that
 * calls it (the working directory for text without a folder) and read as if its statements stood
 * in place of the call: one vertex list, numbered on across the files (Wavefront, <i>Object Files
 * (.obj)</i>, "call"). Refused, each with one sentence naming the files: a cycle (a file that
 * calls itself, directly or through others), calls nested deeper than {@link #MAX_DEPTH}, more than
 * {@link #MAX_CALLS} calls in one read, arguments ({@code $1} substitution is not supported) and
 * anything but an {@code .obj} file. One per read; not thread-safe.
 */
final class ObjCalls {

    /** Deepest nesting of calls: the file opened holds calls, theirs hold calls, … this many levels. */
    static final int MAX_DEPTH = 8;
    /** Most files called in one read (a file may call another many times, and so may that one). */
    static final int MAX_CALLS = 10_000;

    /** An open file: its name in messages, its normalized absolute path (null for text without a file) and folder. */
    private record Open(String name, Path key, Path dir, InputStream in) {}

    private final List<Open> open = new ArrayList<>();
    private int calls;

    /** @param baseDir the folder of the file read first (null: the working directory) */
    ObjCalls(String fileName, Path baseDir) {
        Path key = null;
        if (baseDir != null) {
            try {
                Path name = Path.of(fileName).getFileName();
                key = name == null ? null : baseDir.resolve(name).toAbsolutePath().normalize();
            } catch (InvalidPathException e) {
                key = null; // a name that is no path (in-memory text): it cannot be called again
            }
        }
        open.add(new Open(fileName, key, baseDir, null));
    }

    /** The name of the file being read, for messages. */
    String current() {
        return open.get(open.size() - 1).name();
    }

    /**
     * Opens the file a {@code call} statement {@code t} names, after the checks.
     *
     * @return the text to read, named as the path to it
     * @throws ModelFormatException on the calling line, naming the problem and the files
     */
    TextSource enter(String[] t, int line, ReadLimits limits) {
        String caller = current();
        if (t.length < 2) {
            throw new ModelFormatException(caller, line, "expected a file name after call, found none");
        }
        if (t.length > 2) {
            throw new ModelFormatException(caller, line, "unsupported: call with arguments ($1 substitution); "
                    + "call FILE.obj without arguments is read");
        }
        String name = t[1];
        if (!name.toLowerCase(Locale.ROOT).endsWith(".obj")) {
            throw new ModelFormatException(caller, line, "expected an .obj file after call, found " + Echo.quote(name)
                    + " (only OBJ text files can be called)");
        }
        Path dir = open.get(open.size() - 1).dir();
        Path file = FilePaths.find(dir, name).orElseThrow(() -> new ModelFormatException(caller, line,
                FilePaths.invalidName() + " after call: " + Echo.quote(name)));
        Path key = file.toAbsolutePath().normalize();
        for (int k = 0; k < open.size(); k++) {
            if (key.equals(open.get(k).key())) {
                throw new ModelFormatException(caller, line, "refused: a call cycle, " + chain(k, file.toString())
                        + " (a file may not call itself, directly or through other files)");
            }
        }
        if (open.size() > MAX_DEPTH) {
            throw new ModelFormatException(caller, line, "refused: calls nested more than " + MAX_DEPTH + " deep, "
                    + chain(0, file.toString()));
        }
        if (++calls > MAX_CALLS) {
            throw new ModelFormatException(caller, line, "refused: more than " + MAX_CALLS
                    + " calls in one read (a file and the files it calls)");
        }
        if (!Files.isRegularFile(file)) {
            throw new ModelFormatException(caller, line, "no such file " + Echo.quote(name) + " to call"
                    + (dir == null ? "" : " in " + dir));
        }
        try {
            long size = Files.size(file);
            InputStream in = Files.newInputStream(file);
            open.add(new Open(file.toString(), key, key.getParent(), in));
            return new TextSource(in, file.toString(), limits, size);
        } catch (IOException e) {
            throw new ModelFormatException(caller, line, "cannot read the called file " + Echo.quote(name) + ": "
                    + IoReasons.of(e));
        }
    }

    /** The called file has been read (or its reading failed): it is closed, and its caller is current again. */
    void leave() throws IOException {
        open.remove(open.size() - 1).in().close();
    }

    /** {@code a.obj calls b.obj, which calls c.obj} from open file {@code from}, then {@code next}. */
    private String chain(int from, String next) {
        StringBuilder sb = new StringBuilder(open.get(from).name());
        for (int k = from + 1; k < open.size(); k++) {
            sb.append(k == from + 1 ? " calls " : ", which calls ").append(open.get(k).name());
        }
        return sb.append(open.size() == from + 1 ? " calls " : ", which calls ").append(next).toString();
    }
}
