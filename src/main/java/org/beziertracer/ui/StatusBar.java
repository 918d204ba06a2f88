package org.beziertracer.ui;

import java.util.Locale;

import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JSeparator;
import javax.swing.SwingConstants;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.DifferenceMask;
import org.beziertracer.app.OverlayGeometry;
import org.beziertracer.app.RenderStatus;
import org.beziertracer.app.Settings;
import org.beziertracer.app.Task;
import org.beziertracer.app.Toggle;

/**
 * Frame ms, Mrays/s, pass k of n, samples per pixel, method, BVH speed-up, model size, the last
 * message (for instance the random seed), and — while a model is opened or saved, an image exported
 * or the continuity analysed — a progress bar with its count ({@link Task#text()}) and a Cancel
 * button. Reads the app's status snapshot on every refresh. Fields that do not fit on one row wrap to the next ({@link WrapFlowLayout}); none is ever dropped, and one wider than the
 * whole bar is elided with its full text in its tooltip.
 */
public final class StatusBar extends JPanel {

    private final AppModel app;
    private final JLabel frame = label("time since the render started, at the latest pass; snapshot: re-split and BVH refit (or build)");
    private final JLabel rays = label("millions of rays per second");
    private final JLabel pass = label("progressive pass finished / passes per frame");
    private final JLabel spp = label("samples per pixel");
    private final JLabel method = label("intersection method, or \"tessellated K\" when the surface is rendered as K×K triangles per patch");
    private final JLabel bvh = label("sub-patch BVH and its measured speed-up over whole patches");
    private final JLabel model = label("patches and control points of the model");
    private final JLabel selection = label("selected control points (welded copies count once)");
    private final JLabel difference = label("View → Difference to clipping: pixels whose hit differs from Bézier "
            + "clipping's (another patch, a miss, or farther than 1e-6 of the scene size), marked red in the picture");
    private final JLabel message = label("last action");
    private final JLabel legend = label("the analysis view and the values at the two ends of its colour scale");
    private JSeparator differenceBar;
    private final JProgressBar progress = new JProgressBar();
    private final JButton cancel = new JButton("Cancel");

    public StatusBar(AppModel app) {
        super(new WrapFlowLayout(8, 2));
        this.app = app;
        setBorder(BorderFactory.createMatteBorder(1, 0, 0, 0, getForeground().darker()));
        progress.setName("status.progress");
        progress.setToolTipText("opening or saving a model (the current one stays until it is read), exporting an image "
                + "or analysing continuity; the count is what is done of all");
        cancel.setName("status.cancel");
        cancel.setToolTipText("stop: an open keeps the current model, a save or an export leaves the file as it was");
        cancel.addActionListener(e -> cancelTask());
        add(progress);
        add(cancel);
        for (JLabel l : new JLabel[] {frame, rays, pass, spp, method, bvh, legend, model, selection, difference, message}) {
            add(l);
            if (l != message) {
                JSeparator bar = new JSeparator(SwingConstants.VERTICAL);
                add(bar);
                if (l == difference) {
                    differenceBar = bar;
                }
            }
        }
        frame.setName("status.frame");
        pass.setName("status.pass");
        spp.setName("status.spp");
        bvh.setName("status.bvh");
        method.setName("status.method");
        model.setName("status.model");
        selection.setName("status.selection");
        difference.setName("status.difference");
        message.setName("status.message");
        legend.setName("status.legend");
        app.addListener(this::refresh);
        refresh();
    }

    private void cancelTask() {
        Task t = app.status().task();
        if (t != null) {
            t.cancel();
        }
    }

    private static final String ABOUT = "status.about";

    private static JLabel label(String tip) {
        JLabel l = new JLabel(" ");
        l.putClientProperty(ABOUT, tip);
        l.setToolTipText(tip);
        return l;
    }

    /** Each field's tooltip: its whole text (shown even when the field is elided), then what it is. */
    private void tooltips() {
        for (JLabel l : new JLabel[] {frame, rays, pass, spp, method, bvh, legend, model, selection, difference, message}) {
            String text = l.getText() == null ? "" : l.getText().strip();
            l.setToolTipText(text.isEmpty() ? (String) l.getClientProperty(ABOUT) : text + " — " + l.getClientProperty(ABOUT));
        }
    }

    public void refresh() {
        RenderStatus s = app.status().render();
        Settings t = app.settings().current();
        if (!t.on(Toggle.RAY_TRACE)) {
            frame.setText("wireframe");
            rays.setText("—");
            pass.setText("—");
        } else if (s != null) {
            frame.setText(String.format(Locale.ROOT, "%.1f ms (snapshot %.1f ms)", s.millis(), s.prepMillis()));
            rays.setText(String.format(Locale.ROOT, "%.2f Mrays/s", s.mraysPerSecond()));
            pass.setText("pass " + s.pass() + " of " + s.passCount());
        }
        spp.setText(!t.pathTraced() ? t.samplesPerPixel() + " spp"
                : s != null && s.pathTraced() && t.on(Toggle.RAY_TRACE) ? s.samplesText() : "path traced");
        method.setText(t.intersectionLabel());
        String speedUp = s != null && s.bvhSpeedUp() > 0 ? String.format(Locale.ROOT, " ×%.1f", s.bvhSpeedUp()) : "";
        bvh.setText(t.on(Toggle.BVH) ? "BVH on" + speedUp : "BVH off" + speedUp);
        model.setText(modelText(app.overlay().geometry(), t));
        String key = t.analysis() == null ? "" : s != null && s.shading() == t.analysis() ? s.legend() : t.analysis().label();
        String under = t.analysis() == null ? "" : app.hover().text();
        key = under.isEmpty() ? key : key + " · " + under;
        legend.setText(key);
        legend.setVisible(!key.isEmpty());
        int handles = app.selection().handleCount();
        selection.setText(handles == 0 ? "nothing selected" : handles == 1 ? "1 point selected" : handles + " points selected");
        differenceText(t);
        message.setText(app.status().message());
        tooltips();
        Task task = app.status().task();
        progress.setVisible(task != null);
        cancel.setVisible(task != null);
        progress.setString(task == null ? "" : task.text());
        progress.setStringPainted(task != null);
        // Animated only while shown and without a fraction: a hidden indeterminate bar still ticks
        // its 15 ms timer, waking the event thread 66 times a second for nothing
        progress.setIndeterminate(task != null && task.progress() < 0);
        if (task != null && task.progress() >= 0) {
            progress.setValue((int) Math.round(100 * task.progress()));
        }
    }

    /** Shown only while View → Difference to clipping is on. */
    private void differenceText(Settings t) {
        boolean on = t.on(Toggle.DIFFERENCE_TO_CLIPPING);
        DifferenceMask mask = app.difference().current();
        difference.setVisible(on);
        differenceBar.setVisible(on);
        difference.setText(!on ? "" : mask != null ? mask.describe() : "comparing with clipping…");
    }

    private static String modelText(OverlayGeometry g, Settings t) {
        String grid = "new grid " + t.level(org.beziertracer.app.Level.GRID_U) + "×" + t.level(org.beziertracer.app.Level.GRID_V);
        if (g.scene() == null) {
            return grid;
        }
        int patches = g.scene().patchCount();
        return patches + " patch" + (patches == 1 ? "" : "es") + ", " + g.pointCount() + " points; " + grid;
    }

    /** Text of the label called {@code status.<key>} (tests). */
    public String text(String key) {
        return switch (key) {
            case "frame" -> frame.getText();
            case "pass" -> pass.getText();
            case "spp" -> spp.getText();
            case "bvh" -> bvh.getText();
            case "method" -> method.getText();
            case "model" -> model.getText();
            case "selection" -> selection.getText();
            case "difference" -> difference.getText();
            case "legend" -> legend.getText();
            default -> message.getText();
        };
    }
}
