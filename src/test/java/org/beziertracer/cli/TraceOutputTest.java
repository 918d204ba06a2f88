package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.beziertracer.Main;
import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code trace -o} saves like the PNGs: atomically, and never over its own input (issue 36). */
class TraceOutputTest {

    private static final String OLD = "index,hit\nthe old hits\n";

    @TempDir
    Path dir;

    private Path oldHits() throws IOException {
        return Files.writeString(dir.resolve("hits.csv"), OLD);
    }

    private List<String> leftovers() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".tmp")).toList();
        }
    }

    @Test
    void aTraceThatFailsHalfWayLeavesTheOldCsvUntouched() throws IOException {
        Path hits = oldHits();
        Path rays = Files.writeString(dir.resolve("rays.txt"), "0 0 10 0 0 -1\n".repeat(5000) + "0 0 oops 0 0 -1\n");
        Run r = Run.of("trace", "patch", "-i", rays.toString(), "-o", hits.toString());
        assertEquals(1, r.code(), r.err());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).contains("rays.txt:5001:"), r.err());
        assertEquals(OLD, Files.readString(hits), "the old file is kept");
        assertEquals(List.of(), leftovers(), "no temporary file is left");
    }

    @Test
    void aSuccessfulTraceReplacesTheOldCsv() throws IOException {
        Path hits = oldHits();
        Run r = Run.of("trace", "patch", "--random", "10", "-o", hits.toString());
        assertEquals(0, r.code(), r.err());
        assertEquals(11, Files.readAllLines(hits).size());
        assertEquals(List.of(), leftovers());
    }

    @Test
    void anOutputThatIsTheRayFileIsRefusedAndTheRaysAreKept() throws IOException {
        String text = "0 0 10 0 0 -1\n";
        Path rays = Files.writeString(dir.resolve("rays.txt"), text);
        Run r = Run.of("trace", "patch", "-i", rays.toString(), "-o", rays.toString());
        assertEquals(1, r.code(), r.err());
        assertEquals("beziertracer trace: -o " + rays + " is the ray file -i " + rays
                + ": the hits would replace the rays; choose another output file", UserMessages.checkOneLineOutput(r.err()));
        assertEquals(text, Files.readString(rays));

        // The same file under another name is the same file
        Path link = Files.createSymbolicLink(dir.resolve("link.txt"), rays);
        r = Run.of("trace", "patch", "-i", rays.toString(), "-o", link.toString());
        assertEquals(1, r.code(), r.err());
        assertTrue(UserMessages.checkOneLineOutput(r.err()).contains(" is the ray file -i "), r.err());
        assertEquals(text, Files.readString(rays));
    }

    @Test
    void anOutputThatIsTheModelIsRefused() throws IOException {
        Path model = LimitsFixtures.wavyModel(dir.resolve("m.bpt"), 1);
        String before = Files.readString(model);
        Run r = Run.of("trace", model.toString(), "--random", "3", "-o", model.toString());
        assertEquals(1, r.code(), r.err());
        assertEquals("beziertracer trace: -o " + model + " is the model " + model
                + ": the hits would replace it; choose another output file", UserMessages.checkOneLineOutput(r.err()));
        assertEquals(before, Files.readString(model));
    }

    @Test
    void aKilledTraceLeavesTheOldCsvWholeAndTheNextTraceClearsItsTemporaryFile() throws Exception {
        Path hits = oldHits();
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "trace", "patch", "--random", "100000000", "-o", hits.toString()));
        Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("child.log").toFile()).start();
        try {
            // Wait until the trace is writing: a temporary file, or (before the fix) the target changing
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
            while (leftovers().isEmpty() && Files.readString(hits).equals(OLD) && p.isAlive()
                    && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            Thread.sleep(200); // well into writing
            assertTrue(p.isAlive(), "the trace should still run: " + Files.readString(dir.resolve("child.log")));
        } finally {
            p.destroyForcibly().waitFor(30, TimeUnit.SECONDS);
        }
        assertEquals(OLD, Files.readString(hits), "a killed trace must not cut the old CSV");
        assertEquals(1, leftovers().size(), "the killed trace's temporary file: " + leftovers());

        Run r = Run.of("trace", "patch", "--random", "2", "-o", hits.toString());
        assertEquals(0, r.code(), r.err());
        assertEquals(3, Files.readAllLines(hits).size());
        assertEquals(List.of(), leftovers(), "the next save of the same file removes what the killed one left");
    }
}
