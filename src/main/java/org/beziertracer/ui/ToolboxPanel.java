package org.beziertracer.ui;

import java.awt.Component;
import java.awt.Dimension;
import java.awt.GridLayout;
import java.util.function.IntConsumer;

import javax.swing.Action;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.Level;
import org.beziertracer.app.LightPlacement;
import org.beziertracer.app.Settings;
import org.beziertracer.app.SettingsModel;
import org.beziertracer.app.Toggle;
import org.beziertracer.intersect.Method;

/**
 * The memoir's toolbox (annex 2) plus our extras: buttons and check boxes bound to
 * {@link AppActions} (so they share names, shortcuts and tooltips with the menus), sliders,
 * spinners and combo boxes whose listeners are one-liners into the app's {@link SettingsModel}.
 * Every control has a name ({@code tool.<id>}) for tests, a tooltip and a shortcut.
 */
public final class ToolboxPanel extends JPanel {

    private final AppModel app;
    private final AppActions actions;
    private boolean syncing;
    private final JSlider subdivision;
    private final JSlider interactivity;
    private final JSlider perspective;
    private final JSlider exposure;
    private final JSpinner gridU;
    private final JSpinner gridV;
    private final JComboBox<Integer> spp = new JComboBox<>(boxed(Level.SAMPLES_PER_PIXEL.choices()));
    private final JComboBox<Method> method = new JComboBox<>(Method.values());
    private final JComboBox<Integer> tessellation = new JComboBox<>(boxed(Level.TESSELLATION.choices()));
    private final JComboBox<LightPlacement> light = new JComboBox<>(LightPlacement.values());

    public ToolboxPanel(AppModel app, AppActions actions) {
        this.app = app;
        this.actions = actions;
        subdivision = slider(1, 64, "subdivision", "Wireframe subdivision: granularity of the "
                + "projected 2-D evaluation", "finer", "coarser");
        interactivity = slider(1, 8, "interactivity", "Interactivity: progressive passes per "
                + "displayed frame (left: responsive, right: fewer redraws)", "moreInteractive", "lessInteractive");
        perspective = slider(0, 100, "perspective", "Perspective: from parallel rays "
                + "(orthographic) to strong divergence", "morePerspective", "lessPerspective");
        exposure = slider(Level.EXPOSURE.min(), Level.EXPOSURE.max(), "exposure", "Exposure of the path-traced "
                + "picture, −5..+5 stops (tone mapped again at once; the picture keeps refining)", "brighter", "darker");
        gridU = spinner("gridU", "Control points along u of a new patch (Reset)");
        gridV = spinner("gridV", "Control points along v of a new patch (Reset)");
        setLayout(new BoxLayout(this, BoxLayout.Y_AXIS));
        setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        SettingsModel s = app.settings();
        for (JPanel p : new JPanel[] {surfaceSection(s), viewSection(s), shadingSection(s), qualitySection(s)}) {
            add(p);
        }
        add(Box.createVerticalGlue());
        app.addListener(this::refresh);
        refresh();
    }

    private JPanel surfaceSection(SettingsModel s) {
        JPanel surface = section("Surface");
        surface.add(button("revertPoints"));
        surface.add(button("resetPoints"));
        surface.add(button("randomize"));
        surface.add(check("smoothJoins"));
        surface.add(check("curvatureJoins"));
        surface.add(row(new JLabel("New grid u × v"), gridU, gridV));
        gridU.addChangeListener(e -> onInt(v -> s.set(Level.GRID_U, v), (Integer) gridU.getValue()));
        gridV.addChangeListener(e -> onInt(v -> s.set(Level.GRID_V, v), (Integer) gridV.getValue()));
        return surface;
    }

    private JPanel viewSection(SettingsModel s) {
        JPanel view = section("View");
        view.add(button("resetView"));
        JButton mode = new JButton(actions.get("rayTrace"));
        mode.setName("tool.rayTrace");
        view.add(mode);
        view.add(check("polygon"));
        view.add(check("points"));
        view.add(check("wireframe"));
        view.add(labelled("Wireframe subdivision", subdivision));
        view.add(labelled("Perspective", perspective));
        subdivision.addChangeListener(e -> onInt(v -> s.set(Level.WIREFRAME_SUBDIVISION, v), subdivision.getValue()));
        perspective.addChangeListener(e -> onInt(v -> s.set(Level.PERSPECTIVE, v), perspective.getValue()));
        view.add(check("dark"));
        return view;
    }

    private JPanel shadingSection(SettingsModel s) {
        JPanel shading = section("Shading");
        shading.add(check("phong"));
        shading.add(check("texture"));
        shading.add(check("normals"));
        shading.add(check("shadows"));
        shading.add(check("reflections"));
        shading.add(labelled("Light", combo(light, "light", "Light position")));
        shading.add(check("showLight"));
        shading.add(labelled("Exposure", exposure));
        exposure.addChangeListener(e -> onInt(v -> s.set(Level.EXPOSURE, v), exposure.getValue()));
        light.addActionListener(e -> onInt(v -> s.set(LightPlacement.values()[v]), light.getSelectedIndex()));
        return shading;
    }

    private JPanel qualitySection(SettingsModel s) {
        method.setRenderer(new LabelRenderer<>(Method.class, Method::label, Method::description));
        JPanel quality = section("Quality and speed");
        quality.add(check("superSampling"));
        quality.add(labelled("Samples per pixel", combo(spp, "spp", "Samples per pixel when super-sampling")));
        quality.add(labelled("Interactivity", interactivity));
        quality.add(labelled("Method", combo(method, "method", "Ray–patch intersection method")));
        quality.add(check("bvh"));
        quality.add(check("tessellated"));
        quality.add(labelled("K (cells per side)", combo(tessellation, "tessellation",
                "Tessellated mode: K×K cells per patch, two triangles each")));
        tessellation.addActionListener(e -> onInt(v -> s.set(Level.TESSELLATION, v), (Integer) tessellation.getSelectedItem()));
        spp.addActionListener(e -> onInt(v -> s.set(Level.SAMPLES_PER_PIXEL, v), (Integer) spp.getSelectedItem()));
        method.addActionListener(e -> onInt(v -> s.set(Method.values()[v]), method.getSelectedIndex()));
        interactivity.addChangeListener(e -> onInt(v -> s.set(Level.INTERACTIVITY, v), interactivity.getValue()));
        return quality;
    }

    private static Integer[] boxed(int[] values) {
        return java.util.Arrays.stream(values).boxed().toArray(Integer[]::new);
    }

    private void onInt(IntConsumer apply, int value) {
        if (!syncing) {
            apply.accept(value);
        }
    }

    /** Brings sliders, spinners and combos in line with the settings. */
    public void refresh() {
        Settings t = app.settings().current();
        syncing = true;
        try {
            subdivision.setValue(t.level(Level.WIREFRAME_SUBDIVISION));
            interactivity.setValue(t.level(Level.INTERACTIVITY));
            perspective.setValue(t.level(Level.PERSPECTIVE));
            exposure.setValue(t.level(Level.EXPOSURE));
            exposure.setEnabled(t.pathTraced());
            gridU.setValue(t.level(Level.GRID_U));
            gridV.setValue(t.level(Level.GRID_V));
            spp.setSelectedItem(t.level(Level.SAMPLES_PER_PIXEL));
            spp.setEnabled(t.on(Toggle.SUPER_SAMPLING));
            method.setSelectedItem(t.method());
            tessellation.setSelectedItem(t.level(Level.TESSELLATION));
            tessellation.setEnabled(t.on(Toggle.TESSELLATED));
            light.setSelectedItem(t.light());
        } finally {
            syncing = false;
        }
    }

    private JPanel section(String title) {
        JPanel p = new JPanel(new GridLayout(0, 1, 2, 2));
        p.setBorder(BorderFactory.createTitledBorder(title));
        p.setAlignmentX(Component.LEFT_ALIGNMENT);
        return p;
    }

    private JButton button(String id) {
        JButton b = new JButton(actions.get(id));
        b.setName("tool." + id);
        return b;
    }

    private JCheckBox check(String id) {
        JCheckBox b = new JCheckBox(actions.get(id));
        b.setName("tool." + id);
        return b;
    }

    private JSlider slider(int min, int max, String id, String tip, String up, String down) {
        JSlider s = new JSlider(min, max, min);
        s.setName("tool." + id);
        s.setToolTipText(tip + " (" + shortcut(up) + " / " + shortcut(down) + ")");
        s.setPreferredSize(new Dimension(150, s.getPreferredSize().height));
        return s;
    }

    private String shortcut(String id) {
        return AppActions.keyText((javax.swing.KeyStroke) actions.get(id).getValue(Action.ACCELERATOR_KEY));
    }

    private JSpinner spinner(String id, String tip) {
        JSpinner s = new JSpinner(new SpinnerNumberModel(4, 2, 10, 1));
        s.setName("tool." + id);
        s.setToolTipText(tip + " (" + shortcut(id) + ")");
        return s;
    }

    private JComponent combo(JComboBox<?> box, String id, String tip) {
        box.setName("tool." + id);
        String key = switch (id) {
            case "light" -> shortcut("light");
            case "spp" -> shortcut("spp");
            case "tessellation" -> shortcut("tessellation");
            default -> shortcut("method");
        };
        box.setToolTipText(tip + " (" + key + ")");
        return box;
    }

    private static JPanel labelled(String text, JComponent comp) {
        JPanel p = new JPanel(new java.awt.BorderLayout(4, 0));
        JLabel l = new JLabel(text);
        l.setToolTipText(comp.getToolTipText());
        l.setLabelFor(comp);
        p.add(l, java.awt.BorderLayout.WEST);
        p.add(comp, java.awt.BorderLayout.CENTER);
        return p;
    }

    private static JPanel row(JComponent... comps) {
        JPanel p = new JPanel(new GridLayout(1, comps.length, 4, 0));
        for (JComponent comp : comps) {
            p.add(comp);
        }
        return p;
    }

    /** Every named control of the toolbox (tests). */
    public static void forEachControl(Component root, java.util.function.Consumer<JComponent> visit) {
        if (root instanceof JComponent jc && jc.getName() != null && jc.getName().startsWith("tool.")) {
            visit.accept(jc);
        }
        if (root instanceof java.awt.Container ct) {
            for (Component child : ct.getComponents()) {
                forEachControl(child, visit);
            }
        }
    }
}
