package org.beziertracer.cli;

import java.io.PrintWriter;

import org.beziertracer.model.io.SceneDocument;

/**
 * Shows the reader's notes of an opened file ({@link SceneDocument#notes()}: what it read past
 * without drawing) once, one {@code note: …} line each: {@code info} on standard output among its
 * figures, {@code render}, {@code trace} and {@code analyze} on standard error, so a picture, a
 * hit list or a JSON line on standard output stays as it was.
 */
final class ReadNotes {
    private ReadNotes() {}

    /** Prints the notes of {@code doc} to {@code to} and returns {@code doc}. */
    static SceneDocument show(SceneDocument doc, PrintWriter to) {
        for (String note : doc.notes()) {
            to.println("note: " + note);
        }
        to.flush();
        return doc;
    }
}
