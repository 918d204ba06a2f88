package org.beziertracer.ui;

import java.awt.BorderLayout;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.event.InputEvent;

import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.WindowConstants;

/**
 * The main window: render panel in the centre, toolbox on the left, menu bar and status bar.
 * Closing asks about unsaved edits.
 */
public final class AppFrame extends JFrame {

    private final AppController controller;
    private final AppActions actions;
    private final RenderPanel renderPanel;
    private final ToolboxPanel toolbox;
    private final StatusBar statusBar;

    public AppFrame(PictureEngine engine) {
        super("Bézier Tracer");
        setName("beziertracer.main");
        controller = new AppController(engine, null);
        controller.setDialogs(new SwingDialogs(this));
        actions = new AppActions(controller, this::toggleTheme, Theme::isDark, this::close);
        renderPanel = new RenderPanel(controller);
        toolbox = new ToolboxPanel(controller, actions);
        statusBar = new StatusBar(controller);
        setJMenuBar(new AppMenuBar(actions, this::about));
        JScrollPane side = new JScrollPane(toolbox, JScrollPane.VERTICAL_SCROLLBAR_AS_NEEDED,
                JScrollPane.HORIZONTAL_SCROLLBAR_NEVER);
        side.setBorder(null);
        side.getVerticalScrollBar().setUnitIncrement(16);
        getContentPane().add(side, BorderLayout.WEST);
        getContentPane().add(renderPanel, BorderLayout.CENTER);
        getContentPane().add(statusBar, BorderLayout.SOUTH);
        bindExtraKeys();
        controller.addListener(() -> setTitle(controller.title()));
        setTitle(controller.title());
        setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                close();
            }
        });
        pack();
        setLocationByPlatform(true);
    }

    /** Ctrl+Y as a second redo key (the menu shows Ctrl+Shift+Z). */
    private void bindExtraKeys() {
        JComponent root = getRootPane();
        root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW)
                .put(KeyStroke.getKeyStroke(KeyEvent.VK_Y, InputEvent.CTRL_DOWN_MASK), "redo");
        root.getActionMap().put("redo", actions.get("redo"));
    }

    private void toggleTheme() {
        Theme.toggle();
        actions.refresh();
    }

    private void about() {
        JOptionPane.showMessageDialog(this, "Bézier Tracer — ray tracing Bézier surfaces directly.\n"
                + "Drag control points, drag empty space to rotate, wheel to zoom.", "About", JOptionPane.INFORMATION_MESSAGE);
    }

    /** Asks about unsaved edits, then stops rendering and disposes the window. */
    public void close() {
        if (controller.quit()) {
            dispose();
        }
    }

    public AppController controller() { return controller; }

    public AppActions actions() { return actions; }

    public RenderPanel renderPanel() { return renderPanel; }

    public ToolboxPanel toolbox() { return toolbox; }

    public StatusBar statusBar() { return statusBar; }
}
