package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.beziertracer.app.DifferenceMask;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * View → Difference to clipping through the real menus ({@link java.awt.Robot}): the red marks on
 * screen are the pixels the status bar counts, clipping itself shows none, and switching the view
 * off gives the normal picture back.
 */
@Tag("gui")
class DifferenceGuiTest extends GuiSession {

    private static final Pattern COUNT = Pattern.compile("(.+): (\\d+) pixels? differs? from clipping");

    /** Pure red on screen: a mark (the picture under the veil is at most half as bright). */
    private static int redPixels(BufferedImage img) {
        int n = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int c = img.getRGB(x, y);
                if (((c >> 16) & 0xFF) > 200 && ((c >> 8) & 0xFF) < 50 && (c & 0xFF) < 50) {
                    n++;
                }
            }
        }
        return n;
    }

    /** The count in the status bar for {@code method}. */
    private static int shownCount(String method) {
        String text = d.status("difference");
        Matcher m = COUNT.matcher(text);
        assertTrue(m.matches(), "the status bar counts the differing pixels: " + text);
        assertEquals(method, m.group(1), text);
        return Integer.parseInt(m.group(2));
    }

    private static boolean oneToOne() {
        return GuiDriver.onEdt(() -> d.frame.renderPanel().deviceScale()) == 1;
    }

    @Test
    void marksWhatTheSelectedMethodHitsDifferentlyAndSwitchesBackToTheNormalPicture() {
        d.menu("Models", "model:teapot");
        d.menu("View", "polygon"); // nothing drawn over the marks
        d.menu("View", "points");
        BufferedImage normal = shot();
        assertEquals(0, redPixels(normal), "no marks before: " + GuiDriver.save(normal, "difference-before"));
        assertEquals("", d.status("difference"), "off: no count");

        d.menu("View", "differenceToClipping");
        BufferedImage clipping = shot();
        assertEquals(0, shownCount("clipping"), "clipping against itself");
        assertEquals(0, redPixels(clipping), GuiDriver.save(clipping, "difference-clipping"));
        java.awt.Rectangle all = new java.awt.Rectangle(0, 0, normal.getWidth(), normal.getHeight());
        double[] veiled = GuiDriver.mean(clipping, all), plain = GuiDriver.mean(normal, all);
        assertTrue(veiled[0] < 0.7 * plain[0], "the picture is veiled, so marks would stand out: "
                + java.util.Arrays.toString(veiled) + " vs " + java.util.Arrays.toString(plain));

        d.menu("Render", "tessellated");
        BufferedImage tessellated = shot();
        int count = shownCount("tessellated 16");
        int red = redPixels(tessellated);
        assertTrue(count > 100, "flat triangles lie off the teapot: " + count);
        if (oneToOne()) {
            assertEquals(count, red, "one red pixel on screen per counted pixel: " + GuiDriver.save(tessellated,
                    "difference-tessellated"));
        } else {
            assertTrue(red > 0, "marks on screen");
        }
        DifferenceMask mask = GuiDriver.onEdt(() -> d.app.difference().current());
        assertEquals(count, mask.count());

        d.menu("Render", "tessellated");
        d.menu("Render", "method"); // clipping → Newton
        BufferedImage newton = shot();
        int newtonCount = shownCount("newton");
        assertTrue(newtonCount < count, "Newton is exact, unlike the triangles: " + newtonCount);
        if (oneToOne()) {
            assertEquals(newtonCount, redPixels(newton));
        }
        d.menu("Render", "method"); // subdivision
        d.menu("Render", "method"); // clipping
        d.settle();
        assertEquals(0, shownCount("clipping"));

        d.menu("View", "differenceToClipping");
        BufferedImage back = shot();
        assertEquals("", d.status("difference"));
        int changed = GuiDriver.differing(normal, back, 8);
        assertTrue(changed < 20, "switched off: the normal picture again (" + changed + " pixels differ) "
                + GuiDriver.save(normal, "difference-normal") + " " + GuiDriver.save(back, "difference-off"));
    }
}
