package org.beziertracer.ui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.event.FocusAdapter;
import java.awt.event.FocusEvent;
import java.util.EnumMap;
import java.util.Locale;
import java.util.Map;

import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.KeyStroke;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.Inspector;
import org.beziertracer.app.Inspector.Field;
import org.beziertracer.app.Toggle;

/**
 * The inspector: the selected handle's patch, indices and coordinates (and weight, for a rational
 * patch), or the centroid of several; typing a value and pressing Enter moves them
 * ({@link Inspector#set}, one undoable edit), Escape puts the shown value back. A field being typed
 * in is not overwritten by refreshes. A refused value's reason ({@link Inspector#message}) and the
 * hint wrap to the panel's width, whole. Shown while View → Inspector is on.
 */
final class InspectorPanel extends JPanel {

    private final AppModel app;
    private final JLabel title = new JLabel(" ");
    /** Width of the panel (user-space pixels). */
    static final int WIDTH = 200;
    private final WrappingText where = new WrappingText("inspector.where", WIDTH - 40);
    private final WrappingText message = new WrappingText("inspector.message", WIDTH - 40);
    private final Map<Field, JTextField> fields = new EnumMap<>(Field.class);
    private final Map<Field, JLabel> labels = new EnumMap<>(Field.class);
    private final Map<Field, Boolean> typing = new EnumMap<>(Field.class);

    InspectorPanel(AppModel app) {
        super(new BorderLayout());
        this.app = app;
        setName("inspector");
        setBorder(BorderFactory.createCompoundBorder(BorderFactory.createEmptyBorder(6, 0, 6, 6),
                BorderFactory.createTitledBorder("Inspector")));
        title.setName("inspector.title");
        message.setForeground(new Color(0xC0392B));
        JPanel grid = new JPanel(new GridBagLayout());
        GridBagConstraints c = new GridBagConstraints();
        c.insets = new Insets(2, 4, 2, 4);
        c.gridx = 0;
        c.gridy = 0;
        c.gridwidth = 2;
        c.anchor = GridBagConstraints.WEST;
        grid.add(title, c);
        c.gridy++;
        c.fill = GridBagConstraints.HORIZONTAL;
        grid.add(where, c);
        c.gridwidth = 1;
        for (Field f : Field.values()) {
            c.gridy++;
            c.gridx = 0;
            c.fill = GridBagConstraints.NONE;
            JLabel l = new JLabel(f.label());
            labels.put(f, l);
            grid.add(l, c);
            c.gridx = 1;
            c.fill = GridBagConstraints.HORIZONTAL;
            c.weightx = 1;
            grid.add(field(f, l), c);
            c.weightx = 0;
        }
        c.gridy++;
        c.gridx = 0;
        c.gridwidth = 2;
        c.fill = GridBagConstraints.HORIZONTAL;
        grid.add(message, c);
        add(grid, BorderLayout.NORTH);
        setPreferredSize(new Dimension(WIDTH, getPreferredSize().height));
        app.addListener(this::refresh);
        refresh();
    }

    private JTextField field(Field f, JLabel label) {
        JTextField t = new JTextField(10);
        t.setName("inspector." + f.name().toLowerCase(Locale.ROOT));
        String what = f == Field.WEIGHT ? "weight of the selected point (rational patches)"
                : f.label() + " of the selected point, or of the centroid of several";
        t.setToolTipText("The " + what + ": type a value and press Enter to move (Escape puts it back)");
        label.setLabelFor(t);
        label.setToolTipText(t.getToolTipText());
        fields.put(f, t);
        typing.put(f, false);
        t.addActionListener(e -> apply(f));
        t.getInputMap().put(KeyStroke.getKeyStroke("ESCAPE"), "revert");
        // Up and down stay in the field: they would otherwise reach the menus and nudge the selection
        for (String k : new String[] {"UP", "DOWN", "shift UP", "shift DOWN"}) {
            t.getInputMap().put(KeyStroke.getKeyStroke(k), "stay");
        }
        t.getActionMap().put("stay", new javax.swing.AbstractAction() {
            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {}
        });
        t.getActionMap().put("revert", new javax.swing.AbstractAction() {
            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                typing.put(f, false);
                refresh();
            }
        });
        t.getDocument().addDocumentListener(new DocumentListener() {
            @Override
            public void insertUpdate(DocumentEvent e) { edited(f, t); }

            @Override
            public void removeUpdate(DocumentEvent e) { edited(f, t); }

            @Override
            public void changedUpdate(DocumentEvent e) { edited(f, t); }
        });
        t.addFocusListener(new FocusAdapter() {
            @Override
            public void focusLost(FocusEvent e) {
                typing.put(f, false);
                refresh();
            }
        });
        return t;
    }

    private boolean refreshing;

    private void edited(Field f, JTextField t) {
        if (!refreshing && t.isFocusOwner()) {
            typing.put(f, true);
        }
    }

    private void apply(Field f) {
        String error = app.inspector().set(f, fields.get(f).getText());
        typing.put(f, false);
        refresh();
    }

    static final String HINT = "Click a control point; Shift-click adds, Ctrl-click toggles, Shift-drag on empty space "
            + "selects an area. Then drag, nudge with the arrow keys, or type a coordinate here.";

    /** Shows the selection as it is now, and why the last typed value was refused (wrapped, never cut). */
    void refresh() {
        String refused = app.inspector().message();
        message.setText(refused == null ? "" : refused);
        message.setVisible(refused != null);
        setVisible(app.settings().current().on(Toggle.INSPECTOR));
        Inspector.State st = app.inspector().state();
        refreshing = true;
        try {
            if (st == null) {
                title.setText("No point selected");
                where.setText(HINT);
            } else if (st.handles() == 1) {
                title.setText("Patch " + st.primary().patch() + ", point (" + st.primary().i() + ", " + st.primary().j() + ")");
                where.setText(st.copies() == 1 ? "1 copy" : st.copies() + " welded copies");
            } else {
                title.setText(st.handles() + " points selected");
                where.setText("centroid");
            }
            for (Field f : Field.values()) {
                JTextField t = fields.get(f);
                boolean shown = f != Field.WEIGHT || (st != null && st.hasWeight());
                t.setVisible(shown);
                labels.get(f).setVisible(shown);
                t.setEnabled(st != null);
                if (!typing.get(f)) {
                    t.setText(st == null ? "" : st.text(f));
                }
            }
        } finally {
            refreshing = false;
        }
    }
}
