package org.beziertracer.ui;

import java.awt.Component;
import java.io.File;
import java.nio.file.Path;
import java.util.Locale;

import javax.swing.JFileChooser;
import javax.swing.JOptionPane;
import javax.swing.filechooser.FileNameExtensionFilter;

import org.beziertracer.model.io.FilePaths;
import org.beziertracer.app.ExportOptions;
import org.beziertracer.app.ModelLoader;
import org.beziertracer.app.UserDialogs;
import org.beziertracer.model.io.FileFormat;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.io.FileFormats;
import org.beziertracer.render.SamplerKind;

/** {@link UserDialogs} with {@link JFileChooser} and {@link JOptionPane}, remembering the last folder. */
final class SwingDialogs implements UserDialogs {

    private final Component parent;
    private File folder = new File(System.getProperty("user.dir"));

    SwingDialogs(Component parent) {
        this.parent = parent;
    }

    @Override
    public Path chooseOpen() {
        JFileChooser fc = new JFileChooser(folder);
        fc.setDialogTitle("Open model or scene");
        for (FileFormat f : ModelLoader.OPEN_FORMATS) {
            fc.addChoosableFileFilter(new FileNameExtensionFilter(f.filterLabel(),
                    f.extensions().toArray(String[]::new)));
        }
        fc.setFileFilter(new FileNameExtensionFilter("Models and scenes ("
                + FileFormats.patterns(ModelLoader.OPEN_FORMATS) + ")",
                FileFormats.extensions(ModelLoader.OPEN_FORMATS).toArray(String[]::new)));
        if (fc.showOpenDialog(parent) != JFileChooser.APPROVE_OPTION) {
            return null;
        }
        folder = fc.getCurrentDirectory();
        return path(fc.getSelectedFile());
    }

    @Override
    public Path chooseSave(String title, String... extensions) {
        JFileChooser fc = new JFileChooser(folder);
        fc.setDialogTitle(title);
        for (String ext : extensions) {
            fc.addChoosableFileFilter(new FileNameExtensionFilter(ext.toUpperCase(Locale.ROOT) + " (*." + ext + ")", ext));
        }
        fc.setFileFilter(fc.getChoosableFileFilters()[1]);
        if (fc.showSaveDialog(parent) != JFileChooser.APPROVE_OPTION) {
            return null;
        }
        folder = fc.getCurrentDirectory();
        File f = fc.getSelectedFile();
        String name = f.getName().toLowerCase(Locale.ROOT);
        boolean known = false;
        for (String ext : extensions) {
            known |= name.endsWith("." + ext);
        }
        if (!known) {
            String ext = fc.getFileFilter() instanceof FileNameExtensionFilter ff ? ff.getExtensions()[0] : extensions[0];
            f = new File(f.getPath() + "." + ext);
        }
        if (f.exists() && JOptionPane.showConfirmDialog(parent, f.getName() + " exists. Replace it?", title,
                JOptionPane.OK_CANCEL_OPTION) != JOptionPane.OK_OPTION) {
            return null;
        }
        return path(f);
    }

    @Override
    public Choice confirmDiscard(String documentName) {
        Object[] options = {"Save", "Discard", "Cancel"};
        int answer = JOptionPane.showOptionDialog(parent, documentName + " has unsaved edits. Save them first?",
                "Unsaved edits", JOptionPane.YES_NO_CANCEL_OPTION, JOptionPane.WARNING_MESSAGE, null, options,
                options[0]);
        return switch (answer) {
            case 0 -> Choice.SAVE;
            case 1 -> Choice.DISCARD;
            default -> Choice.CANCEL;
        };
    }

    /**
     * The chosen file as a path ({@link FilePaths}); a name this locale cannot pass on (a new
     * non-ASCII name under {@code LANG=C}) is a one-line error, and null.
     */
    private Path path(File f) {
        Path p = FilePaths.find(f.getPath()).orElse(null);
        if (p == null) {
            error("Cannot use " + f.getName(), f.getPath() + ": " + FilePaths.invalidName());
        }
        return p;
    }

    @Override
    public void error(String title, String message) {
        JOptionPane.showMessageDialog(parent, message, title, JOptionPane.ERROR_MESSAGE);
    }

    @Override
    public ExportOptions exportOptions(ExportOptions offer) {
        javax.swing.JSpinner width = spinner("export.width", offer.width(), RenderSettings.MAX_SIZE, "Image width in pixels");
        javax.swing.JSpinner height = spinner("export.height", offer.height(), RenderSettings.MAX_SIZE, "Image height in pixels");
        javax.swing.JSpinner spp = spinner("export.spp", offer.spp(), RenderSettings.MAX_SPP,
                "Samples per pixel: more smooths edges and costs time");
        javax.swing.JComboBox<SamplerKind> sampler = new javax.swing.JComboBox<>(SamplerKind.values());
        sampler.setName("export.sampler");
        sampler.setSelectedItem(offer.sampler());
        sampler.setRenderer(new LabelRenderer<>(SamplerKind.class, SamplerKind::label));
        sampler.setToolTipText("Where the samples of a pixel go: regular grid, jittered grid, or adaptive (more "
                + "samples only where neighbours differ)");
        javax.swing.JCheckBox path = new javax.swing.JCheckBox("Path traced", offer.pathTraced());
        path.setName("export.path");
        path.setToolTipText("Physically based path tracing (area lights, environment, metal and glass), tone mapped; "
                + "off: the Whitted renderer");
        javax.swing.JSpinner seconds = spinner("export.seconds", offer.seconds(), ExportOptions.MAX_SECONDS,
                "Path tracer: stop after this many seconds even before all samples are traced (0 = no limit)");
        ((javax.swing.SpinnerNumberModel) seconds.getModel()).setMinimum(0);
        seconds.setValue(offer.seconds()); // the shared spinner starts at 1 at least; 0 means no limit
        seconds.setEnabled(offer.pathTraced());
        path.addActionListener(e -> seconds.setEnabled(path.isSelected()));
        javax.swing.JPanel panel = form(new Object[][] {{"Width", width}, {"Height", height}, {"Samples per pixel", spp},
                {"Sampler", sampler}, {"Integrator", path}, {"Time limit (s)", seconds}});
        if (JOptionPane.showConfirmDialog(parent, panel, "Export image", JOptionPane.OK_CANCEL_OPTION,
                JOptionPane.PLAIN_MESSAGE) != JOptionPane.OK_OPTION) {
            return null;
        }
        try {
            return new ExportOptions((Integer) width.getValue(), (Integer) height.getValue(), (Integer) spp.getValue(),
                    (SamplerKind) sampler.getSelectedItem(), path.isSelected(),
                    path.isSelected() ? (Integer) seconds.getValue() : 0);
        } catch (IllegalArgumentException e) {
            error("Cannot export", e.getMessage());
            return null;
        }
    }

    @Override
    public org.beziertracer.render.Analysis analysisSettings(org.beziertracer.render.Analysis current) {
        return AnalysisSettingsPanel.ask(parent, current);
    }

    /** A two-column form: each row's label (its text) beside its component, the label pointing at it. */
    static javax.swing.JPanel form(Object[][] rows) {
        javax.swing.JPanel panel = new javax.swing.JPanel(new java.awt.GridLayout(0, 2, 6, 4));
        for (Object[] row : rows) {
            javax.swing.JLabel l = new javax.swing.JLabel((String) row[0]);
            l.setLabelFor((Component) row[1]);
            panel.add(l);
            panel.add((Component) row[1]);
        }
        return panel;
    }

    private static javax.swing.JSpinner spinner(String name, int value, int max, String tip) {
        javax.swing.JSpinner s = new javax.swing.JSpinner(new javax.swing.SpinnerNumberModel(
                Math.max(1, Math.min(max, value)), 1, max, 1));
        s.setName(name);
        s.setToolTipText(tip);
        return s;
    }
}
