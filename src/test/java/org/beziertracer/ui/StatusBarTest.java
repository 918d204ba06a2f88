package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Container;
import java.awt.Rectangle;

import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.AppThreads;
import org.beziertracer.app.FakeDialogs;
import org.beziertracer.app.FakeEngine;
import org.beziertracer.app.MemoryPreferences;
import org.beziertracer.app.RenderStatus;
import org.beziertracer.app.Toggle;
import org.beziertracer.intersect.Method;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The status bar laid out as the window lays it out (the south of a {@code BorderLayout}), no
 * window needed: at the default 1370 px and narrower, every field with text is shown — whole, or
 * elided with its whole text in its tooltip — inside the bar.
 */
class StatusBarTest {

    private final AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());

    @AfterEach
    void close() { app.close(); }

    private static void layOut(Container c) {
        c.doLayout();
        for (Component child : c.getComponents()) {
            if (child instanceof Container k) {
                layOut(k);
            }
        }
    }

    /** Lays {@code bar} out in a window-like content pane {@code width} wide; returns the rows it takes. */
    private static int showAt(JPanel content, StatusBar bar, int width) {
        for (int pass = 0; pass < 2; pass++) {
            content.setSize(width, 800);
            content.invalidate();
            layOut(content);
        }
        int rowHeight = new JLabel("Xy").getPreferredSize().height;
        return Math.max(1, (bar.getHeight() - 4) / rowHeight);
    }

    private static void assertEveryFieldShown(StatusBar bar, int width) {
        int fields = 0;
        for (Component c : bar.getComponents()) {
            if (!(c instanceof JLabel l) || !l.isVisible() || l.getText().isBlank()) {
                continue;
            }
            fields++;
            String what = "\"" + l.getText() + "\" (" + l.getName() + ") at " + width + " px";
            Rectangle r = l.getBounds();
            assertTrue(r.x >= 0 && r.y >= 0 && r.x + r.width <= bar.getWidth() && r.y + r.height <= bar.getHeight(),
                    what + " at " + r + " lies inside the bar " + bar.getSize());
            assertTrue(r.width >= l.getPreferredSize().width || l.getToolTipText().contains(l.getText()),
                    what + ": whole, or elided with its text in the tooltip");
            assertTrue(r.width > 30 || r.width >= l.getPreferredSize().width, what + " is not squeezed to nothing");
        }
        assertTrue(fields >= 10, "the fields with text: " + fields);
    }

    @Test
    void atTheDefaultWidthAndNarrowerEveryFieldIsShownWrappedOrElided() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            StatusBar bar = new StatusBar(app);
            JPanel content = new JPanel(new BorderLayout());
            content.add(new JPanel(), BorderLayout.CENTER);
            content.add(bar, BorderLayout.SOUTH);
            app.edits().randomize(1234567);
            app.selections().selectAll();
            app.settings().set(Toggle.DIFFERENCE_TO_CLIPPING, true);
            app.status().report(new RenderStatus(4, 4, 918.6, 0.86, 1, Method.CLIPPING, true, 3.2, 12.5, 0));
            bar.refresh();
            int wide = showAt(content, bar, 1370);
            assertEveryFieldShown(bar, 1370);
            int oneRow = 0;
            for (Component c : bar.getComponents()) {
                oneRow += c.isVisible() ? c.getPreferredSize().width + 8 : 0;
            }
            for (int width : new int[] {1000, 700, 420, 160}) {
                int rows = showAt(content, bar, width);
                assertEveryFieldShown(bar, width);
                assertTrue(width >= oneRow || rows >= 2, "the fields (" + oneRow + " px) wrap at " + width + " px: " + rows
                        + " rows");
            }
            assertTrue(wide >= 1, "rows at 1370 px: " + wide);
        });
    }
}
