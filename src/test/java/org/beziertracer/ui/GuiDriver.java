package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.fail;

import java.awt.AWTException;
import java.awt.Component;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.lang.reflect.InvocationTargetException;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import javax.swing.JComponent;
import javax.swing.SwingUtilities;

/**
 * Drives the real app with {@link Robot}: starts it in this JVM, finds components by name,
 * clicks, drags, types, waits for the render to settle and captures screen pixels.
 */
final class GuiDriver {

    final AppFrame frame;
    final AppController c;
    final Robot robot;

    private GuiDriver(AppFrame frame) throws AWTException {
        this.frame = frame;
        this.c = frame.controller();
        this.robot = new Robot();
        robot.setAutoDelay(5);
    }

    static GuiDriver launch() throws Exception {
        AppFrame f = BezierTracerApp.start().get(30, TimeUnit.SECONDS);
        onEdt(() -> {
            f.setSize(new Dimension(960, 600));
            f.setLocation(0, 0);
            f.toFront();
            return null;
        });
        GuiDriver d = new GuiDriver(f);
        d.robot.waitForIdle();
        d.settle();
        return d;
    }

    /** Runs on the event thread and returns the result. */
    static <T> T onEdt(Callable<T> task) {
        AtomicReference<T> out = new AtomicReference<>();
        AtomicReference<Exception> err = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> {
                try {
                    out.set(task.call());
                } catch (Exception e) {
                    err.set(e);
                }
            });
        } catch (InterruptedException | InvocationTargetException e) {
            throw new IllegalStateException(e);
        }
        if (err.get() != null) {
            throw new IllegalStateException(err.get());
        }
        return out.get();
    }

    static void onEdt(Runnable task) {
        onEdt(() -> {
            task.run();
            return null;
        });
    }

    /** Waits until no render is pending or running and the last repaint is on screen. */
    void settle() {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        int quiet = 0;
        while (quiet < 3) {
            robot.waitForIdle();
            boolean busy = onEdt(() -> c.engine().busy());
            quiet = busy ? 0 : quiet + 1;
            robot.delay(busy ? 20 : 40);
            if (System.nanoTime() > end) {
                fail("the render did not settle within 20 s");
            }
        }
    }

    @SuppressWarnings("unchecked")
    <T extends Component> T find(String name) {
        Component comp = onEdt(() -> find(frame.getContentPane(), name));
        if (comp == null) {
            fail("no component named " + name);
        }
        return (T) comp;
    }

    private static Component find(Component root, String name) {
        if (name.equals(root.getName())) {
            return root;
        }
        if (root instanceof Container ct) {
            for (Component child : ct.getComponents()) {
                Component hit = find(child, name);
                if (hit != null) {
                    return hit;
                }
            }
        }
        return null;
    }

    /** Clicks the centre of a component (scrolling it into view first). */
    void click(Component comp) {
        Point p = onEdt(() -> {
            if (comp instanceof JComponent jc) {
                jc.scrollRectToVisible(new Rectangle(0, 0, jc.getWidth(), jc.getHeight()));
            }
            Point s = comp.getLocationOnScreen();
            return new Point(s.x + comp.getWidth() / 2, s.y + comp.getHeight() / 2);
        });
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    /** Screen position of a device-pixel position in the render panel. */
    Point screenOf(double deviceX, double deviceY) {
        return onEdt(() -> {
            Point s = frame.renderPanel().getLocationOnScreen();
            double scale = frame.renderPanel().deviceScale();
            return new Point(s.x + (int) Math.round(deviceX / scale), s.y + (int) Math.round(deviceY / scale));
        });
    }

    /** Drags with the left button from {@code a} to {@code b} in {@code steps} moves. */
    void drag(Point a, Point b, int steps) {
        robot.mouseMove(a.x, a.y);
        robot.waitForIdle();
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int k = 1; k <= steps; k++) {
            robot.mouseMove(a.x + (b.x - a.x) * k / steps, a.y + (b.y - a.y) * k / steps);
            robot.delay(10);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    void key(int code, int... modifiers) {
        for (int m : modifiers) {
            robot.keyPress(m);
        }
        robot.keyPress(code);
        robot.keyRelease(code);
        for (int k = modifiers.length - 1; k >= 0; k--) {
            robot.keyRelease(modifiers[k]);
        }
        robot.waitForIdle();
    }

    void ctrl(int code) { key(code, KeyEvent.VK_CONTROL); }

    /** The render panel as on screen now. */
    BufferedImage capturePanel() {
        Rectangle r = onEdt(() -> {
            Point s = frame.renderPanel().getLocationOnScreen();
            return new Rectangle(s.x, s.y, frame.renderPanel().getWidth(), frame.renderPanel().getHeight());
        });
        return robot.createScreenCapture(r);
    }

    /** Pixels of {@code a} and {@code b} in a box that differ by more than {@code tol} in some channel. */
    static int differing(BufferedImage a, BufferedImage b, Rectangle box, int tol) {
        int count = 0;
        for (int y = Math.max(0, box.y); y < Math.min(a.getHeight(), box.y + box.height); y++) {
            for (int x = Math.max(0, box.x); x < Math.min(a.getWidth(), box.x + box.width); x++) {
                int p = a.getRGB(x, y), q = b.getRGB(x, y);
                for (int s = 0; s <= 16; s += 8) {
                    if (Math.abs(((p >> s) & 255) - ((q >> s) & 255)) > tol) {
                        count++;
                        break;
                    }
                }
            }
        }
        return count;
    }

    /** Mean colour {r, g, b} of a box. */
    static double[] mean(BufferedImage img, Rectangle box) {
        double[] m = new double[3];
        int n = 0;
        for (int y = box.y; y < box.y + box.height; y++) {
            for (int x = box.x; x < box.x + box.width; x++) {
                int p = img.getRGB(x, y);
                m[0] += (p >> 16) & 255;
                m[1] += (p >> 8) & 255;
                m[2] += p & 255;
                n++;
            }
        }
        for (int k = 0; k < 3; k++) {
            m[k] /= n;
        }
        return m;
    }

    void close() {
        onEdt(() -> {
            c.history().markSaved();
            frame.close();
        });
    }
}
