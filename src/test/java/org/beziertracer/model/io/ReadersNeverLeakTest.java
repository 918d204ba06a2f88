package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.UserMessages;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Whatever bytes a file holds, every reader answers with a scene or one clear line naming the file. */
class ReadersNeverLeakTest {

    @TempDir
    Path dir;

    static final String BPT = "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n";
    static final String OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n";
    static final String JSON = "{\"version\": 1, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1}]}";
    static final String SPHERE = "\"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1}]";

    private Path write(String name, byte[] bytes) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, bytes);
        return p;
    }

    private static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }

    private static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private static String loadError(Path p) {
        return UserMessages.of(ModelFormatException.class, () -> SceneFiles.load(p.toString()));
    }

    @Test
    void aFileThatIsNotUtf8IsNotATextFileWithTheOffsetOfTheFirstBadByte() throws IOException {
        for (String[] f : new String[][] {{"m.bpt", BPT}, {"m.obj", OBJ}, {"s.json", JSON}}) {
            byte[] good = utf8(f[1]);
            int at = good.length / 2;
            byte[] bad = concat(java.util.Arrays.copyOf(good, at), new byte[] {(byte) 0xC3, (byte) 0x28},
                    java.util.Arrays.copyOfRange(good, at, good.length));
            Path p = write(f[0], bad);
            assertEquals(p + ": not a text file (invalid UTF-8 at byte " + at + ")", loadError(p));
        }
    }

    @Test
    void aTruncatedMultiByteCharacterAtTheEndIsNotText() throws IOException {
        Path p = write("cut.bpt", concat(utf8(BPT + "# é"), new byte[] {(byte) 0xE2, (byte) 0x82}));
        assertEquals(p + ": not a text file (invalid UTF-8 at byte " + utf8(BPT + "# é").length + ")", loadError(p));
    }

    @Test
    void aByteOrderMarkIsAcceptedByEveryReader() throws IOException {
        byte[] bom = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
        for (String[] f : new String[][] {{"m.bpt", BPT}, {"m.obj", OBJ}, {"s.json", JSON}}) {
            Scene plain = SceneFiles.load(write("plain-" + f[0], utf8(f[1])).toString()).scene();
            Scene marked = SceneFiles.load(write("bom-" + f[0], concat(bom, utf8(f[1]))).toString()).scene();
            assertEquals(plain.patches(), marked.patches(), f[0]);
            assertEquals(plain.spheres(), marked.spheres(), f[0]);
        }
    }

    @Test
    void crlfLineEndsReadLikeLf() throws IOException {
        for (String[] f : new String[][] {{"m.bpt", BPT}, {"m.obj", OBJ}}) {
            Scene lf = SceneFiles.load(write("lf-" + f[0], utf8(f[1])).toString()).scene();
            Scene crlf = SceneFiles.load(write("crlf-" + f[0], utf8(f[1].replace("\n", "\r\n"))).toString()).scene();
            assertEquals(lf.patches(), crlf.patches(), f[0]);
        }
        String bad = loadError(write("crlf.obj", utf8("v 0 0 0\r\nv 1 0 x\r\n")));
        assertTrue(bad.contains("crlf.obj:2: expected a number"), bad);
    }

    @Test
    void aLineLongerThanTheCapIsRefusedWithTheCapInTheMessage() throws IOException {
        String longComment = "#" + "x".repeat(ReadLimits.DEFAULT.lineChars()) + "\n";
        Path p = write("long.obj", utf8(OBJ.substring(0, 8) + longComment + OBJ.substring(8)));
        assertEquals(p + ":2: line longer than " + ReadLimits.DEFAULT.lineChars()
                + " characters, the most a line may hold", loadError(p));
    }

    @Test
    void aSceneFileLargerThanTheInMemoryCapIsRefusedBeforeReading() throws IOException {
        Path p = dir.resolve("huge.json");
        try (RandomAccessFile f = new RandomAccessFile(p.toFile(), "rw")) {
            f.setLength(ReadLimits.DEFAULT.bytesInMemory() + 1); // sparse: no disk used
        }
        String message = loadError(p);
        assertTrue(message.startsWith(p + ": the file holds " + (ReadLimits.DEFAULT.bytesInMemory() + 1)
                + " bytes, more than the " + (ReadLimits.DEFAULT.bytesInMemory() >> 20) + " MB a scene file may hold"),
                message);
    }

    @Test
    void objPatchCountsAreCappedBeforeThePatchesAreBuilt() {
        // One bilinear surf of 1001 x 1000 segments: 1,001,000 patches, all on vertex 1
        int segmentsU = 1001, segmentsV = 1000;
        StringBuilder sb = new StringBuilder("v 0 0 0\ncstype bezier\ndeg 1 1\nsurf 0 1 0 1");
        long refs = (long) (segmentsU + 1) * (segmentsV + 1);
        for (long k = 0; k < refs; k++) {
            sb.append(" 1");
        }
        sb.append("\nparm u");
        for (int a = 0; a <= segmentsU; a++) {
            sb.append(' ').append(a / (double) segmentsU);
        }
        sb.append("\nparm v");
        for (int b = 0; b <= segmentsV; b++) {
            sb.append(' ').append(b / (double) segmentsV);
        }
        sb.append("\nend\n");
        String message = UserMessages.of(ModelFormatException.class, () -> ObjReader.read(sb.toString(), "big.obj"));
        assertEquals("big.obj:4: a model may have at most " + ReadLimits.DEFAULT.patches() + " patches; this surf"
                + " makes 1001000 more after 0", message);
    }

    @Test
    void sceneErrorsNameTheFileAndTheJsonPath() {
        String message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse("{\"version\": 1,"
                + " \"spheres\": [{\"center\": [0, \"x\", 0], \"radius\": 1}]}", "scene.json", null));
        assertEquals("scene.json: spheres[0].center[1]: expected a number, found \"x\"", message);
        message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse("{\"version\": 1, " + SPHERE
                + ", \"materials\": {\"red\": {\"color\": [1, 0, true]}}}", "scene.json", null));
        assertEquals("scene.json: materials.red.color[2]: expected a number, found true", message);
    }

    @Test
    void echoedInputIsCutToSixtyCharacters() {
        String key = "k".repeat(10_000_000);
        String message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse("{\"version\": 1, "
                + SPHERE + ", \"" + key + "\": 1}", "scene.json", null));
        String shown = message.substring(0, Math.min(message.length(), 300));
        assertTrue(message.contains("\"" + "k".repeat(Echo.MAX_CHARS - 1) + "…\""), shown);
        assertTrue(message.length() < 300, shown);
        String sampler = "fancy".repeat(100);
        message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse("{\"version\": 1, " + SPHERE
                + ", \"render\": {\"sampler\": \"" + sampler + "\"}}", "scene.json", null));
        assertTrue(message.startsWith("scene.json: render.sampler: unknown sampler '" + sampler.substring(0, 59) + "…'"),
                message);
        String token = "9".repeat(100) + "x";
        message = UserMessages.of(ModelFormatException.class, () -> BptReader.read("1\n1 1\n" + token, "t.bpt"));
        assertTrue(message.endsWith("found \"" + "9".repeat(Echo.MAX_CHARS - 1) + "…\""), message);
    }

    @Test
    void aJsonNullIsDescribedWithoutTheWordNull() {
        String message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse("{\"version\": 1,"
                + " \"spheres\": [{\"center\": [0, 0, 0], \"radius\": null}]}", "scene.json", null));
        assertEquals("scene.json: spheres[0].radius: expected a positive number, found no value", message);
    }

    @Test
    void overflowsSayWhichValueOverflowed() throws IOException {
        String light = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse("{\"version\": 1, " + SPHERE
                + ", \"lights\": [{\"position\": [0, 0, 9], \"color\": [1e308, 1e308, 1]}]}", "scene.json", null));
        assertEquals("scene.json: lights[0]: the light's total intensity r + g + b = 1e308 + 1e308 + 1 overflows"
                + " (beyond the largest number, about 1.8e308)", light);
        String moved = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse("{\"version\": 1,"
                + " \"models\": [{\"builtin\": \"patch\", \"transform\": {\"translate\": [1.7e308, 0, 0],"
                + " \"scale\": 1e308}}]}", "scene.json", null));
        assertEquals("scene.json: models[0].transform: the translation overflows the x coordinate of control point"
                + " P(2,0) of patch 1: 5e307 + 1.7e308 is beyond the largest number, about 1.8e308", moved);
        String camera = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse("{\"version\": 1, " + SPHERE
                + ", \"camera\": {\"eye\": [1e308, 0, 0], \"target\": [-1e308, 0, 0]}}", "scene.json", null));
        assertEquals("scene.json: camera: the distance from eye to target overflows (x: 1e308 - -1e308 is beyond"
                + " the largest number, about 1.8e308)", camera);
        Path wide = write("wide.bpt", utf8("1\n1 1\n-1e308 0 0\n1e308 0 0\n0 1 0\n1 1 1\n"));
        assertEquals(wide + ": the control points span x[-1e308,1e308] y[0,1] z[0,1], a size that overflows"
                + " (beyond the largest number, about 1.8e308)", loadError(wide));
    }

    @Test
    void everyReaderMessageForTheseBadFilesIsOneLineNamingTheFile() throws IOException {
        List<String[]> bad = List.of(new String[] {"a.bpt", "2\n1 1\n"}, new String[] {"a.obj", "v 1 2\n"},
                new String[] {"a.json", "{\"version\": 1, \"spheres\": [}"});
        for (String[] f : bad) {
            Path p = write(f[0], utf8(f[1]));
            assertTrue(loadError(p).startsWith(p + ":"), f[0]);
        }
    }
}
