package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.GraphicsEnvironment;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

/** No arguments, or a model: the desktop app handed in by {@code Main} opens (on the model), or the headless hint. */
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

    @Test
    void aModelFileOrBuiltInNameOpensTheDesktopAppOnIt(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        java.nio.file.Path bpt = java.nio.file.Files.writeString(dir.resolve("x.bpt"), "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n");
        for (String arg : new String[] {"teapot", bpt.toString()}) {
            java.util.List<String> launched = new java.util.ArrayList<>();
            int code = BezierTracerCommand.run(new String[] {arg}, launched::add);
            if (GraphicsEnvironment.isHeadless()) {
                assertEquals(BezierTracerCommand.EXIT_NO_DISPLAY, code);
            } else {
                assertEquals(BezierTracerCommand.APP_RUNNING, code);
                assertEquals(java.util.List.of(arg), launched, "the app opens on " + arg);
            }
        }
    }

    @Test
    void anArgumentThatIsNoCommandFileOrBuiltInIsOneLineNamingTheChoices() {
        java.util.List<String> launched = new java.util.ArrayList<>();
        java.io.PrintStream err = System.err;
        java.io.ByteArrayOutputStream captured = new java.io.ByteArrayOutputStream();
        int code;
        try {
            System.setErr(new java.io.PrintStream(captured, true, java.nio.charset.StandardCharsets.UTF_8));
            code = BezierTracerCommand.run(new String[] {"rendr"}, launched::add);
        } finally {
            System.setErr(err);
        }
        assertEquals(BezierTracerCommand.EXIT_USAGE, code);
        assertEquals(java.util.List.of(), launched);
        String line = captured.toString(java.nio.charset.StandardCharsets.UTF_8).strip();
        org.beziertracer.UserMessages.check(line);
        org.junit.jupiter.api.Assertions.assertTrue(line.startsWith("beziertracer: \"rendr\" is not a command, a file or a "
                + "built-in model (commands: info, trace, render, analyze, convert; built-ins: patch, teapot"), line);
        org.junit.jupiter.api.Assertions.assertFalse(line.contains("\n"));
        String commands = line.substring(line.indexOf("(commands: ") + 11, line.indexOf(';'));
        assertEquals(String.join(", ", BezierTracerCommand.commandLine().getSubcommands().keySet()), commands,
                "the sentence names every command the tree has");
    }
}
