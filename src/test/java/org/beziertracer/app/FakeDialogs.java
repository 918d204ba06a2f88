package org.beziertracer.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.beziertracer.UserMessages;

/** Scripted {@link UserDialogs} for controller tests: records errors, answers prompts as told. */
public final class FakeDialogs implements UserDialogs {
    /** The errors shown (the app may show one from any of its threads' callbacks). */
    final List<String> errors = java.util.Collections.synchronizedList(new ArrayList<>());
    Path open;
    Path save;
    Choice discard = Choice.CANCEL;
    int prompts;
    /** The export options the dialog answers with (null: cancelled); the last offer is kept. */
    ExportOptions export;
    ExportOptions offered;

    /** A copy of {@link #errors}. */
    List<String> errors() {
        synchronized (errors) {
            return List.copyOf(errors);
        }
    }

    @Override
    public Path chooseOpen() { return open; }

    @Override
    public Path chooseSave(String title, String... extensions) { return save; }

    @Override
    public Choice confirmDiscard(String documentName) {
        prompts++;
        return discard;
    }

    @Override
    public void error(String title, String message) { errors.add(UserMessages.check(message)); }

    @Override
    public ExportOptions exportOptions(ExportOptions offer) {
        offered = offer;
        return export;
    }
}
