package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

class AnalyzeCommandTest {

    @TempDir
    Path dir;

    /** The teapot's body: lower ring 1, 2, 7, 8 and upper ring 3, 4, 9, 10 (1-based). */
    private static final Set<Integer> BODY = Set.of(1, 2, 3, 4, 7, 8, 9, 10);

    private static final Pattern ROW = Pattern.compile(
            "^\\s*(\\d+) (u=[01]|v=[01])\\s+(\\d+) (u=[01]|v=[01])\\s+(yes|no)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(G2|G1|G0|gap)\\b.*$");
    private static final Pattern SUMMARY = Pattern.compile(
            "^summary: (\\d+) borders: (\\d+) G2, (\\d+) G1, (\\d+) G0, (\\d+) open \\(analysed in \\d+ ms\\)$");

    @Test
    void analyzeTeapotPrintsOneRowABorderWithCountsThatMatchAndATangentContinuousBody() {
        Run r = Run.of("analyze", "teapot");
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err());
        String[] lines = r.out().split("\n");
        assertTrue(lines[0].startsWith("model: teapot (32 patches, size "), lines[0]);
        List<Matcher> rows = new ArrayList<>();
        Matcher summary = null;
        int[] counts = new int[4];
        int bodyBorders = 0;
        for (String line : lines) {
            Matcher m = ROW.matcher(line);
            if (m.matches()) {
                rows.add(m);
                counts[List.of("G2", "G1", "G0", "gap").indexOf(m.group(12))]++;
                int a = Integer.parseInt(m.group(1)), b = Integer.parseInt(m.group(3));
                if (BODY.contains(a) && BODY.contains(b)) {
                    bodyBorders++;
                    assertTrue(Double.parseDouble(m.group(8)) <= 0.5, "body border not G1 within 0.5°: " + line);
                    assertTrue(m.group(12).startsWith("G2") || m.group(12).equals("G1"), line);
                }
            }
            Matcher s = SUMMARY.matcher(line);
            if (s.matches()) {
                summary = s;
            }
        }
        assertTrue(summary != null, r.out());
        assertEquals(rows.size(), Integer.parseInt(summary.group(1)), "rows against the summary");
        for (int c = 0; c < 4; c++) {
            assertEquals(counts[c], Integer.parseInt(summary.group(2 + c)), "class " + c + " in " + summary.group());
        }
        assertEquals(12, bodyBorders, r.out());
        // the rim meets the lid's flat ring at a crease (G0) on four borders, and nothing is open
        assertEquals(4, counts[2], r.out());
        assertEquals(0, counts[3], r.out());
        assertTrue(rows.get(0).group(12).equals("G0"), "worst first: " + rows.get(0).group());
        assertTrue(r.out().contains("degenerate normal at t=0"), "the knob's pole: " + r.out());
    }

    @Test
    void analyzeTeapotJsonHasOneObjectABorderWithBoundsInDegreesAndWhereTheyLie() {
        Run table = Run.of("analyze", "teapot");
        Run r = Run.of("analyze", "teapot", "--json");
        assertEquals(0, r.code(), r.err());
        JsonArray rows = JsonParser.parseString(r.out()).getAsJsonArray();
        long tableRows = table.out().lines().filter(l -> ROW.matcher(l).matches()).count();
        assertEquals(tableRows, rows.size());
        int g1 = 0;
        for (JsonElement e : rows) {
            JsonObject o = e.getAsJsonObject();
            int a = o.get("patchA").getAsInt(), b = o.get("patchB").getAsInt();
            assertTrue(a >= 1 && a <= 32 && b >= 1 && b <= 32, o.toString());
            for (String key : new String[] {"g0", "g1", "g2"}) {
                assertTrue(o.get(key).getAsDouble() >= 0, key + " in " + o);
                double t = o.get(key + "At").getAsDouble();
                assertTrue(t >= 0 && t <= 1, key + "At in " + o);
                assertTrue(o.get(key + "Certified").getAsBoolean(), o.toString());
            }
            String c = o.get("class").getAsString();
            if (c.equals("G0")) {
                assertEquals(116.6, o.get("g1").getAsDouble(), 0.1, "the rim-lid crease in degrees: " + o);
            }
            if (BODY.contains(a) && BODY.contains(b)) {
                assertTrue(o.get("g1").getAsDouble() <= 0.5, o.toString());
            }
            g1 += c.equals("G1") || c.equals("G2") ? 1 : 0;
        }
        assertEquals(rows.size() - 4, g1, "all but the four creases are G1 or better");
    }

    @Test
    void aWiderAngleToleranceMakesTheCreasesG1() {
        Run r = Run.of("analyze", "teapot", "--g1", "120");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains(" 0 G0, 0 open"), r.out());
    }

    @Test
    void aMissingOrBrokenFileIsOneLineWithExitCodeOne() throws IOException {
        Run missing = Run.of("analyze", "no-such-model.obj");
        assertEquals(1, missing.code());
        assertEquals("", missing.out());
        assertEquals("beziertracer analyze: no-such-model.obj: no such file", UserMessages.checkOneLineOutput(missing.err()));

        Path file = dir.resolve("broken.bpt");
        Files.writeString(file, "1\n3 3\n0 0 abc\n");
        Run broken = Run.of("analyze", file.toString());
        assertEquals(1, broken.code());
        assertEquals("", broken.out());
        String line = UserMessages.checkOneLineOutput(broken.err());
        assertTrue(line.startsWith("beziertracer analyze: " + file + ":3: expected a number"), line);
    }

    @Test
    void aNegativeToleranceIsRefusedInOneLine() {
        Run r = Run.of("analyze", "teapot", "--g2", "-1");
        assertEquals(1, r.code());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.startsWith("beziertracer analyze: --g2 must be"), line);
    }

    @Test
    void aTerminalShowsTheBordersDoneAndQuietOrAPipeShowsNothing() {
        Run bar = Run.with(cl -> ((AnalyzeCommand) cl.getSubcommands().get("analyze").getCommand()).stderrColumns = () -> 80,
                "analyze", "teapot");
        assertEquals(0, bar.code(), bar.err());
        String[] lines = bar.err().strip().split("\r");
        String last = lines[lines.length - 1].strip();
        assertTrue(last.startsWith("analyze 100%") && last.contains("52/52 borders"), last);
        String first = lines[0].strip();
        assertTrue(first.startsWith("analyze   0%") && first.contains(" 0/52 borders"), "the first frame shows the total: " + first);
        Run quiet = Run.with(cl -> ((AnalyzeCommand) cl.getSubcommands().get("analyze").getCommand()).stderrColumns = () -> 80,
                "analyze", "teapot", "--quiet");
        assertEquals("", quiet.err());
        assertEquals("", Run.of("analyze", "teapot").err(), "standard error is a pipe in tests: no bar");
    }
}
