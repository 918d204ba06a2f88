package org.beziertracer.app;

import java.nio.file.Path;

/**
 * Run in a child JVM by {@link ModelTooBigTest}: opens {@code args[0]} in the app (every worker
 * inline) with fake dialogs and prints whether it opened, the error dialogs' texts and the patch
 * count after.
 */
public final class OpenTooBigProbe {
    private OpenTooBigProbe() {}

    public static void main(String[] args) {
        FakeDialogs dialogs = new FakeDialogs();
        AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());
        int before = app.document().scene().patchCount();
        app.files().open(Path.of(args[0]));
        boolean opened = !"patch".equals(app.document().name());
        System.out.println("opened=" + opened);
        System.out.println("patches=" + before + "->" + app.document().scene().patchCount());
        for (String e : dialogs.errors) {
            System.out.println("error=" + e);
        }
    }
}
