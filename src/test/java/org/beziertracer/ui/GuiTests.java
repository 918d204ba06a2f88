package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.fail;

import java.awt.GraphicsEnvironment;

import org.junit.jupiter.api.Assumptions;

/**
 * Whether GUI tests may run. Without a display they are skipped with a message — unless the
 * system property {@value #REQUIRED} is true (CI sets it), in which case they fail: a CI run
 * cannot pass by skipping them.
 */
final class GuiTests {
    private GuiTests() {}

    /** {@code -Dgui.required=true}: no display is a failure, not a skip. */
    static final String REQUIRED = "gui.required";

    static final String NO_DISPLAY = "GUI test skipped: no display (java.awt is headless); "
            + "run under xvfb-run to include it";

    /** Call first in every GUI test (or its set-up). */
    static void requireDisplay() {
        if (!GraphicsEnvironment.isHeadless()) {
            return;
        }
        if (Boolean.getBoolean(REQUIRED)) {
            fail("GUI tests are required (-D" + REQUIRED + "=true) but there is no display: run under xvfb-run");
        }
        Assumptions.abort(NO_DISPLAY);
    }
}
