package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.GraphicsEnvironment;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

/** No arguments: the desktop app handed in by {@code Main} opens, or the headless hint. */
class LaunchAppTest {

    @Test
    void noArgumentsLaunchTheDesktopAppOnlyWithADisplay() {
        AtomicInteger launched = new AtomicInteger();
        int code = BezierTracerCommand.run(new String[0], model -> launched.incrementAndGet());
        if (GraphicsEnvironment.isHeadless()) {
            assertEquals(BezierTracerCommand.EXIT_NO_DISPLAY, code);
            assertEquals(0, launched.get());
        } else {
            assertEquals(BezierTracerCommand.APP_RUNNING, code);
            assertEquals(1, launched.get());
        }
    }
}
