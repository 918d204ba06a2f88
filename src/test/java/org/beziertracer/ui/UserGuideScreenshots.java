package org.beziertracer.ui;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.beziertracer.app.SettingsModel;
import org.beziertracer.app.Toggle;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Regenerates the user guide's screenshots (not a test; skipped unless asked):
 * {@code xvfb-run -a -s '-screen 0 1280x800x24' mvn -B -q test -Dtest=UserGuideScreenshots -Dscreenshots=docs/images}.
 */
@Tag("gui")
class UserGuideScreenshots {

    @Test
    void writeScreenshots() throws Exception {
        String out = System.getProperty("screenshots");
        Assumptions.assumeTrue(out != null && !java.awt.GraphicsEnvironment.isHeadless(),
                "screenshots are written only with -Dscreenshots=DIR under a display");
        Path dir = Path.of(out);
        Files.createDirectories(dir);
        GuiDriver d = GuiDriver.launch();
        try {
            SettingsModel t = d.app.settings();
            GuiDriver.onEdt(() -> d.frame.setSize(1100, 720));
            // The default patch, bent, a control point under the cursor
            GuiDriver.onEdt(() -> d.app.edits().randomize(7));
            d.settle();
            java.awt.Point p = d.screenOfPoint(0, 2, 1);
            d.robot.mouseMove(p.x, p.y);
            shot(d, dir, "patch.png");
            GuiDriver.onEdt(() -> t.set(Toggle.RAY_TRACE, false));
            shot(d, dir, "wireframe.png");
            GuiDriver.onEdt(() -> {
                t.set(Toggle.RAY_TRACE, true);
                t.set(Toggle.NORMALS, true);
                t.set(Toggle.CONTROL_POLYGON, false);
            });
            shot(d, dir, "normals.png");
            GuiDriver.onEdt(() -> {
                d.app.document().history().markSaved();
                d.app.files().openBuiltIn("teapot");
            });
            d.settle();
            GuiDriver.onEdt(() -> {
                t.set(Toggle.NORMALS, false);
                t.set(Toggle.CONTROL_POINTS, false);
                t.set(Toggle.CONTROL_POLYGON, false);
                t.set(Toggle.SUPER_SAMPLING, true);
            });
            shot(d, dir, "teapot.png");
            GuiDriver.onEdt(() -> d.app.files().openBuiltIn("teapot-room"));
            d.settle();
            GuiDriver.onEdt(() -> t.set(Toggle.SUPER_SAMPLING, true));
            shot(d, dir, "teapot-room.png");
        } finally {
            d.close();
        }
    }

    private static void shot(GuiDriver d, Path dir, String name) throws Exception {
        d.settle();
        d.robot.delay(300);
        Rectangle r = GuiDriver.onEdt(() -> d.frame.getBounds());
        BufferedImage img = d.robot.createScreenCapture(r);
        ImageIO.write(img, "png", dir.resolve(name).toFile());
    }
}
