package org.beziertracer.app;

import java.nio.file.Path;

/** The questions the controller asks the user; swapped out in tests. Event thread only. */
public interface UserDialogs {

    /** Answer to "save your changes?". */
    enum Choice { SAVE, DISCARD, CANCEL }

    /** A file to open, or null when cancelled. */
    Path chooseOpen();

    /**
     * A file to write, or null when cancelled.
     *
     * @param title      dialog title
     * @param extensions accepted extensions, the first the default
     */
    Path chooseSave(String title, String... extensions);

    /** Unsaved edits: save, discard or cancel? */
    Choice confirmDiscard(String documentName);

    /** Shows an error: a title and the one-line message. */
    void error(String title, String message);

    /**
     * File → Export Image…: the size, samples per pixel and sampler, starting from {@code offer};
     * null when cancelled.
     */
    ExportOptions exportOptions(ExportOptions offer);

    /**
     * View → Analysis → Analysis Settings…: the analysis views' settings, starting from
     * {@code current}; null when cancelled (or when there is no one to ask).
     */
    default org.beziertracer.render.Analysis analysisSettings(org.beziertracer.render.Analysis current) { return null; }
}
