package org.beziertracer.ui;

import java.awt.Dimension;
import java.awt.Insets;

import javax.swing.JTextArea;
import javax.swing.UIManager;
import javax.swing.text.View;

/**
 * Read-only text that wraps at word boundaries to the width its layout gives it and asks for the
 * height of every line it then needs, so nothing of it is ever clipped or elided (a {@code JLabel}
 * cuts a long line to "…"). Its preferred width is small: the layout decides the width (fill it
 * horizontally), the text decides the height. The full text is also its tooltip. UI thread only.
 */
final class WrappingText extends JTextArea {

    /** Width assumed for the height before the first layout. */
    private final int firstWidth;

    WrappingText(String name, int firstWidth) {
        this.firstWidth = firstWidth;
        setName(name);
        setLineWrap(true);
        setWrapStyleWord(true);
        setEditable(false);
        setFocusable(false);
        setOpaque(false);
        setBorder(null);
        setFont(UIManager.getFont("Label.font"));
    }

    @Override
    public void setText(String t) {
        super.setText(t);
        setToolTipText(t == null || t.isBlank() ? null : t);
    }

    /** The height that shows every wrapped line at {@code width}. */
    int heightAt(int width) {
        Insets in = getInsets();
        View root = getUI().getRootView(this);
        root.setSize(Math.max(1, width - in.left - in.right), Integer.MAX_VALUE);
        return (int) Math.ceil(root.getPreferredSpan(View.Y_AXIS)) + in.top + in.bottom;
    }

    @Override
    public Dimension getPreferredSize() {
        return new Dimension(1, heightAt(getWidth() > 0 ? getWidth() : firstWidth));
    }

    @Override
    public Dimension getMinimumSize() { return getPreferredSize(); }

    @Override
    public void setBounds(int x, int y, int width, int height) {
        boolean wider = width != getWidth();
        super.setBounds(x, y, width, height);
        if (wider && width > 0 && heightAt(width) != height) {
            revalidate(); // the new width wraps to another number of lines
        }
    }
}
