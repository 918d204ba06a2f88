package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * OBJ as CAD tools write it: 3-D curves, special curves and points, connectivity, points and
 * lines beside the surfaces are skipped and counted in one note, never a failure of the file; the
 * note reaches the document {@link FileFormats} returns, also through a scene file.
 */
class ObjSkippedTest {

    /** The note {@code cad-export.obj} gets. */
    static final String CAD_NOTE = "cad-export.obj: skipped 2 curv, 1 scrv, 1 sp, 1 con (3-D curves, special curves, "
            + "special points and connectivity hints are not drawn)";

    @TempDir
    Path dir;

    /** The text of the fixture {@code cad-export.obj}: two boundary-trimmed faces with curv, scrv, sp and con. */
    static String cadExport() {
        try (InputStream in = ObjSkippedTest.class.getResourceAsStream("cad-export.obj")) {
            assertNotNull(in, "cad-export.obj on the test class path");
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void aCadExportWithCurvesAndConnectivityReadsItsSurfacesAndNotesTheRest() {
        ObjReader.Model m = ObjReader.readModel(cadExport(), "cad-export.obj");
        assertEquals(2, m.patches().size());
        for (BezierPatch p : m.patches()) {
            assertNotNull(p.domain().trim(), "each face keeps its trim loop");
        }
        assertEquals(List.of(CAD_NOTE), m.notes());
    }

    @Test
    void pointsAndLinesAreCountedTooAndAFileWithNothingSkippedHasNoNote() {
        String surface = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n";
        assertEquals(List.of(), ObjReader.readModel(surface, "plain.obj").notes());
        assertEquals(List.of("lines.obj: skipped 1 p, 2 l (points and lines are not drawn)"),
                ObjReader.readModel(surface + "p 1\nl 1 2\nl 2 3 4\n", "lines.obj").notes());
        assertEquals(List.of("one.obj: skipped 1 con (connectivity hints are not drawn)"),
                ObjReader.readModel(surface + "con 1 0 1 1 1 0 1 1\n", "one.obj").notes());
    }

    @Test
    void aCurvBlockIsReadPastWithItsParmAndEndAndStillNeedsItsEnd() {
        String surface = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n";
        // a curv needs no cstype or deg of its own and its parm is not checked
        ObjReader.Model m = ObjReader.readModel("v 0 0 0\nv 1 0 0\ncurv 0 1 1 2\nparm u 1 0 x\nend\n" + surface, "c.obj");
        assertEquals(1, m.patches().size());
        assertEquals(List.of("c.obj: skipped 1 curv (3-D curves are not drawn)"), m.notes());
        assertEquals("c.obj:10: expected end for the curv at line 3, found surf",
                UserMessages.of(ModelFormatException.class, () -> ObjReader.readModel("v 0 0 0\nv 1 0 0\ncurv 0 1 1 2\n" + surface, "c.obj")));
    }

    @Test
    void theNoteReachesTheDocumentOfTheFileAndOfASceneThatNamesIt() throws IOException {
        Path obj = dir.resolve("cad-export.obj");
        Files.writeString(obj, cadExport());
        SceneDocument doc = FileFormats.OBJ.read(obj);
        assertEquals(2, doc.scene().patchCount());
        assertEquals(List.of(CAD_NOTE.replace("cad-export.obj", obj.toString())), doc.notes());
        Path scene = dir.resolve("scene.json");
        Files.writeString(scene, "{\"version\": 1, \"models\": [{\"file\": \"cad-export.obj\"}, {\"file\": \"cad-export.obj\"}]}");
        SceneDocument sceneDoc = SceneFiles.load(scene.toString());
        assertEquals(List.of(CAD_NOTE.replace("cad-export.obj", obj.toString())), sceneDoc.notes(),
                "a model file named twice is read, and noted, once");
        assertEquals(List.of(), FileFormats.BPT.read(writeBpt()).notes());
    }

    private Path writeBpt() throws IOException {
        Path bpt = dir.resolve("plain.bpt");
        Files.writeString(bpt, "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n");
        return bpt;
    }
}
