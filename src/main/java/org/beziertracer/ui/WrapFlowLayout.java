package org.beziertracer.ui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Insets;

/**
 * A left-aligned {@link FlowLayout} that asks for the height of every row it wraps into, so a
 * component that does not fit on the first row moves to the next one instead of vanishing below
 * the container's edge (a plain {@code FlowLayout} asks for one row whatever the width). The width
 * it wraps at is the one its container's parent gives it ({@code BorderLayout.SOUTH}: the window's
 * width). A component wider than a whole row is narrowed to it (a {@code JLabel} then elides its
 * text with "…"; give it a tooltip with the full text).
 *
 * <p>At one width the preferred height never shrinks: a status bar whose texts change after every
 * frame would otherwise change rows, resize the picture above it, start a new frame, change its
 * texts again, and never settle (an app soak found the loop). The height is forgotten when the
 * width changes.
 */
final class WrapFlowLayout extends FlowLayout {

    /** The width the tallest height was asked at, and that height (preferred sizes only). */
    private int heldWidth = -1, heldHeight;

    WrapFlowLayout(int hgap, int vgap) {
        super(FlowLayout.LEFT, hgap, vgap);
    }

    @Override
    public Dimension preferredLayoutSize(Container target) {
        Dimension d = size(target, true);
        int width = rowWidth(target);
        if (width != heldWidth) {
            heldWidth = width;
            heldHeight = 0;
        }
        heldHeight = Math.max(heldHeight, d.height);
        d.height = heldHeight;
        return d;
    }

    @Override
    public Dimension minimumLayoutSize(Container target) {
        Dimension d = size(target, false);
        d.width = 0; // any width: the rows wrap
        return d;
    }

    @Override
    public void layoutContainer(Container target) {
        super.layoutContainer(target);
        int right = target.getWidth() - target.getInsets().right - getHgap();
        int left = target.getInsets().left + getHgap();
        for (Component c : target.getComponents()) {
            if (c.isVisible() && c.getX() + c.getWidth() > right) {
                c.setBounds(left, c.getY(), Math.max(0, right - left), c.getHeight()); // alone on its row
            }
        }
    }

    /** The width the rows wrap at: the parent's for this container (it is about to get it), else its own. */
    private static int rowWidth(Container target) {
        Container parent = target.getParent();
        int w = parent != null && parent.getWidth() > 0 ? parent.getWidth() - parent.getInsets().left
                - parent.getInsets().right : target.getWidth();
        return w > 0 ? w : Integer.MAX_VALUE;
    }

    private Dimension size(Container target, boolean preferred) {
        synchronized (target.getTreeLock()) {
            Insets in = target.getInsets();
            int maxRow = rowWidth(target) - in.left - in.right - 2 * getHgap();
            int width = 0, height = 0, rowWidth = 0, rowHeight = 0;
            boolean first = true;
            for (Component c : target.getComponents()) {
                if (!c.isVisible()) {
                    continue;
                }
                Dimension d = preferred ? c.getPreferredSize() : c.getMinimumSize();
                int w = Math.min(d.width, Math.max(0, maxRow));
                if (!first && rowWidth + w > maxRow) { // FlowLayout's own test
                    width = Math.max(width, rowWidth);
                    height += rowHeight + getVgap();
                    rowWidth = 0;
                    rowHeight = 0;
                    first = true;
                }
                rowWidth += (first ? 0 : getHgap()) + w;
                rowHeight = Math.max(rowHeight, d.height);
                first = false;
            }
            width = Math.max(width, rowWidth);
            height += rowHeight;
            return new Dimension(width + in.left + in.right + 2 * getHgap(), height + in.top + in.bottom + 2 * getVgap());
        }
    }
}
