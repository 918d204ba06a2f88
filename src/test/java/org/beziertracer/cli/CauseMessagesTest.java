package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Each message names the real cause and the file it concerns, not a symptom further down (issue 36). */
class CauseMessagesTest {

    private static final String ONE_PATCH = "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n";

    @TempDir
    Path dir;

    private static String oneLine(Run r, int code) {
        assertEquals(code, r.code(), r.err());
        return UserMessages.checkOneLineOutput(r.err());
    }

    @Test
    void traceHelpDescribesTheRayFileOptionAsARayFile() {
        Run r = Run.of("trace", "--help");
        assertEquals(0, r.code(), r.err());
        String line = r.out().lines().filter(l -> l.contains("--input")).findFirst().orElseThrow();
        assertTrue(line.contains("ray file") && !line.contains("built-in"), line);
        // the positional parameter's description, wrapped over several lines up to the first option
        String out = r.out();
        int from = out.indexOf("MODEL_OR_SCENE    ");
        String model = out.substring(from, out.indexOf("\n      --", from)).replaceAll("\\s+", " ");
        assertTrue(model.contains("built-in"), model);
    }

    @Test
    void randomRaysAndARayFileTogetherAreRefused() throws Exception {
        Path rays = Files.writeString(dir.resolve("f"), "0 0 10 0 0 -1\n");
        assertEquals("beziertracer trace: --random N and -i RAYS exclude each other: trace N random rays, or the rays"
                + " of the file", oneLine(Run.of("trace", "patch", "--random", "3", "-i", rays.toString()), 1));
    }

    @Test
    void aModelTooWideToFrameIsNamedWithItsBoxNotTheCamera() throws Exception {
        Path wide = Files.writeString(dir.resolve("wide.bpt"), "1\n1 1\n0 0 0\n1e308 0 0\n0 1 0\n1 1 1\n");
        String line = oneLine(Run.of("render", wide.toString(), "--size", "8x8", "-o", dir.resolve("w.png").toString()), 1);
        assertEquals("beziertracer render: " + wide + ": the control points span x[0,1e308] y[0,1] z[0,1], wider than"
                + " 1e300: a camera framing it would stand beyond the largest number", line);
    }

    @Test
    void aFifoIsReadAsItComes() throws Exception {
        Path fifo = dir.resolve("fifo.bpt");
        Process mk = new ProcessBuilder("mkfifo", fifo.toString()).start();
        org.junit.jupiter.api.Assumptions.assumeTrue(mk.waitFor(10, TimeUnit.SECONDS) && mk.exitValue() == 0, "mkfifo");
        Thread writer = new Thread(() -> {
            try {
                Files.writeString(fifo, ONE_PATCH);
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        });
        writer.start();
        Run r = Run.of("info", fifo.toString());
        writer.join(10_000);
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("patches: 1"), r.out());
    }

    @Test
    void aDeviceIsARayFileAndAFolderIsNot() {
        Run r = Run.of("trace", "patch", "-i", "/dev/null");
        assertEquals(0, r.code(), r.err());
        assertEquals(TraceCommand.HEADER, r.out().strip(), "no rays, no hits");
        assertEquals("beziertracer trace: " + dir + ": is a folder, not a ray file",
                oneLine(Run.of("trace", "patch", "-i", dir.toString()), 1));
    }

    @Test
    void anEmptyOutputNameIsSaidToBeEmpty() {
        assertEquals("beziertracer render: -o: the file name is empty; -o needs a .png file name",
                oneLine(Run.of("render", "patch", "-o", ""), 1));
        assertEquals("beziertracer trace: -o: the output file name is empty",
                oneLine(Run.of("trace", "patch", "--random", "1", "-o", ""), 1));
        assertEquals("beziertracer trace: -i: the ray file name is empty", oneLine(Run.of("trace", "patch", "-i", ""), 1));
    }

    @Test
    void aZeroUpVectorIsCalledZero() {
        assertEquals("beziertracer render: camera up must not be the zero vector",
                oneLine(Run.of("render", "patch", "--size", "8x8", "-o", dir.resolve("u.png").toString(),
                        "--up", "0,0,0"), 1));
    }

    @Test
    void anEyeAndTargetTooFarApartSaySo() {
        String line = oneLine(Run.of("render", "patch", "--size", "8x8", "-o", dir.resolve("e.png").toString(),
                "--eye", "-1e308,0,0", "--target", "1e308,0,0"), 1);
        assertEquals("beziertracer render: camera eye and target are too far apart: their distance overflows"
                + " (beyond the largest number, about 1.8e308)", line);
    }
}
