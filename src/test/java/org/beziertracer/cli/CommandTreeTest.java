package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

/** The command tree holds only the sub-command a command line names, and every one otherwise. */
class CommandTreeTest {

    private static final List<String> ALL = List.of("info", "trace", "render", "analyze", "convert");

    @Test
    void aNamedSubCommandGetsATreeOfItselfOnly() {
        for (String name : ALL) {
            assertEquals(List.of(name), List.copyOf(BezierTracerCommand.commandLine(name).getSubcommands().keySet()), name);
        }
    }

    @Test
    void anythingElseGetsEverySubCommandInHelpOrder() {
        for (String first : new String[] {null, "--help", "teapot", "inf", "Info", "-V"}) {
            assertEquals(ALL, List.copyOf(BezierTracerCommand.commandLine(first).getSubcommands().keySet()), first);
        }
    }

    @Test
    void topLevelHelpStillListsEveryCommand() {
        Run r = Run.of("--help");
        assertEquals(0, r.code(), r.err());
        for (String name : ALL) {
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
}
