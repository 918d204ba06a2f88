package org.beziertracer.ui;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

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
            ToolSettings t = d.c.tools();
            GuiDriver.onEdt(() -> d.frame.setSize(1100, 720));
            // The default patch, bent by dragging two points
            GuiDriver.onEdt(() -> {
                d.c.randomizeControlPoints(7);
                d.c.mouseMoved(d.c.projected().x(0, 2, 1), d.c.projected().y(0, 2, 1));
            });
            shot(d, dir, "patch.png");
            GuiDriver.onEdt(() -> d.c.setting(() -> t.rayTrace = false));
            shot(d, dir, "wireframe.png");
            GuiDriver.onEdt(() -> d.c.setting(() -> {
                t.rayTrace = true;
                t.normals = true;
                t.controlPolygon = false;
            }));
            shot(d, dir, "normals.png");
            GuiDriver.onEdt(() -> {
                d.c.history().markSaved();
                d.c.openBuiltIn("teapot");
                d.c.setting(() -> {
                    t.normals = false;
                    t.controlPoints = false;
                    t.controlPolygon = false;
                    t.superSampling = true;
                });
            });
            shot(d, dir, "teapot.png");
            GuiDriver.onEdt(() -> d.c.openBuiltIn("teapot-room"));
            GuiDriver.onEdt(() -> d.c.setting(() -> t.superSampling = true));
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
