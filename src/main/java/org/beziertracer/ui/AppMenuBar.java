package org.beziertracer.ui;

import javax.swing.Action;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;

import org.beziertracer.app.AppPreferences;
import org.beziertracer.app.ModelLoader;

/** File, Edit, Models, View, Surface, Render and Help menus, built from {@link AppActions}. */
public final class AppMenuBar extends JMenuBar {

    private final AppActions a;
    private final JMenu recent = new JMenu("Open Recent");
    private final JMenuItem noRecent = new JMenuItem("(no recent files)");

    /**
     * @param about     Help → About
     * @param shortcuts Help → Keyboard Shortcuts
     */
    public AppMenuBar(AppActions actions, Runnable about, Runnable shortcuts) {
        this.a = actions;
        JMenu file = menu("File", 'F', "open");
        file.add(recentMenu());
        for (String id : new String[] {"save", "saveAs", null, "exportPng", "exportImage", "exportMesh", null, "quit"}) {
            addItem(file, id);
        }
        JMenu edit = menu("Edit", 'E', "undo", "redo", null, "selectAll", "clearSelection");
        JMenu nudge = menu("Nudge Selection", 'N', "nudgeLeft", "nudgeRight", "nudgeUp", "nudgeDown", null, "nudgeLeft10",
                "nudgeRight10", "nudgeUp10", "nudgeDown10");
        nudge.setName("menu.nudge");
        edit.add(nudge);
        edit.addSeparator();
        edit.add(item("smoothJoins"));
        edit.add(item("curvatureJoins"));
        JMenu models = new JMenu("Models");
        models.setMnemonic('M');
        for (String name : ModelLoader.BUILT_INS) {
            models.add(item("model:" + name));
        }
        JMenu view = menu("View", 'V', "rayTrace", "polygon", "points", "wireframe", "differenceToClipping", "continuity", null, "finer", "coarser", null,
                "resetView", "zoomIn", "zoomOut", "morePerspective", "lessPerspective", null, "inspector", "dark");
        JMenu analysis = new JMenu("Analysis");
        analysis.setName("menu.analysis");
        analysis.setMnemonic('A');
        for (String id : AppActions.ANALYSIS_IDS) {
            analysis.add(item(id));
            if (id.equals("analysis:none")) {
                analysis.addSeparator();
            }
        }
        analysis.addSeparator();
        analysis.add(item("analysisSettings"));
        view.insert(analysis, 5);
        JMenu surface = menu("Surface", 'S', "revertPoints", "resetPoints", "randomize", null, "gridU", "gridV");
        JMenu render = menu("Render", 'R', "phong", "texture", "normals", "shadows", "reflections", "light", "showLight", null,
                "superSampling", "spp", "moreInteractive", "lessInteractive", null, "pathTraced", "pathSamples", "pathSeconds", "brighter", "darker", "resetExposure", null, "method", "bvh", "tessellated", "tessellation");
        JMenu help = new JMenu("Help");
        help.setMnemonic('H');
        help.setName("menu.help");
        JMenuItem shortcutsItem = new JMenuItem("Keyboard Shortcuts");
        shortcutsItem.setName("menu.shortcuts");
        shortcutsItem.setMnemonic('K');
        shortcutsItem.setToolTipText("Every keyboard shortcut, as the keys are bound now");
        shortcutsItem.addActionListener(e -> shortcuts.run());
        help.add(shortcutsItem);
        help.addSeparator();
        JMenuItem aboutItem = new JMenuItem("About Bézier Tracer");
        aboutItem.setName("menu.about");
        aboutItem.addActionListener(e -> about.run());
        help.add(aboutItem);
        for (JMenu m : new JMenu[] {file, edit, models, view, surface, render, help}) {
            add(m);
        }
    }

    private JMenu menu(String title, char mnemonic, String... ids) {
        JMenu m = new JMenu(title);
        m.setMnemonic(mnemonic);
        for (String id : ids) {
            addItem(m, id);
        }
        return m;
    }

    private void addItem(JMenu m, String id) {
        if (id == null) {
            m.addSeparator();
        } else {
            m.add(item(id));
        }
    }

    /** File → Open Recent: the recent files, shown as they are when the menu opens. */
    private JMenu recentMenu() {
        recent.setName("menu.openRecent");
        recent.setMnemonic('R');
        noRecent.setEnabled(false);
        recent.add(noRecent);
        for (int k = 0; k < AppPreferences.MAX_RECENT; k++) {
            recent.add(item("recent" + k));
        }
        recent.addMenuListener(new javax.swing.event.MenuListener() {
            @Override
            public void menuSelected(javax.swing.event.MenuEvent e) { syncRecent(); }

            @Override
            public void menuDeselected(javax.swing.event.MenuEvent e) {}

            @Override
            public void menuCanceled(javax.swing.event.MenuEvent e) {}
        });
        syncRecent();
        return recent;
    }

    /** Shows one item per recent file. */
    void syncRecent() {
        a.refresh();
        int n = a.recentCount();
        noRecent.setVisible(n == 0);
        for (int k = 0; k < AppPreferences.MAX_RECENT; k++) {
            recent.getItem(k + 1).setVisible(k < n);
        }
    }

    private JMenuItem item(String id) {
        Action action = a.get(id);
        JMenuItem item = action.getValue(Action.SELECTED_KEY) != null ? new JCheckBoxMenuItem(action) : new JMenuItem(action);
        item.setName("menu." + id);
        return item;
    }
}
