package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * A run that names a command builds a tree of that command alone ({@link BezierTracerCommand#commandLine(String[])}),
 * and says exactly what the whole tree would.
 */
class CommandTreeTest {

    @Test
    void theCommandsAreNamedAsTheirAnnotationsNameThem() {
        for (Map.Entry<String, java.util.function.Supplier<Object>> e : BezierTracerCommand.COMMANDS.entrySet()) {
            Command c = e.getValue().get().getClass().getAnnotation(Command.class);
            assertEquals(e.getKey(), c.name());
        }
        assertEquals(List.of("info", "trace", "render", "analyze", "convert"),
                List.copyOf(BezierTracerCommand.commandLine().getSubcommands().keySet()));
    }

    @Test
    void aRunNamingACommandBuildsThatOneAlone() {
        for (String name : BezierTracerCommand.COMMANDS.keySet()) {
            CommandLine cl = BezierTracerCommand.commandLine(new String[] {name, "--help"});
            assertEquals(List.of(name), List.copyOf(cl.getSubcommands().keySet()));
        }
        for (String[] args : List.of(new String[] {"--help"}, new String[] {"rendr", "x"}, new String[0],
                new String[] {"teapot"}, new String[] {"inf"}, new String[] {"Info"}, new String[] {"-V"})) {
            assertEquals(5, BezierTracerCommand.commandLine(args).getSubcommands().size(), String.join(" ", args));
        }
    }

    @Test
    void theOneCommandTreeSaysWhatTheWholeTreeSays() {
        List<String[]> runs = List.of(new String[] {"render", "--help"}, new String[] {"info", "--help"},
                new String[] {"trace", "--help"}, new String[] {"analyze", "--help"}, new String[] {"convert", "--help"},
                new String[] {"render", "patch", "--size", "0x0"}, new String[] {"info", "no-such-model"},
                new String[] {"trace", "--bogus"}, new String[] {"render"}); // (info prints its build time: not compared)
        for (String[] args : runs) {
            assertEquals(run(BezierTracerCommand.commandLine(), args), run(BezierTracerCommand.commandLine(args), args),
                    String.join(" ", args));
        }
    }

    @Test
    void topLevelHelpStillListsEveryCommand() {
        Run r = Run.of("--help");
        assertEquals(0, r.code(), r.err());
        for (String name : BezierTracerCommand.COMMANDS.keySet()) {
            assertTrue(r.out().matches("(?s).*\\n\\s+" + name + "\\s.*"), name + " missing from\n" + r.out());
        }
    }

    @Test
    void aSubCommandRunAloneKeepsItsQualifiedNameInHelpAndErrors() {
        Run help = Run.of("info", "--help");
        assertEquals(0, help.code(), help.err());
        assertTrue(help.out().contains("Usage: beziertracer info "), help.out());
        Run bad = Run.of("render", "teapot", "--spp", "x");
        assertEquals(2, bad.code(), bad.err());
        assertTrue(bad.err().startsWith("beziertracer render: "), bad.err());
    }

    private static String run(CommandLine cl, String[] args) {
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code = BezierTracerCommand.run(cl, args, new PrintWriter(out), new PrintWriter(err));
        return code + "\n" + out + "\n---\n" + err;
    }
}
