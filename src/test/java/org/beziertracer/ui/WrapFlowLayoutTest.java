package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.BorderLayout;
import java.awt.Dimension;

import javax.swing.JLabel;
import javax.swing.JPanel;

import org.junit.jupiter.api.Test;

/**
 * The wrapping status row: more rows when its texts need them, and at one width never fewer (a
 * picture resized by every change of the rows would start a new frame whose texts change the rows
 * again: the loop an app soak found).
 */
class WrapFlowLayoutTest {

    @Test
    void atOneWidthTheHeightGrowsButNeverShrinksAndANewWidthStartsAfresh() {
        JPanel window = new JPanel(new BorderLayout());
        JPanel bar = new JPanel(new WrapFlowLayout(6, 2));
        JLabel a = new JLabel("short"), b = new JLabel("short");
        bar.add(a);
        bar.add(b);
        window.add(bar, BorderLayout.SOUTH);
        window.setSize(new Dimension(300, 200));
        int oneRow = bar.getPreferredSize().height;

        a.setText("a much longer text that fills the row");
        b.setText("another long text that needs its own row");
        int twoRows = bar.getPreferredSize().height;
        assertTrue(twoRows > oneRow, twoRows + " vs " + oneRow);

        a.setText("short");
        b.setText("short");
        assertEquals(twoRows, bar.getPreferredSize().height, "the same width keeps its rows");

        window.setSize(new Dimension(900, 200));
        assertEquals(oneRow, bar.getPreferredSize().height, "a new width asks again");
    }
}
