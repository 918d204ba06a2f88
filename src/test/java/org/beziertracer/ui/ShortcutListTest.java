package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.InputMap;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.AppThreads;
import org.beziertracer.app.FakeDialogs;
import org.beziertracer.app.FakeEngine;
import org.beziertracer.app.MemoryPreferences;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Help → Keyboard Shortcuts lists every bound key, generated from the actions and the window's bindings. */
class ShortcutListTest {

    private final AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());

    @AfterEach
    void close() { app.close(); }

    private AppActions actions() {
        return new AppActions(app, () -> new java.awt.image.BufferedImage(1, 1, java.awt.image.BufferedImage.TYPE_INT_RGB),
                () -> {}, () -> false, () -> {});
    }

    @Test
    void everyActionWithAnAcceleratorAndEveryExtraBindingIsListed() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            AppActions a = actions();
            InputMap keys = new InputMap();
            ActionMap table = new ActionMap();
            KeyStroke ctrlY = KeyStroke.getKeyStroke(KeyEvent.VK_Y, InputEvent.CTRL_DOWN_MASK);
            keys.put(ctrlY, "redo");
            table.put("redo", a.get("redo"));
            List<ShortcutList.Row> rows = ShortcutList.of(a.all().values(), keys, table);
            int accelerated = 0;
            for (Action action : a.all().values()) {
                KeyStroke k = (KeyStroke) action.getValue(Action.ACCELERATOR_KEY);
                if (k == null) {
                    continue;
                }
                accelerated++;
                String text = AppActions.keyText(k);
                String name = String.valueOf(action.getValue(Action.NAME)).strip();
                assertTrue(rows.stream().anyMatch(r -> r.keys().equals(text) && (name.isEmpty() || r.command().equals(name))
                        && !r.description().isBlank()), action.getValue("id") + " (" + text + ", " + name + ") is listed");
            }
            assertTrue(accelerated > 50, "the app binds many keys: " + accelerated);
            assertTrue(rows.contains(new ShortcutList.Row("Ctrl+Y", "Redo", "Redo the edit just undone")),
                    "the window's extra binding: " + rows.stream().filter(r -> r.keys().equals("Ctrl+Y")).toList());
            assertTrue(rows.stream().anyMatch(r -> r.keys().startsWith("X") && r.command().contains("Along X")), "axis keys");
            assertEquals(accelerated + 1 + 3, rows.size(), "no row twice, none made up");
            assertTrue(rows.stream().noneMatch(r -> r.command().isBlank()), "every row names its command (recent files too)");
            assertTrue(rows.contains(new ShortcutList.Row("Ctrl+3", "Open Recent File 3", "Open file 3 of File → Open Recent again")),
                    "a recent file's place, by number");
            var model = ShortcutsDialog.model(rows);
            assertEquals(3, model.getColumnCount());
            assertEquals(rows.size(), model.getRowCount());
            assertEquals("Ctrl+Y", model.getValueAt(rows.size() - 4, 0));
        });
    }

    @Test
    void helpHasAKeyboardShortcutsPageBesideAbout() throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            AtomicInteger shown = new AtomicInteger(), about = new AtomicInteger();
            AppMenuBar bar = new AppMenuBar(actions(), about::incrementAndGet, shown::incrementAndGet);
            JMenu help = bar.getMenu(bar.getMenuCount() - 1);
            assertEquals("Help", help.getText());
            JMenuItem item = (JMenuItem) GuiDriver.find(help.getPopupMenu(), "menu.shortcuts");
            assertEquals("Keyboard Shortcuts", item.getText());
            item.doClick(0);
            assertEquals(1, shown.get(), "it opens the page");
            assertEquals(0, about.get());
            ((JMenuItem) GuiDriver.find(help.getPopupMenu(), "menu.about")).doClick(0);
            assertEquals(1, about.get());
        });
    }
}
