package org.beziertracer.ui;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;

import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.InputMap;
import javax.swing.KeyStroke;

import org.beziertracer.app.Axis;

/**
 * Help → Keyboard Shortcuts' rows, generated from what the keys are bound to — never a hand-kept
 * list: every {@link Action} with an accelerator (the menus' and toolbox's commands, in their
 * order), then each extra binding of the window's input map (for instance Ctrl+Y for Redo), then the
 * axis keys held while dragging points ({@link Axis}). A command's text is its name as the menu
 * shows it now. Event thread only.
 */
final class ShortcutList {
    private ShortcutList() {}

    /** Action key of the name a row shows when the action's own name is blank (File → Open Recent's places). */
    static final String NAME = "shortcutName";

    /** One shortcut: its keys as the tooltips write them (e.g. {@code Ctrl+Shift+Z}), the command, what it does. */
    record Row(String keys, String command, String description) {}

    /**
     * @param actions    the app's actions ({@link AppActions#all()})
     * @param extraKeys  the window's own bindings (may be null)
     * @param extraTable what they run, by key (may be null)
     */
    static List<Row> of(Collection<Action> actions, InputMap extraKeys, ActionMap extraTable) {
        List<Row> rows = new ArrayList<>();
        for (Action a : actions) {
            KeyStroke k = (KeyStroke) a.getValue(Action.ACCELERATOR_KEY);
            if (k != null) {
                rows.add(row(k, a));
            }
        }
        if (extraKeys != null && extraKeys.keys() != null) {
            for (KeyStroke k : extraKeys.keys()) {
                Action a = extraTable == null ? null : extraTable.get(extraKeys.get(k));
                if (a != null) {
                    rows.add(row(k, a));
                }
            }
        }
        for (Axis axis : Axis.values()) {
            String name = axis.name().toLowerCase(Locale.ROOT);
            rows.add(new Row(axis.name() + " (held)", "Drag Along " + axis.name(), "While dragging control points: move "
                    + "them along the " + name + " axis only"));
        }
        return rows;
    }

    private static Row row(KeyStroke k, Action a) {
        String name = String.valueOf(a.getValue(Action.NAME)).strip();
        String about = a.getValue(Action.LONG_DESCRIPTION) instanceof String s ? s : "";
        Object fallback = a.getValue(NAME);
        return new Row(AppActions.keyText(k), !name.isEmpty() ? name : fallback != null ? fallback.toString() : about, about);
    }
}
