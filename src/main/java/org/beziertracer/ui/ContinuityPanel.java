package org.beziertracer.ui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Dimension;
import java.util.Locale;

import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSpinner;
import javax.swing.JTable;
import javax.swing.SpinnerNumberModel;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.DefaultTableCellRenderer;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.ContinuityAnalysis;
import org.beziertracer.app.ContinuityModel;
import org.beziertracer.app.Toggle;
import org.beziertracer.geometry.BorderStrip;

/**
 * View → Continuity: the model's shared borders, worst first, with their certified bounds (gap,
 * normal angle, curvature mismatch) and class, the counts of each class, and the tolerances that
 * decide the classes, editable. Shown while {@link Toggle#CONTINUITY} is on. Event thread only.
 */
final class ContinuityPanel extends JPanel {

    /** Mark colours, by class ({@link ContinuityAnalysis.Continuity} order: G2, G1, G0, gap). */
    static final Color[] COLOURS = {new Color(0x3CC85A), new Color(0xF0C83C), new Color(0xE8453C), new Color(0xE8453C)};

    private final AppModel app;
    private final JLabel summary = new JLabel(" ");
    private final Rows rows = new Rows();
    private final JTable table = new JTable(rows);
    private final JSpinner g0 = spinner("continuity.g0", 1e-9, 1e-15, 1e6, 1e-9);
    private final JSpinner g1 = spinner("continuity.g1", ContinuityAnalysis.Tolerances.G1_DEGREES, 0, 90, 0.05);
    private final JSpinner g2 = spinner("continuity.g2", 1e-3, 0, 1e9, 1e-4);
    private Object shownTolerances;

    ContinuityPanel(AppModel app) {
        super(new BorderLayout(4, 4));
        this.app = app;
        setName("continuity");
        setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        summary.setName("continuity.summary");
        table.setName("continuity.table");
        table.setAutoCreateRowSorter(false);
        table.setDefaultRenderer(Object.class, new ClassColours());
        JScrollPane scroll = new JScrollPane(table);
        scroll.setPreferredSize(new Dimension(360, 200));
        scroll.setMinimumSize(new Dimension(200, 60));
        JPanel tolerances = SwingDialogs.form(new Object[][] {{"G0 gap ≤", g0}, {"G1 angle (°) ≤", g1},
            {"G2 mismatch ≤", g2}});
        JButton apply = new JButton("Apply tolerances");
        apply.setName("continuity.apply");
        apply.addActionListener(e -> app.continuityTolerances(new ContinuityAnalysis.Tolerances(
                ((Number) g0.getValue()).doubleValue(), ((Number) g1.getValue()).doubleValue(),
                ((Number) g2.getValue()).doubleValue())));
        tolerances.add(new JLabel());
        tolerances.add(apply);
        add(summary, BorderLayout.NORTH);
        add(scroll, BorderLayout.CENTER);
        add(tolerances, BorderLayout.SOUTH);
        app.addListener(this::refresh);
        refresh();
    }

    /** Shows the newest analysis (or that one is running). */
    void refresh() {
        boolean on = app.settings().current().on(Toggle.CONTINUITY);
        setVisible(on);
        ContinuityModel.Shown shown = on ? app.continuity().current() : null;
        if (shown == null) {
            summary.setText(on ? "certifying the borders…" : " ");
            rows.show(null);
            return;
        }
        ContinuityAnalysis.Result r = shown.result();
        summary.setText(String.format(Locale.ROOT, "%d borders: %d G2, %d G1, %d G0, %d open", r.rows().size(),
                r.count(ContinuityAnalysis.Continuity.G2), r.count(ContinuityAnalysis.Continuity.G1),
                r.count(ContinuityAnalysis.Continuity.G0), r.count(ContinuityAnalysis.Continuity.GAP)));
        rows.show(r);
        if (shownTolerances != r.tolerances()) {
            shownTolerances = r.tolerances();
            g0.setValue(r.tolerances().g0());
            g1.setValue(r.tolerances().g1Degrees());
            g2.setValue(r.tolerances().g2());
        }
    }

    /** Text of the summary line (tests). */
    String summary() { return summary.getText(); }

    /** Rows of the table (tests). */
    int rowCount() { return rows.getRowCount(); }

    private static JSpinner spinner(String name, double value, double min, double max, double step) {
        JSpinner s = new JSpinner(new SpinnerNumberModel(value, min, max, step));
        s.setName(name);
        s.setEditor(new JSpinner.NumberEditor(s, "0.###E0"));
        return s;
    }

    /** The borders as table rows: patches and sides (1-based patches, as the command line shows them), bounds, class. */
    private static final class Rows extends AbstractTableModel {
        private static final String[] COLUMNS = {"patch", "side", "patch", "side", "g0", "g1 (°)", "g2", "class"};
        private ContinuityAnalysis.Result result;

        void show(ContinuityAnalysis.Result r) {
            if (r != result) {
                result = r;
                fireTableDataChanged();
            }
        }

        ContinuityAnalysis.Continuity classOf(int row) { return result.rows().get(row).continuity(); }

        @Override
        public int getRowCount() { return result == null ? 0 : result.rows().size(); }

        @Override
        public int getColumnCount() { return COLUMNS.length; }

        @Override
        public String getColumnName(int c) { return COLUMNS[c]; }

        @Override
        public Object getValueAt(int row, int c) {
            ContinuityAnalysis.Row r = result.rows().get(row);
            return switch (c) {
                case 0 -> r.border().a() + 1;
                case 1 -> BorderStrip.SIDE_NAMES[r.border().sideA()];
                case 2 -> r.border().b() + 1;
                case 3 -> BorderStrip.SIDE_NAMES[r.border().sideB()];
                case 4 -> String.format(Locale.ROOT, "%.2e", r.report().g0().bound());
                case 5 -> String.format(Locale.ROOT, "%.3g", r.g1Degrees());
                case 6 -> String.format(Locale.ROOT, "%.2e", r.report().g2().bound())
                        + (r.report().g2().certified() ? "" : " (sampled)");
                default -> r.continuity().label();
            };
        }
    }

    /** The class column in the mark's colour. */
    private final class ClassColours extends DefaultTableCellRenderer {
        @Override
        public Component getTableCellRendererComponent(JTable t, Object value, boolean selected, boolean focus, int row,
                                                       int column) {
            Component c = super.getTableCellRendererComponent(t, value, selected, focus, row, column);
            c.setForeground(column == 7 ? COLOURS[rows.classOf(row).ordinal()] : t.getForeground());
            return c;
        }
    }
}
