package org.beziertracer.model.io;

/**
 * A model file could not be read: bad syntax, a wrong count, a value out of range, an unsupported
 * element, a missing file. The message is always <b>one line</b> of the form
 * {@code file:line: expected …, found …} (or {@code file: …} when no line applies), so the
 * command line and the app can show it as is.
 *
 * <p>It is an {@link IllegalArgumentException} because the input, not the program, is at fault.
 */
public final class ModelFormatException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    private final String fileName;
    private final int line;
    private final String detail;

    /**
     * @param fileName the file name as the user gave it (shown first)
     * @param line     1-based line number, or 0 when the problem concerns the whole file
     * @param detail   what was expected and what was found
     */
    public ModelFormatException(String fileName, int line, String detail) {
        super(oneLine((line > 0 ? fileName + ":" + line : fileName) + ": " + detail));
        this.fileName = fileName;
        this.line = line;
        this.detail = detail;
    }

    /** A problem with the whole file (no line number), e.g. a missing file. */
    public ModelFormatException(String fileName, String detail) {
        this(fileName, 0, detail);
    }

    /** The file name as given by the caller. */
    public String fileName() { return fileName; }

    /** 1-based line number, or 0 when the problem concerns the whole file. */
    public int line() { return line; }

    /** The message without the {@code file:line: } prefix. */
    public String detail() { return detail; }

    private static String oneLine(String s) {
        return s.replace("\r", " ").replace('\n', ' ');
    }
}
