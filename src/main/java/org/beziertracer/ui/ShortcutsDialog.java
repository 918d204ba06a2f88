package org.beziertracer.ui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Window;
import java.util.List;

import javax.swing.BorderFactory;
import javax.swing.JDialog;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.table.AbstractTableModel;

/**
 * Help → Keyboard Shortcuts: a table of {@link ShortcutList}'s rows (keys, command, what it does),
 * sortable by any column, made afresh each time it opens so that it shows the bindings as they are.
 */
final class ShortcutsDialog {
    private ShortcutsDialog() {}

    /** The rows as a read-only table model (three columns). */
    static AbstractTableModel model(List<ShortcutList.Row> rows) {
        return new AbstractTableModel() {
            private final String[] columns = {"Keys", "Command", "What it does"};

            @Override
            public int getRowCount() { return rows.size(); }

            @Override
            public int getColumnCount() { return columns.length; }

            @Override
            public String getColumnName(int c) { return columns[c]; }

            @Override
            public Object getValueAt(int r, int c) {
                ShortcutList.Row row = rows.get(r);
                return c == 0 ? row.keys() : c == 1 ? row.command() : row.description();
            }
        };
    }

    /** Shows the dialog over {@code owner} (not modal: it can stay open beside the window). */
    static void show(Window owner, List<ShortcutList.Row> rows) {
        JDialog d = new JDialog(owner, "Keyboard Shortcuts");
        d.setName("dialog.shortcuts");
        JTable table = new JTable(model(rows));
        table.setName("shortcuts.table");
        table.setAutoCreateRowSorter(true);
        table.setFillsViewportHeight(true);
        table.getColumnModel().getColumn(0).setPreferredWidth(140);
        table.getColumnModel().getColumn(1).setPreferredWidth(200);
        table.getColumnModel().getColumn(2).setPreferredWidth(520);
        JScrollPane scroll = new JScrollPane(table);
        scroll.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        d.getContentPane().add(scroll, BorderLayout.CENTER);
        d.setSize(new Dimension(880, 560));
        d.setLocationRelativeTo(owner);
        d.setDefaultCloseOperation(JDialog.DISPOSE_ON_CLOSE);
        d.getRootPane().registerKeyboardAction(e -> d.dispose(), javax.swing.KeyStroke.getKeyStroke("ESCAPE"),
                javax.swing.JComponent.WHEN_IN_FOCUSED_WINDOW);
        d.setVisible(true);
    }
}
