package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

import org.beziertracer.UserMessages;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.FileFormat.Holds;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The format and built-in registries: each entry declared once, found by what users type. */
class FileFormatsTest {

    @TempDir
    Path dir;

    @Test
    void everyFormatIsDeclaredOnceWithItsExtensionsAndWhatItHolds() {
        assertEquals(List.of("BPT", "OBJ", "IGES", "STEP", "scene"), FileFormats.ALL.stream().map(FileFormat::name).toList());
        assertEquals(List.of("bpt", "obj", "igs", "iges", "stp", "step", "json"), FileFormats.extensions(FileFormats.ALL));
        assertEquals(List.of(FileFormats.BPT, FileFormats.OBJ, FileFormats.IGES, FileFormats.STEP), FileFormats.holding(Holds.MODEL));
        assertEquals(List.of(FileFormats.SCENE), FileFormats.holding(Holds.SCENE));
        assertEquals(".bpt, .obj, .igs, .iges, .stp, .step or .json", FileFormats.extensionList(FileFormats.ALL));
        assertEquals("*.bpt, *.obj, *.igs, *.iges, *.stp, *.step", FileFormats.patterns(FileFormats.holding(Holds.MODEL)));
        assertEquals("Bézier patch text (*.bpt)", FileFormats.BPT.filterLabel());
    }

    @Test
    void formatsAreFoundByExtensionInAnyCase() {
        assertEquals(Optional.of(FileFormats.OBJ), FileFormats.find("models/Teapot.OBJ"));
        assertEquals(Optional.of(FileFormats.SCENE), FileFormats.find("room.Json"));
        assertEquals(Optional.empty(), FileFormats.find("model.stl"));
        assertEquals(Optional.empty(), FileFormats.find("obj"), "a bare word is not a file of that format");
    }

    @Test
    void everyWritableFormatReadsBackWhatItWrote() throws IOException {
        Scene teapot = Models.teapot();
        for (FileFormat f : FileFormats.writable()) {
            Path file = dir.resolve("teapot." + f.extensions().get(0));
            f.write(file, new SceneDocument(teapot, RenderSettings.defaults()));
            assertEquals(teapot.patches(), SceneFiles.load(file.toString()).scene().patches(), f.name());
            String text = f.toText(new SceneDocument(teapot, RenderSettings.defaults()));
            SceneDocument again = f.read(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), "t", null);
            assertEquals(teapot.patches(), again.scene().patches(), f.name() + " from a stream");
        }
    }

    @Test
    void aFolderOrAMissingFileIsOneLineNamingIt() {
        String folder = UserMessages.of(ModelFormatException.class, () -> FileFormats.OBJ.read(dir));
        assertEquals(dir + ": is a folder, not a file", folder);
        Path missing = dir.resolve("gone.bpt");
        assertEquals(missing + ": no such file",
                UserMessages.of(ModelFormatException.class, () -> FileFormats.BPT.read(missing)));
    }

    @Test
    void builtInNamesAreDeclaredOnceAndLoadInAnyCase() {
        List<String> models = List.of("patch", "teapot", "teacup", "teaspoon", "sphere", "torus", "trimmed-plate",
                "wavy6", "wavy10", "curved");
        assertEquals(models, BuiltIns.names(Holds.MODEL));
        List<String> all = new java.util.ArrayList<>(models);
        all.add("teapot-room");
        all.add("studio");
        assertEquals(all, BuiltIns.names());
        assertEquals(List.of("teapot-room", "studio"), BuiltIns.names(Holds.SCENE));
        for (BuiltIns.BuiltIn b : BuiltIns.ALL) {
            SceneDocument doc = b.load();
            assertTrue(doc.scene().patchCount() > 0, b.name());
            assertEquals(doc, b.load(), b.name() + " is read once and shared");
            assertEquals(b, BuiltIns.find(b.name().toUpperCase(java.util.Locale.ROOT)).orElseThrow());
        }
        assertFalse(BuiltIns.find("kettle").isPresent());
        assertEquals(32, SceneFiles.load("TEAPOT-Room").scene().patchCount());
    }

    @Test
    void aSceneFilesBuiltinKeyTakesOnlyModels() {
        String message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse(
                "{\"version\": 1, \"models\": [{\"builtin\": \"teapot-room\"}]}", "s.json", null));
        assertEquals("s.json: models[0].builtin: unknown built-in model \"teapot-room\" (expected one of: patch,"
                + " teapot, teacup, teaspoon, sphere, torus, trimmed-plate, wavy6, wavy10,"
                + " curved)", message);
    }
}
