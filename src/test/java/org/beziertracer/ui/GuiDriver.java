package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.AWTException;
import java.awt.Component;
import java.awt.Container;
import java.awt.Dimension;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;

import javax.swing.AbstractButton;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.AppPreferences;
import org.beziertracer.app.MemoryPreferences;
import org.beziertracer.model.BezierPatch;

/**
 * Drives the real app with {@link Robot}: starts it in this JVM with preferences of its own (in
 * memory), clicks menus, buttons and check boxes, types into dialogs, drags, waits for the app to
 * settle and captures screen pixels.
 */
final class GuiDriver {

    final AppFrame frame;
    final AppModel app;
    final AppPreferences prefs;
    final Robot robot;
    /** The window's size as the app opened it, before the tests set their own. */
    static Dimension openedSize;

    private GuiDriver(AppFrame frame, AppPreferences prefs) throws AWTException {
        this.frame = frame;
        this.app = frame.app();
        this.prefs = prefs;
        this.robot = new Robot();
        robot.setAutoDelay(5);
    }

    /** Starts the app (failing or skipping without a display, see {@link GuiTests}). */
    static GuiDriver launch() throws Exception {
        GuiTests.requireDisplay();
        AppPreferences prefs = new AppPreferences(MemoryPreferences.root().node(AppPreferences.NODE));
        AppFrame f = BezierTracerApp.start(prefs).get(30, TimeUnit.SECONDS);
        openedSize = onEdt(() -> f.getSize());
        onEdt(() -> {
            f.setSize(new Dimension(960, 600));
            f.setLocation(0, 0);
            f.toFront();
            return null;
        });
        GuiDriver d = new GuiDriver(f, prefs);
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

    /** Waits until nothing is pending (edits, loads, overlay, render) and the last repaint is on screen. */
    void settle() {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        int quiet = 0;
        while (quiet < 3) {
            robot.waitForIdle();
            boolean busy = onEdt(app::busy);
            quiet = busy ? 0 : quiet + 1;
            robot.delay(busy ? 20 : 40);
            if (System.nanoTime() > end) {
                fail("the app did not settle within 60 s");
            }
        }
    }

    /** Waits (up to 20 s) until {@code condition}, checked on the event thread, holds. */
    void waitFor(String what, BooleanSupplier condition) {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!onEdt(condition::getAsBoolean)) {
            robot.delay(20);
            if (System.nanoTime() > end) {
                fail("timed out waiting for " + what);
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

    static Component find(Component root, String name) {
        return descendant(root, Component.class, c -> name.equals(c.getName()));
    }

    /** Clicks the centre of a component (scrolling it into view first). */
    void click(Component comp) {
        alignDialog(comp);
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
        if (idleAfterClick) {
            robot.waitForIdle();
        } else {
            robot.delay(50);
        }
    }

    /**
     * Moves the dialog that holds {@code comp} (if any) to where Java believes it is. Without a
     * window manager, a loaded X server sometimes leaves a freshly shown dialog somewhere else
     * than the bounds Java reports (a CI run saw Java say (0, 0) for a dialog drawn centred), so a
     * click computed from Java's coordinates lands beside it; moving it by a pixel and back makes
     * the X window follow Java's bounds. Plumbing: the app's own placement is not under test.
     */
    private void alignDialog(Component comp) {
        boolean moved = onEdt(() -> {
            Window w = SwingUtilities.getWindowAncestor(comp);
            if (!(w instanceof JDialog) || !w.isShowing()) {
                return false;
            }
            Point p = w.getLocation();
            w.setLocation(p.x + 1, p.y);
            w.setLocation(p);
            return true;
        });
        if (moved) {
            robot.waitForIdle();
        }
    }

    /** Clicks {@code field} (again, if a click is dropped) until it has the keyboard focus. */
    void focus(Component field) {
        clickUntil(field, "the keyboard focus in " + field.getName(), field::isFocusOwner);
    }

    /** Clicks the tool {@code tool.<id>} in the toolbox. */
    void tool(String id) {
        click(find("tool." + id));
    }

    /** Opens the menu called {@code title} in the menu bar and clicks its item {@code menu.<id>}, with the mouse. */
    void menu(String title, String id) {
        menuPath(title, id.startsWith("menu.") ? id.substring("menu.".length()) : id);
    }

    /**
     * As {@link #menu}, without waiting for the event queue to go idle after the click: while a
     * progressive path-traced render refines, every pass repaints the panel, so the queue is idle
     * only once the whole render is done.
     */
    void menuBusy(String title, String id) {
        idleAfterClick = false;
        try {
            menu(title, id);
        } finally {
            idleAfterClick = true;
        }
    }

    /** Whether {@link #click} and {@link #menuPath} wait for the event queue to go idle after the click ({@link #menuBusy}). */
    private boolean idleAfterClick = true;

    /**
     * Opens menu {@code title}, then each submenu {@code menu.<id>} of {@code path} in turn, and clicks
     * the last item, with the mouse.
     */
    void menuPath(String title, String... path) {
        for (int attempt = 1; ; attempt++) {
            if (openAndClick(title, path)) {
                return;
            }
            // the menu closed without the item's action firing: the click was lost (a menu closed
            // under the mouse by a focus change or a repaint). Open the path again rather than go on
            // with a setting that never changed.
            if (attempt == 3) {
                fail(title + " → " + String.join(" → ", path) + " did not fire after three tries; screen: "
                        + save(robot.createScreenCapture(new Rectangle(java.awt.Toolkit.getDefaultToolkit().getScreenSize())),
                                "menu-lost"));
            }
            key(KeyEvent.VK_ESCAPE);
            robot.waitForIdle();
        }
    }

    /** One try of {@link #menuPath}: whether the last item's action fired. */
    private boolean openAndClick(String title, String... path) {
        JMenu m = onEdt(() -> {
            for (int k = 0; k < frame.getJMenuBar().getMenuCount(); k++) {
                if (title.equals(frame.getJMenuBar().getMenu(k).getText())) {
                    return frame.getJMenuBar().getMenu(k);
                }
            }
            return null;
        });
        if (m == null) {
            fail("no menu " + title);
        }
        JMenu current = m;
        for (int p = 0; p < path.length; p++) {
            String name = "menu." + path[p];
            JMenu in = current;
            JMenuItem item = onEdt(() -> {
                for (Component c : in.getMenuComponents()) {
                    if (c instanceof JMenuItem mi && name.equals(mi.getName())) {
                        return mi;
                    }
                }
                return null;
            });
            if (item == null) {
                fail("no item " + name + " in " + onEdt(in::getText));
            }
            if (p == 0) {
                clickUntil(m, title + " → " + name + " showing", item::isShowing);
            } else {
                waitFor(name + " showing", item::isShowing);
            }
            if (item instanceof JMenu sub) {
                click(item);
                waitFor(name + " open", sub::isPopupMenuVisible);
                current = sub;
            } else {
                java.util.concurrent.atomic.AtomicBoolean fired = new java.util.concurrent.atomic.AtomicBoolean();
                java.awt.event.ActionListener listener = e -> fired.set(true);
                onEdt(() -> {
                    item.addActionListener(listener);
                    return null;
                });
                try {
                    clickUntil(item, name + " chosen", () -> fired.get() || !item.isShowing());
                    if (idleAfterClick) {
                        robot.waitForIdle();
                    }
                    return onEdt(fired::get);
                } finally {
                    onEdt(() -> {
                        item.removeActionListener(listener);
                        return null;
                    });
                }
            }
        }
        throw new AssertionError("the path " + String.join(" → ", path) + " ends in a submenu");
    }

    /** The visible dialog that holds a {@code type} (a file chooser, an option pane), waiting up to 10 s. */
    <T extends Component> JDialog dialogWith(Class<T> type) {
        for (int k = 0; k < 400; k++) {
            JDialog found = onEdt(() -> {
                for (Window w : Window.getWindows()) {
                    if (w instanceof JDialog jd && jd.isShowing() && descendant(jd, type) != null) {
                        return jd;
                    }
                }
                return null;
            });
            if (found != null) {
                return found;
            }
            robot.delay(25);
        }
        throw new AssertionError("no dialog with a " + type.getSimpleName() + " opened");
    }

    static <T extends Component> T descendant(Component root, Class<T> type) {
        return descendant(root, type, c -> true);
    }

    /** The first component below {@code root} (itself included, depth first) of {@code type} that {@code test} accepts. */
    static <T extends Component> T descendant(Component root, Class<T> type, java.util.function.Predicate<T> test) {
        if (type.isInstance(root) && test.test(type.cast(root))) {
            return type.cast(root);
        }
        if (root instanceof Container ct) {
            for (Component child : ct.getComponents()) {
                T hit = descendant(child, type, test);
                if (hit != null) {
                    return hit;
                }
            }
        }
        return null;
    }

    /** In the open file chooser, types {@code file} into the name field and presses Enter. */
    void chooseFile(Path file) {
        JDialog dialog = dialogWith(JFileChooser.class);
        JTextField name = onEdt(() -> descendant(dialog, JTextField.class));
        focus(name);
        key(KeyEvent.VK_A, KeyEvent.VK_CONTROL);
        key(KeyEvent.VK_DELETE);
        type(file.toString());
        waitFor("the path typed into the file chooser", () -> file.toString().equals(name.getText()));
        key(KeyEvent.VK_ENTER);
        waitFor("the file chooser to close", () -> !dialog.isShowing());
    }

    /** The message of the open option dialog. */
    String optionMessage(JDialog dialog) {
        return onEdt(() -> String.valueOf(descendant(dialog, JOptionPane.class).getMessage()));
    }

    /** The button labelled {@code text} in {@code root}, or null. */
    static AbstractButton button(Container root, String text) {
        return descendant(root, AbstractButton.class, b -> text.equals(b.getText()));
    }

    /** Types plain ASCII text (letters, digits, / . - _ space) with the keyboard. */
    void type(String text) {
        for (char c : text.toCharArray()) {
            boolean shift = Character.isUpperCase(c) || c == '_';
            int code;
            if (Character.isLetter(c) && c < 128) {
                code = KeyEvent.VK_A + Character.toLowerCase(c) - 'a';
            } else if (Character.isDigit(c)) {
                code = KeyEvent.VK_0 + c - '0';
            } else {
                code = switch (c) {
                    case '/' -> KeyEvent.VK_SLASH;
                    case '.' -> KeyEvent.VK_PERIOD;
                    case '-', '_' -> KeyEvent.VK_MINUS;
                    case ' ' -> KeyEvent.VK_SPACE;
                    default -> throw new IllegalArgumentException("cannot type '" + c + "'");
                };
            }
            press(code, shift ? new int[] {KeyEvent.VK_SHIFT} : new int[0]);
        }
    }

    /** Screen position of a device-pixel position in the render panel. */
    Point screenOf(double deviceX, double deviceY) {
        return onEdt(() -> {
            Point s = frame.renderPanel().getLocationOnScreen();
            double scale = frame.renderPanel().deviceScale();
            return new Point(s.x + (int) Math.round(deviceX / scale), s.y + (int) Math.round(deviceY / scale));
        });
    }

    /** Where control point (i, j) of patch {@code p} is on screen now. */
    Point screenOfPoint(int p, int i, int j) {
        double[] at = onEdt(() -> {
            BezierPatch patch = app.document().scene().patches().get(p);
            double[] out = new double[3];
            app.view().projector().project(patch.get(i, j, 0), patch.get(i, j, 1), patch.get(i, j, 2), out);
            return out;
        });
        return screenOf(at[0], at[1]);
    }

    /** {@code screen} relative to the render panel (screen pixels). */
    Point inPanel(Point screen) {
        Point origin = onEdt(() -> frame.renderPanel().getLocationOnScreen());
        return new Point(screen.x - origin.x, screen.y - origin.y);
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

    /** {@link #drag} with {@code keys} (e.g. {@code VK_SHIFT}) held down from before the press to after the release. */
    void dragHolding(Point a, Point b, int steps, int... keys) {
        for (int k : keys) {
            robot.keyPress(k);
        }
        try {
            drag(a, b, steps);
        } finally {
            for (int k = keys.length - 1; k >= 0; k--) {
                robot.keyRelease(keys[k]);
            }
            robot.waitForIdle();
        }
    }

    /** Clicks the left button at {@code p} (screen) with {@code keys} held. */
    void clickAt(Point p, int... keys) {
        robot.mouseMove(p.x, p.y);
        robot.waitForIdle();
        for (int k : keys) {
            robot.keyPress(k);
        }
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        for (int k = keys.length - 1; k >= 0; k--) {
            robot.keyRelease(keys[k]);
        }
        robot.waitForIdle();
    }

    /** Clicks the text field, replaces its text by {@code text} with the keyboard and presses Enter. */
    void typeInto(JTextField field, String text) {
        focus(field);
        key(KeyEvent.VK_A, KeyEvent.VK_CONTROL);
        type(text);
        waitFor("the text typed into " + field.getName(), () -> text.equals(field.getText()));
        key(KeyEvent.VK_ENTER);
    }

    /** Types {@code value} into the spinner {@code name} of {@code dialog} and leaves it with Tab, then waits for the value. */
    void typeSpinner(javax.swing.JDialog dialog, String name, String value) {
        javax.swing.JSpinner s = (javax.swing.JSpinner) find(dialog, name);
        JTextField field = ((javax.swing.JSpinner.DefaultEditor) s.getEditor()).getTextField();
        focus(field);
        key(KeyEvent.VK_A, KeyEvent.VK_CONTROL);
        type(value);
        waitFor(name + " typed", () -> value.equals(field.getText()));
        key(KeyEvent.VK_TAB);
        waitFor(name + " = " + value, () -> String.valueOf(s.getValue()).equals(value));
    }

    /** Moves the mouse out of the way (to a corner of the picture), so no handle is hovered. */
    void mouseAway() {
        Point away = screenOf(3, 3);
        robot.mouseMove(away.x, away.y);
        robot.waitForIdle();
    }

    /** Gives the picture the keyboard focus (arrow keys, X/Y/Z, Escape go to it). */
    void focusPicture() {
        onEdt(() -> frame.renderPanel().requestFocusInWindow());
        waitFor("the picture to have the focus", () -> frame.renderPanel().isFocusOwner());
    }

    void key(int code, int... modifiers) {
        press(code, modifiers);
        robot.waitForIdle();
    }

    /**
     * Presses and releases a key without waiting for the event thread: typing waits once for the
     * text instead (Robot.waitForIdle after each key cost seconds a key in a file chooser on Xvfb).
     */
    private void press(int code, int... modifiers) {
        for (int m : modifiers) {
            robot.keyPress(m);
        }
        robot.keyPress(code);
        robot.keyRelease(code);
        for (int k = modifiers.length - 1; k >= 0; k--) {
            robot.keyRelease(modifiers[k]);
        }
    }

    void ctrl(int code) { key(code, KeyEvent.VK_CONTROL); }

    /** The render panel as on screen now. */
    BufferedImage capturePanel() {
        return capture(frame.renderPanel());
    }

    BufferedImage capture(Component c) {
        Rectangle r = onEdt(() -> {
            Point s = c.getLocationOnScreen();
            return new Rectangle(s.x, s.y, c.getWidth(), c.getHeight());
        });
        return robot.createScreenCapture(r);
    }

    /** The status bar label {@code status.<key>}. */
    String status(String key) {
        return onEdt(() -> frame.statusBar().text(key));
    }

    /** Pixels of {@code a} and {@code b} in a box that differ by more than {@code tol} in some channel. */
    static int differing(BufferedImage a, BufferedImage b, Rectangle box, int tol) {
        int count = 0;
        int height = Math.min(a.getHeight(), b.getHeight()), width = Math.min(a.getWidth(), b.getWidth());
        for (int y = Math.max(0, box.y); y < Math.min(height, box.y + box.height); y++) {
            for (int x = Math.max(0, box.x); x < Math.min(width, box.x + box.width); x++) {
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

    /** Writes {@code img} to {@code target/gui-shots/NAME.png} (to look at after a failure); returns the path. */
    static String save(BufferedImage img, String name) {
        try {
            Path dir = Path.of("target", "gui-shots");
            java.nio.file.Files.createDirectories(dir);
            Path f = dir.resolve(name + ".png");
            javax.imageio.ImageIO.write(img, "png", f.toFile());
            return f.toString();
        } catch (java.io.IOException e) {
            return "(not saved: " + e.getMessage() + ")";
        }
    }

    /** Pixels that differ anywhere. */
    static int differing(BufferedImage a, BufferedImage b, int tol) {
        return differing(a, b, new Rectangle(0, 0, a.getWidth(), a.getHeight()), tol);
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

    /**
     * Set-up plumbing: closes any dialog or menu a failed test left open (a modal dialog would
     * otherwise swallow every later test's input) and brings the main window to the front.
     */
    void dismissStrayWindows() {
        onEdt(() -> {
            javax.swing.MenuSelectionManager.defaultManager().clearSelectedPath();
            for (Window w : Window.getWindows()) {
                if (w != frame && w.isShowing() && w.getOwner() != null) {
                    w.dispose();
                }
            }
            frame.toFront();
        });
        robot.waitForIdle();
    }

    /**
     * Clicks {@code comp} until {@code done} holds: a real X server may drop a click that lands
     * while a new window is still being mapped (seen on a loaded CI machine), so the click is
     * repeated, up to three times, 5 s apart.
     */
    void clickUntil(Component comp, String what, BooleanSupplier done) {
        for (int attempt = 0; attempt < 3; attempt++) {
            click(comp);
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
            while (System.nanoTime() < end) {
                if (onEdt(done::getAsBoolean)) {
                    return;
                }
                robot.delay(20);
            }
        }
        fail("timed out waiting for " + what + " after three clicks on " + comp.getClass().getSimpleName()
                + "; windows: " + onEdt(GuiDriver::describeWindows) + "; screen: " + save(robot.createScreenCapture(
                new Rectangle(java.awt.Toolkit.getDefaultToolkit().getScreenSize())), "click-dropped"));
    }

    /** The showing windows, their titles, modality, focus and bounds (for a failure message). */
    static String describeWindows() {
        StringBuilder sb = new StringBuilder();
        for (Window w : Window.getWindows()) {
            if (w.isShowing()) {
                sb.append('[').append(w.getClass().getSimpleName());
                if (w instanceof JDialog jd) {
                    sb.append(" \"").append(jd.getTitle()).append("\" modal=").append(jd.isModal());
                }
                sb.append(" active=").append(w.isActive()).append(" at ").append(w.getBounds()).append("] ");
            }
        }
        return sb.toString();
    }

    /** Closes the window without the unsaved-edits question. */
    void close() {
        onEdt(() -> {
            app.document().history().markSaved();
            frame.close();
        });
    }
}
