package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.swing.Action;
import javax.swing.SwingUtilities;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.AppThreads;
import org.beziertracer.app.FakeDialogs;
import org.beziertracer.app.FakeEngine;
import org.beziertracer.app.Level;
import org.beziertracer.app.MemoryPreferences;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The Surface commands are named for what they do: Replace with Flat u×v Grid, and Revert to Original beside it. */
class AppActionsTest {

    private final AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());

    @AfterEach
    void close() { app.close(); }

    @Test
    void theFlatGridIsNamedWithItsSizeAndRevertToOriginalIsOnlyOfferedAfterAnEdit() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            AppActions a = new AppActions(app, () -> null, () -> {}, () -> false, () -> {});
            Action grid = a.get("resetPoints"), revert = a.get("revertPoints");
            assertEquals("Replace with Flat 4×4 Grid", grid.getValue(Action.NAME));
            app.settings().set(Level.GRID_U, 6);
            assertEquals("Replace with Flat 6×4 Grid", grid.getValue(Action.NAME), "follows New grid u × v");
            assertEquals("Revert to Original", revert.getValue(Action.NAME));
            assertFalse(revert.isEnabled(), "nothing to revert in a model as opened");
            app.files().openBuiltIn("teapot");
            grid.actionPerformed(null);
            assertEquals(1, app.document().scene().patchCount());
            assertTrue(revert.isEnabled());
            revert.actionPerformed(null);
            assertEquals(32, app.document().scene().patchCount(), "the teapot back");
            assertFalse(revert.isEnabled());
            assertTrue(String.valueOf(revert.getValue(Action.SHORT_DESCRIPTION)).endsWith("(Ctrl+Alt+R)"));
        });
    }
}
