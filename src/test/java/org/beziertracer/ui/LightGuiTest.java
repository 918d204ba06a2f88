package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Point;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.util.Arrays;
import java.util.List;

import org.beziertracer.app.LightMarker;
import org.beziertracer.app.LightPlacement;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;

/**
 * GUI tests of the first look: the default light above left of the eye, "at the eye" one preset
 * away, and Render → Show Light drawing a marker that the mouse drags. Checks are on pixels.
 */
@Tag("gui")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class LightGuiTest extends GuiSession {

    @Test
    @Order(1)
    void theDefaultLightComesFromAboveLeftAndAtTheEyeIsOnePresetAway() {
        Rectangle centre = centreBox();
        BufferedImage aboveLeft = shot();
        javax.swing.JComboBox<?> light = d.find("tool.light");
        assertEquals(LightPlacement.EYE_ABOVE_LEFT, GuiDriver.onEdt(() -> light.getSelectedItem()));
        d.menu("Render", "light");
        BufferedImage atEye = shot();
        assertEquals(LightPlacement.AT_EYE, GuiDriver.onEdt(() -> light.getSelectedItem()), "Render → Next Light Position once");
        int changed = GuiDriver.differing(aboveLeft, atEye, 10);
        assertTrue(changed > 1000, "the light moved: " + changed + " pixels " + GuiDriver.save(aboveLeft, "light-above-left")
                + " " + GuiDriver.save(atEye, "light-at-eye"));
        // Lit from the upper left, the flat patch is brighter towards its left: a gradient the eye light lacks
        Point left = d.inPanel(d.screenOfPoint(0, 0, 1)), right = d.inPanel(d.screenOfPoint(0, 3, 2));
        double gradient = contrast(aboveLeft, left, right), flat = contrast(atEye, left, right);
        assertTrue(gradient > flat + 5, "shading varies across the patch: " + gradient + " vs at the eye " + flat);
    }

    /** Red of the surface near {@code a} (nudged towards {@code b}) minus near {@code b}. */
    private static double contrast(BufferedImage img, Point a, Point b) {
        Point pa = new Point(a.x + (b.x - a.x) / 6, a.y + (b.y - a.y) / 6), pb = new Point(b.x + (a.x - b.x) / 6, b.y + (a.y - b.y) / 6);
        return GuiDriver.mean(img, new Rectangle(pa.x - 3, pa.y - 3, 6, 6))[0] - GuiDriver.mean(img, new Rectangle(pb.x - 3, pb.y - 3, 6, 6))[0];
    }

    @Test
    @Order(2)
    void showLightDrawsAMarkerThatTheMouseDrags() {
        BufferedImage without = shot();
        d.menu("Render", "showLight");
        BufferedImage with = shot();
        List<LightMarker> markers = GuiDriver.onEdt(() -> d.app.overlay().snapshot().lights());
        assertEquals(1, markers.size());
        LightMarker m = markers.get(0);
        Point at = d.screenOf(m.x(), m.y());
        Point in = d.inPanel(at);
        double[] sun = GuiDriver.mean(with, new Rectangle(in.x - 2, in.y - 2, 5, 5));
        assertTrue(sun[0] > 200 && sun[1] > 180 && sun[2] < 160, "a yellow sun at the light: " + Arrays.toString(sun)
                + " " + GuiDriver.save(with, "light-marker"));
        assertTrue(GuiDriver.differing(without, with, new Rectangle(in.x - 15, in.y - 15, 30, 30), 30) > 30,
                "drawn over the picture");
        Point to = new Point(at.x + 160, at.y + 120);
        d.drag(at, to, 12);
        BufferedImage dragged = shot();
        LightMarker now = GuiDriver.onEdt(() -> d.app.overlay().snapshot().lights()).get(0);
        Point nowIn = d.inPanel(d.screenOf(now.x(), now.y()));
        Point toIn = d.inPanel(to);
        assertTrue(Math.abs(nowIn.x - toIn.x) <= 2 && Math.abs(nowIn.y - toIn.y) <= 2, "the marker followed the mouse: "
                + nowIn + " vs " + toIn);
        double[] moved = GuiDriver.mean(dragged, new Rectangle(nowIn.x - 2, nowIn.y - 2, 5, 5));
        assertTrue(moved[0] > 200 && moved[1] > 180 && moved[2] < 160, "the sun is drawn there: " + Arrays.toString(moved));
        Rectangle centre = centreBox();
        assertTrue(GuiDriver.differing(with, dragged, new Rectangle(centre.x - 60, centre.y - 40, 120, 80), 8) > 200,
                "the surface is lit from the new place: " + GuiDriver.save(dragged, "light-dragged"));
        d.focusPicture();
        d.key(java.awt.event.KeyEvent.VK_L, java.awt.event.KeyEvent.VK_CONTROL, java.awt.event.KeyEvent.VK_SHIFT);
        BufferedImage hidden = shot();
        assertTrue(GuiDriver.mean(hidden, new Rectangle(nowIn.x - 2, nowIn.y - 2, 5, 5))[2] > 0
                && GuiDriver.differing(dragged, hidden, new Rectangle(nowIn.x - 15, nowIn.y - 15, 30, 30), 30) > 30,
                "Ctrl+Shift+L hides the marker again");
    }
}
