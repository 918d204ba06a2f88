package org.beziertracer.ui;

import java.awt.Point;
import java.awt.Rectangle;

import org.beziertracer.app.Settings;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;

/**
 * Shared set-up of the GUI test classes: one app per class, reset to the default patch and the
 * default settings before each test, closed after the class.
 */
abstract class GuiSession {

    static GuiDriver d;

    @BeforeAll
    static void start() throws Exception {
        d = GuiDriver.launch();
    }

    @AfterAll
    static void stop() {
        if (d != null) {
            d.dismissStrayWindows();
            d.close();
            d = null;
        }
    }

    @BeforeEach
    void reset() {
        d.dismissStrayWindows();
        defaultPatch();
    }

    /** Set-up plumbing (not under test): the default patch, default settings, home view. */
    static void defaultPatch() {
        GuiTests.requireDisplay();
        GuiDriver.onEdt(() -> {
            d.app.document().history().markSaved();
            d.app.settings().replace(Settings.defaults());
            d.app.files().openBuiltIn("patch");
        });
        d.settle();
    }

    /** The main window's title. */
    static String title() {
        return GuiDriver.onEdt(() -> d.frame.getTitle());
    }

    /** The picture once settled, with the mouse out of the way (no hovered handle). */
    static java.awt.image.BufferedImage shot() {
        d.mouseAway();
        d.settle();
        return d.capturePanel();
    }

    /** A box in the middle of the default patch, relative to the panel (screen pixels). */
    static Rectangle centreBox() {
        double x = 0, y = 0;
        for (int[] ij : new int[][] {{1, 1}, {2, 1}, {1, 2}, {2, 2}}) {
            Point p = d.inPanel(d.screenOfPoint(0, ij[0], ij[1]));
            x += p.x / 4.0;
            y += p.y / 4.0;
        }
        return new Rectangle((int) x - 20, (int) y + 10, 16, 12);
    }
}
