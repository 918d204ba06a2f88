package org.beziertracer.ui;

import javax.swing.Action;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;

import org.beziertracer.app.ModelLoader;

/** File, Edit, Models, View, Render and Help menus, built from {@link AppActions}. */
public final class AppMenuBar extends JMenuBar {

    private final AppActions a;

    public AppMenuBar(AppActions actions, Runnable about) {
        this.a = actions;
        JMenu file = menu("File", 'F', "open", "save", "saveAs", null, "exportPng", "exportMesh", null, "quit");
        JMenu edit = menu("Edit", 'E', "undo", "redo");
        JMenu models = new JMenu("Models");
        models.setMnemonic('M');
        for (String name : ModelLoader.BUILT_INS) {
            models.add(item("model:" + name));
        }
        JMenu view = menu("View", 'V', "rayTrace", "polygon", "points", "wireframe", null, "finer", "coarser", null,
                "resetView", "zoomIn", "zoomOut", "morePerspective", "lessPerspective", null, "dark");
        JMenu surface = menu("Surface", 'S', "resetPoints", "randomize", null, "gridU", "gridV");
        JMenu render = menu("Render", 'R', "phong", "texture", "normals", "shadows", "reflections", "light", null,
                "superSampling", "spp", "moreInteractive", "lessInteractive", null, "method", "bvh", "tessellated", "tessellation");
        JMenu help = new JMenu("Help");
        help.setMnemonic('H');
        JMenuItem aboutItem = new JMenuItem("About Bézier Tracer");
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
            if (id == null) {
                m.addSeparator();
            } else {
                m.add(item(id));
            }
        }
        return m;
    }

    private JMenuItem item(String id) {
        Action action = a.get(id);
        JMenuItem item = action.getValue(Action.SELECTED_KEY) != null ? new JCheckBoxMenuItem(action) : new JMenuItem(action);
        item.setName("menu." + id);
        return item;
    }
}
