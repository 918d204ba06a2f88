package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TraceCommandTest {

    @TempDir
    Path dir;

    private static Run run(String... args) {
        return Run.of(args);
    }

    private Path rays(String text) throws IOException {
        Path p = dir.resolve("rays.txt");
        Files.writeString(p, text);
        return p;
    }

    @Test
    void traceWritesOneCsvLinePerRayWithTheHeader() throws IOException {
        // straight down onto the lid top (0,0,120), then a miss, with a comment and a blank line
        Path in = rays("# lid top\n0 0 220 0 0 -2\n\n1000 1000 1000 1 0 0\n");
        // Newton has no convergence at the collapsed lid top (singular Jacobian): see NewtonSolver
        for (String method : List.of("clipping", "subdivision")) {
            Run r = run("trace", "teapot", "-i", in.toString(), "--method", method);
            assertEquals(0, r.code(), r.err());
            String[] lines = r.out().split("\n");
            assertEquals(TraceCommand.HEADER, lines[0]);
            assertEquals(3, lines.length, r.out());
            String[] hit = lines[1].split(",", -1);
            assertEquals(12, hit.length);
            assertEquals("0", hit[0]);
            assertEquals("1", hit[1], method + " hits the lid top: " + lines[1]);
            assertEquals(50, Double.parseDouble(hit[2]), method.equals("subdivision") ? 1e-3 : 1e-9, "t along the given direction");
            assertEquals(120, Double.parseDouble(hit[8]), method.equals("subdivision") ? 1e-3 : 1e-9, "z of the hit");
            assertEquals(1, Math.abs(Double.parseDouble(hit[11])), 1e-6, "vertical normal");
            assertEquals("1,0,,,,,,,,,,", lines[2]);
        }
    }

    @Test
    void curvatureAddsGaussianMeanPrincipalCurvaturesAndDirectionsToEachHit() {
        Run r = run("trace", "sphere", "--random", "300", "--curvature");
        assertEquals(0, r.code(), r.err());
        String[] lines = r.out().split("\n");
        assertEquals(TraceCommand.HEADER + "," + TraceCommand.CURVATURE_HEADER, lines[0]);
        int hits = 0;
        for (int k = 1; k < lines.length; k++) {
            String[] f = lines[k].split(",", -1);
            assertEquals(22, f.length, lines[k]);
            if (f[1].equals("0")) {
                assertEquals("", f[12] + f[21], "a miss has empty curvature columns: " + lines[k]);
                continue;
            }
            hits++;
            double gaussian = Double.parseDouble(f[12]), mean = Double.parseDouble(f[13]);
            double k1 = Double.parseDouble(f[14]), k2 = Double.parseDouble(f[15]);
            assertEquals(1, gaussian, 1e-9, "the unit sphere: " + lines[k]);
            assertEquals(1, Math.abs(mean), 1e-9, lines[k]);
            assertTrue(k1 >= k2, "k1 ≥ k2: " + lines[k]);
            double d1n = 0, d1d2 = 0;
            for (int c = 0; c < 3; c++) {
                d1n += Double.parseDouble(f[16 + c]) * Double.parseDouble(f[9 + c]);
                d1d2 += Double.parseDouble(f[16 + c]) * Double.parseDouble(f[19 + c]);
            }
            assertEquals(0, d1n, 1e-9, "d1 is tangent: " + lines[k]);
            assertEquals(0, d1d2, 1e-9, "d1 ⊥ d2: " + lines[k]);
        }
        assertTrue(hits > 50, "hits: " + hits);
    }

    @Test
    void newtonFindsTheSameRegularHitAsClipping() throws IOException {
        Path in = rays("20 10 300 0 0 -1\n-50 -20 300 0.1 0 -1\n");
        Run a = run("trace", "teapot", "-i", in.toString());
        Run b = run("trace", "teapot", "-i", in.toString(), "--method", "newton");
        String[] la = a.out().split("\n"), lb = b.out().split("\n");
        for (int k = 1; k <= 2; k++) {
            String[] x = la[k].split(","), y = lb[k].split(",");
            assertEquals("1", x[1], la[k]);
            assertEquals("1", y[1], lb[k]);
            assertEquals(Double.parseDouble(x[2]), Double.parseDouble(y[2]), 1e-9, "t of ray " + k);
        }
    }

    @Test
    void traceWithoutTheBvhGivesTheSameHits() throws IOException {
        Path in = dir.resolve("in.txt");
        StringBuilder sb = new StringBuilder();
        java.util.Random rnd = new java.util.Random(3);
        for (int k = 0; k < 200; k++) {
            sb.append(-120 + 260 * rnd.nextDouble()).append(' ').append(-80 + 160 * rnd.nextDouble()).append(' ').append(300)
                    .append(' ').append(rnd.nextGaussian() * 0.05).append(' ').append(rnd.nextGaussian() * 0.05).append(" -1\n");
        }
        Files.writeString(in, sb);
        Path a = dir.resolve("a.csv"), b = dir.resolve("b.csv");
        assertEquals(0, run("trace", "teapot", "-i", in.toString(), "-o", a.toString()).code());
        assertEquals(0, run("trace", "teapot", "-i", in.toString(), "-o", b.toString(), "--no-bvh").code());
        List<String> la = Files.readAllLines(a), lb = Files.readAllLines(b);
        assertEquals(201, la.size());
        int hits = 0;
        for (int k = 1; k < la.size(); k++) {
            String[] x = la.get(k).split(",", -1), y = lb.get(k).split(",", -1);
            assertEquals(x[1], y[1], "hit flag of ray " + k);
            if (x[1].equals("1")) {
                hits++;
                assertEquals(Double.parseDouble(x[2]), Double.parseDouble(y[2]), 1e-9, "t of ray " + k);
            }
        }
        assertTrue(hits > 60, "hits " + hits);
    }

    @Test
    void aMalformedRayLineIsOneErrorLineWithItsNumber() throws IOException {
        Path in = rays("0 0 10 0 0 -1\n0 0 abc 0 0 -1\n");
        Run r = run("trace", "teapot", "-i", in.toString());
        assertEquals(1, r.code());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.contains("rays.txt:2:") && line.contains("\"abc\""), line);

        r = run("trace", "teapot", "-i", rays("1 2 3 4 5\n").toString());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).endsWith("rays.txt:1: expected 6 numbers \"ox oy oz dx dy dz\", found 5 fields"), r.err());
        r = run("trace", "teapot", "-i", rays("bad\n").toString());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).endsWith("rays.txt:1: expected 6 numbers \"ox oy oz dx dy dz\", found 1 field"), r.err());
        r = run("trace", "teapot", "-i", rays("1 2 3 0 0 0\n").toString());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).contains("direction is zero"), r.err());
        r = run("trace", "teapot", "-i", rays("1 2 3 0 1e-320 0\n").toString());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).contains("rays.txt:1: the ray direction's length"), r.err());
        r = run("trace", "teapot", "-i", rays("1 2 NaN 0 0 1\n").toString());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).contains("must be finite"), r.err());
        r = run("trace", "teapot", "--method", "magic", "-i", in.toString());
        assertEquals(1, r.code());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).contains("unknown method 'magic'"), r.err());
        r = run("trace", "teapot", "-i", dir.resolve("missing.txt").toString());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).contains("missing.txt: no such ray file"), r.err());
        r = run("trace", "teapot", "-i", Files.write(dir.resolve("bin.txt"), new byte[] {'0', ' ', (byte) 0xFF}).toString());
        assertEquals("beziertracer trace: " + dir.resolve("bin.txt") + ": not a text file (invalid UTF-8 at byte 2)",
                UserMessages.checkOneLineOutput(r.err()));
    }

    @Test
    void randomRaysAndStatsReportThroughput() {
        Run r = run("trace", "teapot", "--random", "2000", "--stats", "-o", dir.resolve("r.csv").toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().matches("(?s)trace: 2000 rays, \\d+ hits, method clipping, bvh true, \\d+ sub-patches.*rays/s, [0-9.]+ leaf tests and [0-9.]+ clip steps per ray\\s*"), r.err());
    }

    @Test
    void infoAccelReportsSubPatchesAndTheBvh() {
        Run r = run("info", "--accel", "teapot");
        assertTrue(r.out().matches("(?s).*sub-patches: \\d+\n.*bvh: \\d+ nodes, depth \\d+\n.*build: .* ms.*"), r.out());
    }
}
