package org.beziertracer.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.beziertracer.UserMessages;

/** Scripted {@link UserDialogs} for controller tests: records errors, answers prompts as told. */
final class FakeDialogs implements UserDialogs {
    final List<String> errors = new ArrayList<>();
    Path open;
    Path save;
    Choice discard = Choice.CANCEL;
    int prompts;
    /** The export options the dialog answers with (null: cancelled); the last offer is kept. */
    ExportOptions export;
    ExportOptions offered;

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
