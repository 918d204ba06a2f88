package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.Set;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

import picocli.CommandLine;

class RenderProgressBarTest {
    private static final Pattern ELAPSED_AND_ETA = Pattern.compile("\\(\\d+:\\d\\d:\\d\\d / \\d+:\\d\\d:\\d\\d\\)");

    @TempDir
    Path dir;

    /** Runs {@code render} as if standard error were a terminal {@code columns} wide. */
    private static Run onTerminal(int columns, String... args) {
        return Run.with(cl -> render(cl).stderrColumns = () -> columns, args);
    }

    private static RenderCommand render(CommandLine cl) {
        return (RenderCommand) cl.getSubcommands().get("render").getCommand();
    }

    private String[] args(String... extra) {
        String[] base = {"render", "teapot", "-o", dir.resolve("t.png").toString(), "--size", "64x48", "--threads", "2"};
        String[] all = new String[base.length + extra.length];
        System.arraycopy(base, 0, all, 0, base.length);
        System.arraycopy(extra, 0, all, base.length, extra.length);
        return all;
    }

    @Test
    void standardErrorThatIsNoTerminalGetsNothing() {
        assertEquals(0, StandardError.terminalColumns(), "the test JVM's standard error is a pipe");
        Run r = Run.of(args());
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err());
    }

    @Test
    void aTerminalShowsPercentElapsedAndEtaEndingAt100Percent() {
        Run r = onTerminal(72, args("--repeat", "2"));
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().startsWith("\r") && r.err().endsWith(System.lineSeparator()), r.err());
        String[] lines = r.err().strip().split("\r");
        String last = lines[lines.length - 1].strip();
        assertTrue(last.startsWith("render 100% ["), last);
        assertTrue(ELAPSED_AND_ETA.matcher(last).find(), last);
        assertTrue(last.contains("6/6 k samples"), "2 frames of 64x48 = 6144 samples: " + last);
        for (String line : lines) {
            assertTrue(line.strip().length() <= 71, "fits the terminal: " + line);
        }
    }

    @Test
    void quietSilencesTheBarEvenOnATerminal() {
        Run r = onTerminal(72, args("--quiet"));
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err());
        assertEquals("", onTerminal(72, args("-q")).err());
    }

    @Test
    void statsAreTheSameLineWithOrWithoutTheBar() {
        Run shown = onTerminal(72, args("--stats"));
        Run quiet = onTerminal(72, args("--stats", "--quiet"));
        assertTrue(shown.err().contains("100%"), shown.err());
        assertEquals(1, shown.out().strip().split("\n").length, shown.out());
        assertTrue(!shown.out().contains("\r") && !shown.out().contains("%"), "nothing of the bar on stdout: " + shown.out());
        JsonObject a = JsonParser.parseString(shown.out()).getAsJsonObject();
        JsonObject b = JsonParser.parseString(quiet.out()).getAsJsonObject();
        assertEquals(b.keySet(), a.keySet());
        Set<String> timings = Set.of("buildMillis", "frameMillis", "renderMillis", "mraysPerSecond");
        for (String key : a.keySet()) {
            if (!timings.contains(key)) {
                assertEquals(b.get(key), a.get(key), key);
            }
        }
    }

    @Test
    void theFirstDrawingBeforeAnySampleShowsTheRealTotal() throws InterruptedException {
        StringWriter err = new StringWriter();
        try (ProgressBarDisplay bar = new ProgressBarDisplay(new PrintWriter(err), 72, 2, 64 * 48)) {
            Thread.sleep(3 * ProgressBarDisplay.REFRESH_MILLIS);
        }
        String first = err.toString().strip().split("\r")[0].strip();
        assertTrue(first.startsWith("render   0% ["), first);
        assertTrue(first.contains("0/6 k samples"), "2 frames of 64x48: " + first);
        assertTrue(!first.contains("? %") && !first.contains("0/0"), first);
    }

    @Test
    void theDisplayAddsFramesUpAndRedrawsInPlace() {
        StringWriter err = new StringWriter();
        try (ProgressBarDisplay bar = new ProgressBarDisplay(new PrintWriter(err), 60, 2, 1000)) {
            bar.progress(7, 500, 1000);
            bar.progress(7, 1000, 1000);
            bar.progress(8, 250, 1000);
        }
        String out = err.toString();
        String last = out.strip().substring(out.strip().lastIndexOf('\r') + 1);
        assertTrue(last.startsWith("render  62% ["), "1250 of 2000 samples: " + last);
        assertTrue(last.contains("1/2 k samples"), last);
    }
}
