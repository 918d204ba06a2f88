package org.beziertracer.ui;

import java.awt.FlowLayout;
import java.util.Locale;

import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSeparator;
import javax.swing.SwingConstants;

/**
 * Frame ms, Mrays/s, pass k of n, samples per pixel, method, BVH speed-up, grid and the last
 * message (for instance the random seed). Reads the controller on every refresh.
 */
public final class StatusBar extends JPanel {

    private final AppController c;
    private final JLabel frame = label("time since the render started, at the latest pass; snapshot: re-split and BVH refit (or build)");
    private final JLabel rays = label("millions of rays per second");
    private final JLabel pass = label("progressive pass finished / passes per frame");
    private final JLabel spp = label("samples per pixel");
    private final JLabel method = label("intersection method, or \"tessellated K\" when the surface is rendered as K×K triangles per patch");
    private final JLabel bvh = label("sub-patch BVH and its measured speed-up over whole patches");
    private final JLabel model = label("patches and control points of the model");
    private final JLabel message = label("last action");

    public StatusBar(AppController controller) {
        super(new FlowLayout(FlowLayout.LEFT, 8, 2));
        this.c = controller;
        setBorder(BorderFactory.createMatteBorder(1, 0, 0, 0, getForeground().darker()));
        for (JLabel l : new JLabel[] {frame, rays, pass, spp, method, bvh, model, message}) {
            add(l);
            if (l != message) {
                add(new JSeparator(SwingConstants.VERTICAL));
            }
        }
        frame.setName("status.frame");
        pass.setName("status.pass");
        bvh.setName("status.bvh");
        method.setName("status.method");
        message.setName("status.message");
        c.addListener(this::refresh);
        refresh();
    }

    private static JLabel label(String tip) {
        JLabel l = new JLabel(" ");
        l.setToolTipText(tip);
        return l;
    }

    public void refresh() {
        RenderStatus s = c.status();
        ToolSettings t = c.tools();
        if (!t.rayTrace) {
            frame.setText("wireframe");
            rays.setText("—");
            pass.setText("—");
        } else if (s != null) {
            frame.setText(String.format(Locale.ROOT, "%.1f ms (snapshot %.1f ms)", s.millis(), s.prepMillis()));
            rays.setText(String.format(Locale.ROOT, "%.2f Mrays/s", s.mraysPerSecond()));
            pass.setText("pass " + s.pass() + " of " + s.passCount());
        }
        spp.setText((t.superSampling ? t.samplesPerPixel : 1) + " spp");
        method.setText(t.intersectionLabel());
        String speedUp = s != null && s.bvhSpeedUp() > 0 ? String.format(Locale.ROOT, " ×%.1f", s.bvhSpeedUp()) : "";
        bvh.setText(t.bvh ? "BVH on" + speedUp : "BVH off" + speedUp);
        int points = 0;
        for (var p : c.scene().patches()) {
            points += p.pointCount();
        }
        model.setText(c.scene().patchCount() + " patch" + (c.scene().patchCount() == 1 ? "" : "es") + ", " + points
                + " points; new grid " + t.gridPointsU + "×" + t.gridPointsV);
        message.setText(c.message());
    }

    /** Text of the label called {@code status.<key>} (tests). */
    public String text(String key) {
        return switch (key) {
            case "frame" -> frame.getText();
            case "pass" -> pass.getText();
            case "bvh" -> bvh.getText();
            case "method" -> method.getText();
            default -> message.getText();
        };
    }
}
