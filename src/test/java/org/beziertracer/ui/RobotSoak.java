package org.beziertracer.ui;

import java.awt.Dimension;
import java.awt.Point;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import javax.swing.JComponent;

import org.beziertracer.app.OverlayGeometry;

/**
 * The GUI soak's real-input part: seeded random mouse drags on control points and on empty space,
 * wheel clicks, keyboard shortcuts, toolbox clicks, menu items and window resizes, sent with
 * {@link java.awt.Robot} without waiting for the app between them (so they come faster than frames
 * complete). Every action draws the same count of random numbers, so a seed replays the sequence.
 */
final class RobotSoak {

    /** Shortcuts that change something and open no dialog: {key, modifiers}. */
    private static final int CTRL = KeyEvent.VK_CONTROL, SHIFT = KeyEvent.VK_SHIFT;
    private static final int[][] KEYS = {
            {KeyEvent.VK_Z, CTRL}, {KeyEvent.VK_Z, CTRL, SHIFT}, {KeyEvent.VK_Y, CTRL}, {KeyEvent.VK_Z, CTRL},
            {KeyEvent.VK_F2}, {KeyEvent.VK_F3}, {KeyEvent.VK_F4}, {KeyEvent.VK_F5}, {KeyEvent.VK_F6}, {KeyEvent.VK_F7},
            {KeyEvent.VK_F8}, {KeyEvent.VK_F9}, {KeyEvent.VK_F11}, {KeyEvent.VK_F12}, {KeyEvent.VK_B, CTRL},
            {KeyEvent.VK_K, CTRL}, {KeyEvent.VK_K, CTRL, SHIFT}, {KeyEvent.VK_M, CTRL}, {KeyEvent.VK_L, CTRL},
            {KeyEvent.VK_P, CTRL, SHIFT}, {KeyEvent.VK_PERIOD, CTRL}, {KeyEvent.VK_COMMA, CTRL},
            {KeyEvent.VK_CLOSE_BRACKET, CTRL}, {KeyEvent.VK_OPEN_BRACKET, CTRL}, {KeyEvent.VK_CLOSE_BRACKET, CTRL, SHIFT},
            {KeyEvent.VK_OPEN_BRACKET, CTRL, SHIFT}, {KeyEvent.VK_HOME}, {KeyEvent.VK_EQUALS, CTRL},
            {KeyEvent.VK_MINUS, CTRL}, {KeyEvent.VK_R, CTRL}, {KeyEvent.VK_R, CTRL, SHIFT}, {KeyEvent.VK_U, CTRL, SHIFT},
            {KeyEvent.VK_V, CTRL, SHIFT}};
    /** Menu items that are always enabled and open no dialog: {menu, item}. */
    private static final String[][] MENUS = {
            {"Render", "method"}, {"Render", "bvh"}, {"Render", "tessellated"}, {"Render", "light"},
            {"Render", "superSampling"}, {"View", "resetView"}, {"View", "rayTrace"}, {"Surface", "randomize"},
            {"Models", "model:teapot"}, {"Models", "model:teapot-room"}, {"Models", "model:patch"}};

    private final GuiDriver d;
    private final Random random;
    private final List<JComponent> tools = new ArrayList<>();
    private int actions;

    RobotSoak(GuiDriver d, long seed) {
        this.d = d;
        this.random = new Random(seed);
        GuiDriver.onEdt(() -> ToolboxPanel.forEachControl(d.frame.toolbox(), c -> {
            if (c instanceof javax.swing.AbstractButton && !"tool.dark".equals(c.getName())) {
                tools.add(c);
            }
        }));
    }

    /** One action; returns what it was, for the summary. */
    String step() {
        double r = random.nextDouble(), a = random.nextDouble(), b = random.nextDouble(), c = random.nextDouble();
        actions++;
        if (r < 0.40) {
            drag(a, b, c, true);
            return "drag";
        } else if (r < 0.48) {
            drag(a, b, c, false);
            return "rotate";
        } else if (r < 0.54) {
            wheel(a, b);
            return "wheel";
        } else if (r < 0.80) {
            int[] k = KEYS[(int) (a * KEYS.length)];
            key(k);
            return "key";
        } else if (r < 0.94) {
            click(tools.get((int) (a * tools.size())));
            return "toolbox";
        } else if (r < 0.97) {
            menu(MENUS[(int) (a * MENUS.length)]);
            return "menu";
        } else {
            resize(a, b);
            return "resize";
        }
    }

    /** Actions so far. */
    int count() { return actions; }

    /** A drag from a drawn control point ({@code onPoint}, when there is one) or from anywhere in the picture. */
    private void drag(double a, double b, double c, boolean onPoint) {
        double[] from = GuiDriver.onEdt(() -> {
            OverlayGeometry g = d.app.overlay().geometry();
            if (onPoint && g.handleCount() > 0) {
                int k = (int) (a * g.handleCount());
                return new double[] {g.handleX(k), g.handleY(k)};
            }
            return new double[] {b * d.app.view().width(), c * d.app.view().height()};
        });
        Point p = d.screenOf(from[0], from[1]);
        double angle = 2 * Math.PI * c, length = 10 + 80 * b;
        int steps = 2 + (int) (4 * a);
        d.robot.mouseMove(p.x, p.y);
        d.robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int k = 1; k <= steps; k++) {
            d.robot.mouseMove(p.x + (int) (length * Math.cos(angle) * k / steps),
                    p.y + (int) (length * Math.sin(angle) * k / steps));
        }
        d.robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
    }

    /** Clicks a toolbox control (scrolled into view) without waiting for the app. */
    private void click(JComponent c) {
        Point p = GuiDriver.onEdt(() -> {
            c.scrollRectToVisible(new java.awt.Rectangle(0, 0, c.getWidth(), c.getHeight()));
            Point s = c.getLocationOnScreen();
            return new Point(s.x + c.getWidth() / 2, s.y + c.getHeight() / 2);
        });
        d.robot.mouseMove(p.x, p.y);
        d.robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        d.robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
    }

    private void wheel(double a, double b) {
        Point p = d.screenOf(a * 100 + 20, b * 100 + 20);
        d.robot.mouseMove(p.x, p.y);
        d.robot.mouseWheel(a < 0.5 ? -1 : 1);
    }

    private void key(int[] k) {
        for (int m = 1; m < k.length; m++) {
            d.robot.keyPress(k[m]);
        }
        d.robot.keyPress(k[0]);
        d.robot.keyRelease(k[0]);
        for (int m = k.length - 1; m >= 1; m--) {
            d.robot.keyRelease(k[m]);
        }
    }

    /** A menu item with the mouse; a model switch first marks the document saved (no unsaved-edits question). */
    private void menu(String[] item) {
        if (item[0].equals("Models")) {
            // the input sent so far (a drag is not waited for) lands first: it cannot make an edit
            // after the mark and so ask the unsaved-edits question
            d.robot.waitForIdle();
            GuiDriver.onEdt(() -> d.app.document().history().markSaved());
        }
        d.menu(item[0], item[1]);
        GuiDriver.onEdt(() -> d.frame.renderPanel().requestFocusInWindow());
    }

    private void resize(double a, double b) {
        Dimension size = new Dimension(640 + (int) (260 * a), 440 + (int) (160 * b));
        GuiDriver.onEdt(() -> d.frame.setSize(size));
    }
}
