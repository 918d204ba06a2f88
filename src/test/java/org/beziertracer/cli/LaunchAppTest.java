package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.awt.GraphicsEnvironment;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

/** No arguments: the desktop app handed in by {@code Main} opens, or the headless hint. */
class LaunchAppTest {

    @Test
    void noArgumentsLaunchTheDesktopAppOnlyWithADisplay() {
        AtomicInteger launched = new AtomicInteger();
        int code = BezierTracerCommand.run(new String[0], launched::incrementAndGet);
        if (GraphicsEnvironment.isHeadless()) {
            assertEquals(BezierTracerCommand.EXIT_NO_DISPLAY, code);
            assertEquals(0, launched.get());
        } else {
            assertEquals(BezierTracerCommand.APP_RUNNING, code);
            assertEquals(1, launched.get());
        }
    }

    @Test
    void theHintNamesTheLauncherOfTheDesktopPackageWhenStartedByIt() {
        assertNull(System.getProperty("jpackage.app-path"), "not set by the test JVM");
        assertEquals("java -jar target/beziertracer.jar", BezierTracerCommand.howToRun());
        System.setProperty("jpackage.app-path", "/opt/BezierTracer/bin/BezierTracer");
        try {
            assertEquals("/opt/BezierTracer/bin/BezierTracer", BezierTracerCommand.howToRun());
        } finally {
            System.clearProperty("jpackage.app-path");
        }
    }
}
