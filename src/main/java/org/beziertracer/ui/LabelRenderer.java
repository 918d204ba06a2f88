package org.beziertracer.ui;

import java.awt.Component;
import java.util.function.Function;

import javax.swing.DefaultListCellRenderer;
import javax.swing.JList;

/**
 * A combo box renderer that shows each choice by a label of its own (an enum's lower-case name,
 * say), and, when given one, a tooltip of its own (what the choice does).
 */
final class LabelRenderer<T> extends DefaultListCellRenderer {

    private final Class<T> type;
    private final Function<T, String> label;
    /** Null for no tooltip per choice. */
    private final Function<T, String> tooltip;

    LabelRenderer(Class<T> type, Function<T, String> label) {
        this(type, label, null);
    }

    LabelRenderer(Class<T> type, Function<T, String> label, Function<T, String> tooltip) {
        this.type = type;
        this.label = label;
        this.tooltip = tooltip;
    }

    @Override
    public Component getListCellRendererComponent(JList<?> list, Object value, int index, boolean selected,
                                                  boolean focus) {
        boolean choice = type.isInstance(value);
        Object text = choice ? label.apply(type.cast(value)) : value;
        Component c = super.getListCellRendererComponent(list, text, index, selected, focus);
        setToolTipText(choice && tooltip != null ? tooltip.apply(type.cast(value)) : null);
        return c;
    }
}
