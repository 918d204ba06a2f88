package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.Dimension;
import java.awt.Window;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;

import javax.swing.JDialog;
import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;

import org.beziertracer.app.Settings;
import org.beziertracer.app.SoakActions;
import org.beziertracer.app.SoakChecks;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The app soak: the real window under a seeded storm of random edits issued faster than frames
 * complete — first a few hundred real mouse drags, wheel clicks, shortcuts, toolbox clicks, menu
 * items and resizes ({@link RobotSoak}), then thousands of commands through the app layer's own
 * entry points, the calls the window's one-line handlers make ({@link SoakActions}), in bursts on
 * the event thread. Then, once the app is idle:
 * <ul>
 * <li>no exception escaped on any thread (a recording default handler replaces the app's dialog
 *     handler during the run), and no dialog is open — the app's error dialogs (a failed render or
 *     scene preparation, a failed edit or load) are the only ones these commands can open;</li>
 * <li>the picture equals, pixel for pixel, a fresh render of the final document, settings and view
 *     through the same render pipeline;</li>
 * <li>back on the first model with the default settings, the heap is within 2× of what it was
 *     after that model's first load.</li>
 * </ul>
 * The seed is printed; {@code -Dsoak.seed=N} replays the command sequence (not the threads'
 * timing).
 */
@Tag("gui")
class AppSoakGuiTest extends GuiSession {

    /** Most real-input actions. */
    static final int ROBOT_ACTIONS = Integer.getInteger("soak.robotActions", 240);
    /** Most seconds of real input (a loaded machine gets through fewer actions). */
    static final int ROBOT_SECONDS = Integer.getInteger("soak.robotSeconds", 15);
    /** App-layer commands, in {@link #ROUNDS} rounds. */
    static final int COMMANDS = Integer.getInteger("soak.commands", 3000);
    /** Checkpoints after the app-layer commands (one more follows the real input). */
    static final int ROUNDS = 2;
    static final String FIRST_MODEL = "teapot-room";
    static final Dimension SIZE = new Dimension(760, 520);

    @Test
    void aStormOfRandomEditsEndsOnFreshRendersWithNoErrorAndABoundedHeap() throws Exception {
        long seed = SoakChecks.seed("AppSoakGuiTest");
        long t0 = System.nanoTime();
        try (SoakChecks.Uncaught uncaught = SoakChecks.Uncaught.install()) {
            GuiDriver.onEdt(() -> d.frame.setSize(SIZE));
            d.menu("Models", "model:" + FIRST_MODEL);
            d.settle();
            long heapAfterLoad = SoakChecks.settledHeap();
            SoakActions commands = new SoakActions(d.app, seed ^ 0x9E3779B97F4A7C15L,
                    () -> d.app.document().history().markSaved(), false);

            Map<String, Integer> robot = robotPhase(seed);
            checkpoint(commands, uncaught, "after the real input (seed " + seed + ")");
            long robotDone = System.nanoTime();
            Random pace = new Random(seed ^ 0x5DEECE66DL);
            SoakChecks.Final last = null;
            for (int round = 1; round <= ROUNDS; round++) {
                commands.issue(SwingUtilities::invokeLater, COMMANDS / ROUNDS, pace);
                last = checkpoint(commands, uncaught, "after round " + round + " of the commands (seed " + seed + ")");
            }
            long checked = System.nanoTime();

            long heapAfterRun = heapBackOnTheFirstModel();
            System.out.printf("AppSoakGuiTest: %d robot actions %s and a checkpoint in %.1f s; %d app commands (%s) and "
                            + "%d checkpoints in %.1f s; heap %.1f MB after the first load, %.1f MB after the run; "
                            + "total %.1f s; last state %s%n",
                    robot.values().stream().mapToInt(Integer::intValue).sum(), robot, (robotDone - t0) / 1e9,
                    commands.total(), GuiDriver.onEdt(commands::summary), ROUNDS, (checked - robotDone) / 1e9,
                    heapAfterLoad / 1e6, heapAfterRun / 1e6, (System.nanoTime() - t0) / 1e9, last.describe());
            assertTrue(heapAfterRun <= 2 * heapAfterLoad, "heap " + heapAfterRun + " after the run, " + heapAfterLoad
                    + " after the first load (seed " + seed + ")");
        }
    }

    /**
     * Waits until the app is idle (ray trace on, see {@link SoakActions#finish}), then: nothing
     * escaped, no dialog is open, the picture is a fresh render of the state.
     */
    private static SoakChecks.Final checkpoint(SoakActions commands, SoakChecks.Uncaught uncaught, String where)
            throws Exception {
        SoakChecks.Final state = SoakChecks.idleState(GuiDriver::onEdt, d.app, commands, 60_000);
        assertEquals(List.of(), uncaught.seen(), "no exception escaped on any thread " + where);
        noDialogOpen();
        assertNull(state.mismatch(state.freshRender()), "the picture is a fresh render of the state " + where);
        return state;
    }

    /** Real input, a few hundred actions (fewer when the machine is slow), checking for dialogs every 20. */
    private static Map<String, Integer> robotPhase(long seed) {
        RobotSoak soak = new RobotSoak(d, seed);
        Map<String, Integer> kinds = new TreeMap<>();
        GuiDriver.onEdt(() -> d.frame.renderPanel().requestFocusInWindow());
        int autoDelay = d.robot.getAutoDelay();
        d.robot.setAutoDelay(1);
        long end = System.nanoTime() + ROBOT_SECONDS * 1_000_000_000L;
        while (soak.count() < ROBOT_ACTIONS && System.nanoTime() < end) {
            kinds.merge(soak.step(), 1, Integer::sum);
            if (soak.count() % 20 == 0) {
                d.robot.waitForIdle();
                noDialogOpen();
            }
        }
        d.robot.setAutoDelay(autoDelay);
        d.robot.waitForIdle();
        return kinds;
    }

    /** Fails, naming it, when a dialog is open (closing it first, so the window can close). */
    private static void noDialogOpen() {
        List<String> open = GuiDriver.onEdt(() -> {
            List<String> out = new ArrayList<>();
            for (Window w : Window.getWindows()) {
                if (w instanceof JDialog dialog && dialog.isShowing()) {
                    JOptionPane pane = GuiDriver.descendant(dialog, JOptionPane.class);
                    out.add(dialog.getTitle() + ": " + (pane == null ? "" : pane.getMessage()));
                    dialog.dispose();
                }
            }
            return out;
        });
        if (!open.isEmpty()) {
            fail("a dialog opened during the soak: " + open);
        }
    }

    /** The first model again, with the default settings, the first size, idle: its heap after full collections. */
    private static long heapBackOnTheFirstModel() throws InterruptedException {
        GuiDriver.onEdt(() -> {
            d.frame.setSize(SIZE);
            d.app.document().history().markSaved();
            d.app.settings().replace(Settings.defaults());
            d.app.files().openBuiltIn(FIRST_MODEL);
        });
        d.settle();
        return SoakChecks.settledHeap();
    }
}
