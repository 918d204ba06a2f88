package org.beziertracer.ui;

import java.awt.Component;

import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;

import org.beziertracer.render.Analysis;

/**
 * View → Analysis → Analysis Settings…: the analysis views' settings in one small form — zebra
 * bars (axis, count, dark share), isophote step, the curvature colour scale (automatic, or fixed
 * ends), the draft's pull axis and tolerance. Event thread only.
 */
final class AnalysisSettingsPanel {
    private AnalysisSettingsPanel() {}

    /** The axes offered for the zebra bars and the pull direction. */
    private static final String[] AXES = {"x", "y", "z", "-x", "-y", "-z"};

    /** Asks for new settings starting from {@code current}; null when cancelled. */
    static Analysis ask(Component parent, Analysis current) {
        JComboBox<String> zebraAxis = axisBox("analysis.zebraAxis", current.zebraAxis());
        JSpinner stripes = spinner("analysis.zebraStripes", current.zebraStripes(), 2, 200, 1);
        JSpinner width = spinner("analysis.zebraWidth", current.zebraWidth(), 0.05, 0.95, 0.05);
        JSpinner step = spinner("analysis.isophoteStep", current.isophoteStep(), 0.5, 90, 0.5);
        JCheckBox auto = new JCheckBox("automatic", current.autoRange());
        auto.setName("analysis.autoRange");
        JSpinner low = spinner("analysis.rangeLow", current.autoRange() ? -1 : current.rangeLow(), -1e9, 1e9, 0.001);
        JSpinner high = spinner("analysis.rangeHigh", current.autoRange() ? 1 : current.rangeHigh(), -1e9, 1e9, 0.001);
        low.setEnabled(!auto.isSelected());
        high.setEnabled(!auto.isSelected());
        auto.addActionListener(e -> {
            low.setEnabled(!auto.isSelected());
            high.setEnabled(!auto.isSelected());
        });
        JComboBox<String> pull = axisBox("analysis.draftPull", current.draftPull());
        JSpinner tolerance = spinner("analysis.draftTolerance", current.draftTolerance(), 0, 45, 0.5);
        JPanel panel = SwingDialogs.form(new Object[][] {{"Zebra bars along", zebraAxis}, {"Zebra bars", stripes},
            {"Zebra dark share", width}, {"Isophote step (°)", step}, {"Curvature scale", auto}, {"Scale low end", low},
            {"Scale high end", high}, {"Draft pull direction", pull}, {"Draft tolerance (°)", tolerance}});
        if (JOptionPane.showConfirmDialog(parent, panel, "Analysis settings", JOptionPane.OK_CANCEL_OPTION,
                JOptionPane.PLAIN_MESSAGE) != JOptionPane.OK_OPTION) {
            return null;
        }
        try {
            Analysis a = current.withZebra(axis(zebraAxis), ((Number) stripes.getValue()).intValue(),
                    ((Number) width.getValue()).doubleValue())
                    .withIsophotes(current.isophoteLight(), ((Number) step.getValue()).doubleValue())
                    .withDraft(axis(pull), ((Number) tolerance.getValue()).doubleValue());
            return auto.isSelected() ? a.withRange(Double.NaN, Double.NaN)
                    : a.withRange(((Number) low.getValue()).doubleValue(), ((Number) high.getValue()).doubleValue());
        } catch (IllegalArgumentException e) {
            JOptionPane.showMessageDialog(parent, e.getMessage(), "Analysis settings", JOptionPane.ERROR_MESSAGE);
            return null;
        }
    }

    private static JComboBox<String> axisBox(String name, double[] direction) {
        JComboBox<String> box = new JComboBox<>(AXES);
        box.setName(name);
        for (int k = 0; k < 3; k++) {
            if (Math.abs(direction[k]) > 0.999) {
                box.setSelectedIndex(direction[k] > 0 ? k : k + 3);
            }
        }
        return box;
    }

    private static double[] axis(JComboBox<String> box) {
        int k = box.getSelectedIndex();
        double[] d = new double[3];
        d[k % 3] = k < 3 ? 1 : -1;
        return d;
    }

    private static JSpinner spinner(String name, double value, double min, double max, double step) {
        JSpinner s = new JSpinner(new SpinnerNumberModel(Math.max(min, Math.min(max, value)), min, max, step));
        s.setName(name);
        return s;
    }

    private static JSpinner spinner(String name, int value, int min, int max, int step) {
        JSpinner s = new JSpinner(new SpinnerNumberModel(Math.max(min, Math.min(max, value)), min, max, step));
        s.setName(name);
        return s;
    }
}
