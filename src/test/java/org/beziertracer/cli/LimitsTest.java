package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.ChildJvm;
import org.beziertracer.Main;
import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Work that would not fit, and files that cannot be written, end in one line that says so. */
class LimitsTest {

    @TempDir
    Path dir;

    private ChildJvm.Result beziertracer(String heap, String... args) throws Exception {
        return ChildJvm.run(dir, List.of("-Xmx" + heap), Main.class.getName(), args);
    }

    @Test
    void aTessellationThatWouldNotFitIsRefusedInOneLineBeforeAllocating() throws Exception {
        Files.writeString(dir.resolve("rays.txt"), "0 0 300 0 0 -1\n");
        ChildJvm.Result r = beziertracer("64m", "trace", "teapot", "-i", "rays.txt", "--tessellate", "400");
        assertEquals(1, r.code(), r.err());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.startsWith("beziertracer trace: teapot: 32 patches tessellated 400x400 (10240000 triangles)"
                + " need about "), line);
        assertTrue(line.matches(".* need about \\d+(\\.\\d)? [MG]B of heap; this JVM allows \\d+ MB"
                + "(, \\d+ MB of it in use)? \\(run java -Xmx\\d+[mg] …\\)"), line);
    }

    @Test
    void aModelWhoseSubPatchesWouldNotFitIsRefusedInOneLine() throws Exception {
        Path big = LimitsFixtures.wavyModel(dir.resolve("big.bpt"), 80);
        ChildJvm.Result r = beziertracer("32m", "info", "--accel", big.getFileName().toString());
        assertEquals(1, r.code(), r.err());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.startsWith("beziertracer info: big.bpt: 80 patches need about "), line);
        assertTrue(line.contains(" of heap; this JVM allows "), line);
    }

    @Test
    void runningOutOfMemoryAnywhereIsOneLineWithoutATrace() throws Exception {
        // 12 M characters of text read into a 16 MB heap: out of memory while reading
        Files.writeString(dir.resolve("huge.json"), "{\"version\": 1, \"description\": \"" + "x".repeat(12 << 20) + "\"}");
        ChildJvm.Result r = beziertracer("16m", "info", "huge.json");
        assertEquals(1, r.code(), r.err());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.startsWith("beziertracer info: huge.json: out of memory: this JVM allows "), line);
        assertTrue(line.contains("-Xmx"), line);
    }

    @Test
    void aMillionPatchFileIsRefusedFromItsHeaderNamingTheFileAndAHeapThatWouldDo() throws Exception {
        // The header announces a million degree-15 patches; the body stops after the first
        StringBuilder body = new StringBuilder("1000000\n15 15\n");
        for (int k = 0; k < 256; k++) {
            body.append(k).append(" 0 0\n");
        }
        Files.writeString(dir.resolve("big.bpt"), body);
        ChildJvm.Result r = beziertracer("64m", "info", "big.bpt");
        assertEquals(1, r.code(), r.err());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.matches("beziertracer info: big\\.bpt:2: 1000000 patches of degree 15x15 need about 6\\.\\d GB "
                + "of heap; this JVM allows \\d+ MB(, \\d+ MB of it in use)? \\(run java -Xmx(8|16)g …\\)"), line);
    }

    @Test
    void renderingToTheRootFolderIsAClearError() {
        Run r = Run.of("render", "teapot", "-o", "/");
        assertEquals(1, r.code());
        assertEquals("beziertracer render: /: is a folder; -o needs a .png file name",
                UserMessages.checkOneLineOutput(r.err()));
    }

    @Test
    void aFailedImageWriteNamesTheTargetAndTheReason() throws IOException {
        Path folder = Files.createDirectory(dir.resolve("picture.png"));
        Files.writeString(folder.resolve("keep.txt"), "x");
        Run r = Run.of("render", "patch", "--size", "8x8", "-o", folder.toString());
        assertEquals(1, r.code());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertEquals("beziertracer render: " + folder + ": is a folder; -o needs a .png file name", line);
    }

    @Test
    void optionValuesEchoedInAMessageAreCutToSixtyCharacters() {
        String eye = "1,".repeat(500) + "2";
        Run r = Run.of("render", "patch", "--size", "8x8", "-o", "x.png", "--eye", eye);
        String line = UserMessages.checkOneLineOutput(r.err());
        assertEquals("beziertracer render: --eye must be x,y,z, got '" + eye.substring(0, 59) + "…'", line);
    }

    @Test
    void aCsvThatCannotBeWrittenNamesTheTargetAndTheReason() {
        Run r = Run.of("trace", "teapot", "--random", "1", "-o", dir.toString());
        assertEquals("beziertracer trace: " + dir + ": cannot write: is a folder", UserMessages.checkOneLineOutput(r.err()));
        Path missing = dir.resolve("gone").resolve("hits.csv");
        r = Run.of("trace", "teapot", "--random", "1", "-o", missing.toString());
        assertEquals("beziertracer trace: " + missing + ": cannot write: the folder " + missing.getParent()
                + " does not exist", UserMessages.checkOneLineOutput(r.err()));
    }
}
