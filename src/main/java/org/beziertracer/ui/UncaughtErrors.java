package org.beziertracer.ui;

import java.awt.Component;

import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;

import org.beziertracer.render.Failures;

/**
 * The app's last line of defence: an exception no one caught, on any thread, is logged (with its
 * stack trace, on the console) and shown in a dialog as one line without class names; the app
 * keeps running. While one such dialog is open, further errors are only logged, so an error that
 * repeats (in painting, say) cannot flood the screen.
 */
final class UncaughtErrors implements Thread.UncaughtExceptionHandler {

    /** Title of the dialog. */
    static final String TITLE = "Something went wrong — the app keeps running";

    private final Component parent;
    private boolean showing;

    private UncaughtErrors(Component parent) {
        this.parent = parent;
    }

    /** Makes this the handler of every thread that has none of its own. */
    static void install(Component parent) {
        Thread.setDefaultUncaughtExceptionHandler(new UncaughtErrors(parent));
    }

    @Override
    public void uncaughtException(Thread t, Throwable e) {
        System.err.println("beziertracer: uncaught error on thread " + t.getName() + ":");
        e.printStackTrace();
        String line = Failures.describe(e);
        if (SwingUtilities.isEventDispatchThread()) {
            show(line);
        } else {
            SwingUtilities.invokeLater(() -> show(line));
        }
    }

    private void show(String line) {
        if (showing) {
            return;
        }
        showing = true;
        try {
            JOptionPane.showMessageDialog(parent, line, TITLE, JOptionPane.ERROR_MESSAGE);
        } finally {
            showing = false;
        }
    }
}
