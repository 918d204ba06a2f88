package org.beziertracer.ui;

import java.awt.BorderLayout;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.function.Function;

import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JOptionPane;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.WindowConstants;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.UserDialogs;

/**
 * The main window: render panel in the centre, toolbox on the left, inspector on the right, menu
 * bar and status bar; model files can be dropped on it. Views and Swing adapters only; the app
 * itself is the {@link AppModel}. Closing asks about unsaved edits.
 */
public final class AppFrame extends JFrame {

    private final AppModel app;
    private final Theme theme;
    private final AppActions actions;
    private final RenderPanel renderPanel;
    private final ToolboxPanel toolbox;
    private final StatusBar statusBar;
    private final InspectorPanel inspector;
    private final ContinuityPanel continuity;

    /**
     * @param newApp makes the app with the dialogs this window shows
     * @param theme  the installed look and feel
     */
    public AppFrame(Function<UserDialogs, AppModel> newApp, Theme theme) {
        super("Bézier Tracer");
        setName("beziertracer.main");
        this.theme = theme;
        app = newApp.apply(new SwingDialogs(this));
        renderPanel = new RenderPanel(app);
        actions = new AppActions(app, renderPanel::snapshot, this::toggleTheme, theme::isDark, this::close);
        toolbox = new ToolboxPanel(app, actions);
        statusBar = new StatusBar(app);
        inspector = new InspectorPanel(app);
        setJMenuBar(new AppMenuBar(actions, this::about, this::shortcuts));
        JScrollPane side = new JScrollPane(toolbox, JScrollPane.VERTICAL_SCROLLBAR_AS_NEEDED,
                JScrollPane.HORIZONTAL_SCROLLBAR_NEVER);
        side.setBorder(null);
        side.getVerticalScrollBar().setUnitIncrement(16);
        getContentPane().add(side, BorderLayout.WEST);
        getContentPane().add(renderPanel, BorderLayout.CENTER);
        getContentPane().add(statusBar, BorderLayout.SOUTH);
        continuity = new ContinuityPanel(app);
        // the inspector takes the right column's height; View → Continuity's panel, when on, its own
        // height at the bottom of it (its table scrolls)
        javax.swing.JPanel east = new javax.swing.JPanel(new BorderLayout());
        east.add(inspector, BorderLayout.CENTER);
        east.add(continuity, BorderLayout.SOUTH);
        getContentPane().add(east, BorderLayout.EAST);
        setTransferHandler(new FileDrop(app.files()));
        bindExtraKeys();
        app.addListener(() -> setTitle(app.document().title()));
        setTitle(app.document().title());
        setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                close();
            }
        });
        pack();
        fitScreen();
        setLocationByPlatform(true);
    }

    /** Shrinks the packed window to the screen's usable area (a 1280×800 screen cut off the inspector). */
    private void fitScreen() {
        java.awt.Rectangle usable = getGraphicsConfiguration() == null ? null
                : java.awt.GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        if (usable != null && (getWidth() > usable.width || getHeight() > usable.height)) {
            setSize(Math.min(getWidth(), usable.width), Math.min(getHeight(), usable.height));
        }
    }

    /** Ctrl+Y as a second redo key (the menu shows Ctrl+Shift+Z). */
    private void bindExtraKeys() {
        JComponent root = getRootPane();
        root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW)
                .put(KeyStroke.getKeyStroke(KeyEvent.VK_Y, InputEvent.CTRL_DOWN_MASK), "redo");
        root.getActionMap().put("redo", actions.get("redo"));
    }

    private void toggleTheme() {
        theme.toggle();
        actions.refresh();
    }

    /** The shortcuts as bound now: the actions' accelerators and the window's own bindings. */
    java.util.List<ShortcutList.Row> shortcutRows() {
        return ShortcutList.of(actions.all().values(), getRootPane().getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW),
                getRootPane().getActionMap());
    }

    private void shortcuts() {
        ShortcutsDialog.show(this, shortcutRows());
    }

    private void about() {
        JOptionPane.showMessageDialog(this, org.beziertracer.app.AboutText.text(), "About",
                JOptionPane.INFORMATION_MESSAGE);
    }

    /** Asks about unsaved edits, then stops the app's threads and disposes the window. */
    public void close() {
        app.files().quit(this::dispose);
    }

    public AppModel app() { return app; }

    public Theme theme() { return theme; }

    public AppActions actions() { return actions; }

    public RenderPanel renderPanel() { return renderPanel; }

    public ToolboxPanel toolbox() { return toolbox; }

    public StatusBar statusBar() { return statusBar; }

    InspectorPanel inspector() { return inspector; }

    ContinuityPanel continuity() { return continuity; }
}
