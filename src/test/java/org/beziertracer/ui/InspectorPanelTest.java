package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Component;
import java.awt.Container;
import java.awt.Rectangle;

import javax.swing.SwingUtilities;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.AppThreads;
import org.beziertracer.app.FakeDialogs;
import org.beziertracer.app.FakeEngine;
import org.beziertracer.app.MemoryPreferences;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The inspector panel laid out at its real width (no window needed): a refused value's reason and
 * the hint are shown whole, wrapped, and the reason goes when the selection changes or a model is
 * opened.
 */
class InspectorPanelTest {

    private final AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());

    @AfterEach
    void close() { app.close(); }

    /** Lays the panel out at its preferred width, twice (wrapped text learns its width in the first pass). */
    private static void layOut(InspectorPanel p) {
        for (int pass = 0; pass < 2; pass++) {
            p.setSize(InspectorPanel.WIDTH, p.getPreferredSize().height + 400);
            p.invalidate();
            validateTree(p);
        }
    }

    private static void validateTree(Component c) {
        c.doLayout();
        if (c instanceof Container k) {
            for (Component child : k.getComponents()) {
                validateTree(child);
            }
        }
    }

    /** True when {@code t} shows all of its text: inside the panel's border and tall enough for every wrapped line. */
    private static void assertWhole(InspectorPanel p, WrappingText t, String what) {
        Rectangle r = SwingUtilities.convertRectangle(t.getParent(), t.getBounds(), p);
        var in = p.getInsets();
        Rectangle inside = new Rectangle(in.left, in.top, p.getWidth() - in.left - in.right, p.getHeight() - in.top - in.bottom);
        assertTrue(r.width > 20 && inside.contains(r), what + " at " + r + " lies within the panel's " + inside);
        assertTrue(t.getHeight() >= t.heightAt(t.getWidth()), what + ": " + t.getHeight() + " px tall, its wrapped lines need "
                + t.heightAt(t.getWidth()));
        assertTrue(t.getLineCount() >= 1);
    }

    @Test
    void theHintAndARefusalAreShownWholeAndTheRefusalClearsOnSelectionAndLoad() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            InspectorPanel p = new InspectorPanel(app);
            layOut(p);
            WrappingText where = (WrappingText) GuiDriver.find(p, "inspector.where");
            WrappingText message = (WrappingText) GuiDriver.find(p, "inspector.message");
            assertEquals(InspectorPanel.HINT, where.getText());
            assertWhole(p, where, "the hint");
            assertTrue(where.getHeight() > 3 * where.getFontMetrics(where.getFont()).getHeight(),
                    "the hint wraps to several lines: " + where.getHeight());
            app.selections().selectAll();
            javax.swing.JTextField x = (javax.swing.JTextField) GuiDriver.find(p, "inspector.x");
            x.setText("a number, five, 5.0e-3 or so");
            x.postActionEvent(); // Enter
            String refusal = app.inspector().message();
            assertTrue(refusal.length() > 40, refusal);
            layOut(p);
            assertEquals(refusal, message.getText(), "the whole reason, not cut");
            assertTrue(message.isVisible());
            assertWhole(p, message, "the refusal");
            assertEquals(refusal, message.getToolTipText());
            app.selections().clear();
            assertEquals("", message.getText(), "a new selection clears the refusal");
            assertFalse(message.isVisible());
            app.selections().selectAll();
            x.setText("?");
            x.postActionEvent();
            assertFalse(message.getText().isEmpty());
            app.files().openBuiltIn("teapot");
            assertEquals("", message.getText(), "opening a model clears the refusal");
        });
    }
}
