package org.beziertracer.ui;

import java.nio.file.Path;

/**
 * Run in a child JVM by {@link ModelTooBigTest}: opens {@code args[0]} in a controller with fake
 * dialogs and prints whether it opened, the error dialogs' texts and the patch count after.
 */
public final class OpenTooBigProbe {
    private OpenTooBigProbe() {}

    public static void main(String[] args) {
        FakeDialogs dialogs = new FakeDialogs();
        AppController c = new AppController(new FakeEngine(), dialogs);
        int before = c.scene().patchCount();
        boolean opened = c.open(Path.of(args[0]));
        System.out.println("opened=" + opened);
        System.out.println("patches=" + before + "->" + c.scene().patchCount());
        for (String e : dialogs.errors) {
            System.out.println("error=" + e);
        }
    }
}
