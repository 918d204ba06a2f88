package org.beziertracer.ui;

import java.awt.Component;
import java.util.function.Function;

import javax.swing.DefaultListCellRenderer;
import javax.swing.JList;

/** A combo box renderer that shows each choice by a label of its own (an enum's lower-case name, say). */
final class LabelRenderer<T> extends DefaultListCellRenderer {

    private final Class<T> type;
    private final Function<T, String> label;

    LabelRenderer(Class<T> type, Function<T, String> label) {
        this.type = type;
        this.label = label;
    }

    @Override
    public Component getListCellRendererComponent(JList<?> list, Object value, int index, boolean selected,
                                                  boolean focus) {
        Object text = type.isInstance(value) ? label.apply(type.cast(value)) : value;
        return super.getListCellRendererComponent(list, text, index, selected, focus);
    }
}
