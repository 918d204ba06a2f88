package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * OBJ {@code call FILE.obj}: the named file, relative to the calling one, read in place with the
 * vertex numbering running on; cycles, nesting deeper than 8, arguments and other files refused
 * with one line naming the files.
 */
class ObjCallTest {

    private static final String SURF = "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n";

    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
        return p;
    }

    private String fails(Path file) {
        return UserMessages.of(ModelFormatException.class, () -> FileFormats.OBJ.read(file));
    }

    @Test
    void aCalledFilesStatementsAreReadInPlaceAndItsVerticesNumberedOn() throws IOException {
        write("corners.obj", "v 1 0 0\nv 0 1 0\n");
        Path main = write("main.obj", "v 0 0 0\ncall corners.obj\nv 1 1 2\n" + SURF + "surf 0 1 0 1 -4 -3 -2 -1\nend\n");
        List<BezierPatch> patches = FileFormats.OBJ.read(main).scene().patches();
        assertEquals(2, patches.size());
        double[] net = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 2};
        assertArrayEquals(net, patches.get(0).copyNet(), "absolute indices run across the files");
        assertArrayEquals(net, patches.get(1).copyNet(), "negative indices count back across the files");
    }

    @Test
    void aCallNamesItsFileRelativeToTheCallingFileAndNestedCallsWork() throws IOException {
        write("parts/surface.obj", "call more/corners.obj\n" + SURF);
        write("parts/more/corners.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n");
        write("more/corners.obj", "v 9 9 9\n"); // beside main: not the one meant
        Path main = write("main.obj", "call parts/surface.obj\n");
        BezierPatch p = FileFormats.OBJ.read(main).scene().patches().get(0);
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, p.copyNet());
    }

    @Test
    void callsNestedEightDeepAreReadAndNineAreRefusedNamingTheChain() throws IOException {
        for (int k = 1; k <= 9; k++) {
            write("f" + k + ".obj", k < 9 ? "call f" + (k + 1) + ".obj\n" : "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n");
        }
        Path eight = write("f0.obj", "call f2.obj\n" + SURF); // f0 → f2 → … → f9: 8 calls deep
        assertEquals(1, FileFormats.OBJ.read(eight).scene().patchCount());
        Path nine = write("g0.obj", "call f1.obj\n" + SURF); // g0 → f1 → … → f9: 9 deep
        String message = fails(nine);
        assertTrue(message.startsWith(dir.resolve("f8.obj") + ":1: refused: calls nested more than 8 deep, " + nine
                + " calls " + dir.resolve("f1.obj") + ", which calls "), message);
        assertTrue(message.endsWith(", which calls " + dir.resolve("f9.obj")), message);
    }

    @Test
    void aCallCycleIsRefusedNamingTheFiles() throws IOException {
        Path a = write("a.obj", "v 0 0 0\ncall b.obj\n");
        write("b.obj", "call a.obj\n");
        assertEquals(dir.resolve("b.obj") + ":1: refused: a call cycle, " + a + " calls " + dir.resolve("b.obj")
                + ", which calls " + a + " (a file may not call itself, directly or through other files)", fails(a));
        Path self = write("self.obj", "call ./self.obj\n");
        assertEquals(self + ":1: refused: a call cycle, " + self + " calls " + dir.resolve("./self.obj")
                + " (a file may not call itself, directly or through other files)", fails(self));
    }

    @Test
    void argumentsMissingFilesAndOtherFormatsAreRefusedInOneLine() throws IOException {
        write("part.obj", "v 0 0 0\n");
        Path args = write("args.obj", "call part.obj 1 2\n");
        assertEquals(args + ":1: unsupported: call with arguments ($1 substitution); call FILE.obj without arguments is read",
                fails(args));
        Path missing = write("missing.obj", "\ncall nowhere.obj\n");
        assertEquals(missing + ":2: no such file \"nowhere.obj\" to call in " + dir, fails(missing));
        Path mod = write("mod.obj", "call part.mod\n");
        assertEquals(mod + ":1: expected an .obj file after call, found \"part.mod\" (only OBJ text files can be called)",
                fails(mod));
        Path bare = write("bare.obj", "call\n");
        assertEquals(bare + ":1: expected a file name after call, found none", fails(bare));
    }

    @Test
    void anErrorInACalledFileNamesThatFileAndLineAndTheCallerReadsOnAfterIt() throws IOException {
        write("bad.obj", "v 0 0 0\nv 1 0 zero\n");
        Path main = write("main.obj", "call bad.obj\n");
        assertTrue(fails(main).startsWith(dir.resolve("bad.obj") + ":2: "), fails(main));
        // after a call, errors name the caller again
        write("good.obj", "v 0 0 0\n");
        Path after = write("after.obj", "call good.obj\n\nv 1 0 zero\n");
        assertTrue(fails(after).startsWith(after + ":3: "), fails(after));
    }

    @Test
    void whatACalledFileSkipsIsInTheNoteOfTheFileOpened() throws IOException {
        write("curves.obj", "v 0 0 0\nv 1 0 0\ncurv 0 1 1 2\nparm u 0 1\nend\ncon 1 0 1 1 1 0 1 1\n");
        Path main = write("main.obj", "call curves.obj\nv 0 1 0\nv 1 1 0\n" + SURF);
        assertEquals(List.of(main + ": skipped 1 curv, 1 con (3-D curves and connectivity hints are not drawn)"),
                FileFormats.OBJ.read(main).notes());
    }
}
