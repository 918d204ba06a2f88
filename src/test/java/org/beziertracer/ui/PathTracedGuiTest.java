package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Render → Path Traced through the real menus ({@link java.awt.Robot}): the samples a pixel in
 * the status bar rise while the picture changes (it refines), and an edit starts it again; Render →
 * Brighter Exposure brightens the picture while it goes on refining (no restart) and moves the
 * toolbox's exposure slider.
 */
@Tag("gui")
class PathTracedGuiTest extends GuiSession {

    private static final Pattern SAMPLES = Pattern.compile("(\\d+) of (\\d+) spp, .+ samples/s");

    /** The samples a pixel the status bar shows now, or -1 while it shows none yet (event thread). */
    private static int shownSamples() {
        Matcher m = SAMPLES.matcher(d.frame.statusBar().text("spp"));
        return m.matches() ? Integer.parseInt(m.group(1)) : -1;
    }

    /** {@link #shownSamples()} from the test thread. */
    private static int samples() {
        return GuiDriver.onEdt(PathTracedGuiTest::shownSamples);
    }

    /**
     * As {@link GuiDriver#waitFor} with up to 120 s: a pass of the path tracer over the whole picture
     * may take seconds on a machine shared with other builds.
     */
    private static void waitLong(String what, java.util.function.BooleanSupplier condition) {
        long end = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(120);
        while (!GuiDriver.onEdt(condition::getAsBoolean)) {
            assertTrue(System.nanoTime() < end, () -> "timed out waiting for " + what + "; status: "
                    + GuiDriver.onEdt(() -> d.frame.statusBar().text("spp") + " | " + d.frame.statusBar().text("pass") + " | "
                    + d.frame.statusBar().text("frame") + " | " + d.frame.statusBar().text("message")));
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError(what, e);
            }
        }
    }

    /** Mean of the three channels over the panel, 0..255. */
    private static double brightness(BufferedImage img) {
        double[] m = GuiDriver.mean(img, new java.awt.Rectangle(0, 0, img.getWidth(), img.getHeight()));
        return (m[0] + m[1] + m[2]) / 3;
    }

    private static int exposureSlider() {
        return GuiDriver.onEdt(() -> ((javax.swing.JSlider) GuiDriver.find(d.frame, "tool.exposure")).getValue());
    }

    @Test
    void aBrighterExposureBrightensThePictureWhileItKeepsRefining() {
        d.menuBusy("Render", "pathTraced");
        waitLong("two path-traced samples in every pixel", () -> shownSamples() >= 2);
        d.mouseAway();
        double before = brightness(d.capturePanel());
        int samplesBefore = samples();
        d.menuBusy("Render", "brighter");
        d.menuBusy("Render", "brighter");
        // the film is tone mapped again at once, whatever pass is in progress
        long end = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(60);
        double after = brightness(d.capturePanel());
        while (after < before + 4 && System.nanoTime() < end) {
            after = brightness(d.capturePanel());
        }
        int samplesAfter = samples();
        assertTrue(after >= before + 4, "one stop brighter: mean " + before + " → " + after);
        assertTrue(samplesAfter >= samplesBefore, "the samples went on, not from the start: " + samplesBefore + " → "
                + samplesAfter + " spp");
        assertTrue(d.status("spp").contains(" of 256 spp"), d.status("spp"));
        assertTrue(exposureSlider() == 10, "the toolbox shows +1 EV: " + exposureSlider());
        assertTrue(GuiDriver.onEdt(() -> d.app.settings().current().exposure()) == 1.0);
        // more samples at the new exposure, unless the render had already reached its target (on a quiet
        // machine 256 spp of the default patch take about 10 s, as long as the steps above may take)
        waitLong("more samples at the new exposure", () -> shownSamples() >= samplesAfter + 1 || shownSamples() == 256);
        d.menuBusy("Render", "resetExposure");
        assertTrue(GuiDriver.onEdt(() -> d.app.settings().current().exposure()) == 0, "reset to 0 EV");
        waitLong("the slider back at 0", () -> ((javax.swing.JSlider) GuiDriver.find(d.frame, "tool.exposure")).getValue() == 0);
        d.menu("Render", "pathTraced");
        d.settle();
    }

    @Test
    void thePathTracedPictureRefinesWhileTheSamplesRiseAndAnEditStartsItAgain() {
        BufferedImage whitted = shot();
        d.menuBusy("Render", "pathTraced");
        waitLong("a first path-traced sample in every pixel", () -> shownSamples() >= 1);
        int early = samples();
        BufferedImage first = d.capturePanel();
        waitLong("more samples a pixel", () -> shownSamples() >= early + 2);
        BufferedImage later = d.capturePanel();
        String text = d.status("spp");
        assertTrue(SAMPLES.matcher(text).matches() && text.contains(" of 256 spp"), "the target is shown: " + text);
        int changed = GuiDriver.differing(first, later, 2);
        assertTrue(changed > 50, "the picture refines: " + changed + " pixels changed "
                + GuiDriver.save(first, "path-first") + " " + GuiDriver.save(later, "path-later"));
        assertTrue(GuiDriver.differing(whitted, later, 8) > 500, "path traced, not the Whitted picture: "
                + GuiDriver.save(whitted, "path-whitted"));

        int before = samples();
        d.menuBusy("Surface", "randomize");
        waitLong("the count to start again below " + before, () -> shownSamples() >= 0 && shownSamples() < before);
        d.menu("Render", "pathTraced");
        d.settle();
        assertTrue(d.status("spp").endsWith(" spp") && !d.status("spp").contains(" of "),
                "Whitted again: " + d.status("spp"));
    }
}
