package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import javax.imageio.ImageIO;

import org.beziertracer.model.io.JobDocument;
import org.beziertracer.model.io.JobFiles;
import org.beziertracer.model.io.ModelFormatException;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * Issue 37: the tiles of a job's frame, rendered separately ({@link JobFrames#renderTile}) and put
 * together ({@link FrameAssembly}), are byte for byte the whole frame: its PNG pixels and its .pfm floats.
 */
class JobFramesTest {

    @TempDir
    Path dir;

    static final String SCENE = "{\"version\": 1, \"models\": [{\"builtin\": \"teapot\"}],"
            + " \"lights\": [{\"position\": [-200, -350, 450]}],"
            + " \"render\": {\"width\": 37, \"height\": 27}}";

    static JobDocument job(String settings) {
        return JobFiles.parse("{\"job\": 1, \"scene\": " + SCENE + ", \"seed\": 11, \"settings\": {" + settings + "},"
                + " \"camera\": {\"turntable\": {\"frames\": 2}}}", "job.json", null, m -> { });
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = ';', value = {"\"spp\": 2, \"sampler\": \"jittered\"",
            "\"spp\": 3, \"sampler\": \"adaptive\"",
            "\"spp\": 2, \"sampler\": \"jittered\", \"integrator\": \"path\", \"pathDepth\": 4, \"exposure\": 0.5"})
    void aFrameAssembledFromTilesIsTheWholeFrameByteForByte(String settings) throws Exception {
        JobFrames frames = JobFrames.of(job(settings), 2, "job.json");
        int n = 4;
        for (int f = 1; f <= 2; f++) {
            TilePixels whole;
            try (RenderSession session = new RenderSession(1, FrameSink.NONE)) {
                whole = frames.render(session, f, PixelWindow.whole(37, 27));
            }
            assertTrue(Arrays.stream(whole.argb()).distinct().count() > 20, "the frame has detail: "
                    + Arrays.stream(whole.argb()).distinct().count() + " colours");
            FrameAssembly frame = new FrameAssembly(37, 27);
            for (int i = n; i >= 1; i--) {
                assertFalse(frame.isComplete());
                frame.add(frames.renderTile(f, i, n));
            }
            assertTrue(frame.isComplete());
            assertArrayEquals(Pfm.encode(37, 27, whole.rgb()), frame.pfm(), "the .pfm floats of frame " + f);
            assertArrayEquals(whole.argb(), pixels(frame.png()), "the PNG pixels of frame " + f);
            Path png = dir.resolve("f.png"), pfm = dir.resolve("f.pfm");
            frame.write(png, pfm);
            assertArrayEquals(frame.pfm(), Files.readAllBytes(pfm));
            assertArrayEquals(whole.argb(), pixels(Files.readAllBytes(png)));
        }
    }

    @Test
    void aTileTravelsAsBytesAndComesBackTheSame() throws Exception {
        TilePixels t = JobFrames.of(job("\"spp\": 1"), 1, "job.json").renderTile(2, 3, 5);
        TilePixels back = TilePixels.fromBytes(t.toBytes(), "t");
        assertEquals(t.window(), back.window());
        assertArrayEquals(t.argb(), back.argb());
        assertArrayEquals(t.rgb(), back.rgb());
        byte[] cut = Arrays.copyOf(t.toBytes(), t.toBytes().length - 1);
        assertEquals("t: a 37x5 tile needs 2980 bytes, the file has 2979",
                assertThrows(IllegalArgumentException.class, () -> TilePixels.fromBytes(cut, "t")).getMessage());
        assertEquals("x: not a tile file",
                assertThrows(IllegalArgumentException.class, () -> TilePixels.fromBytes(new byte[40], "x")).getMessage());
    }

    @Test
    void aTileAsBytesIsItsRawBitsBigEndianAfterTheHeader() {
        // 3x2 pixels at (5, 7): values that a stream of floats would change (a NaN's payload) or lose (-0)
        float nan = Float.intBitsToFloat(0x7fa00001);
        int[] argb = {0xff010203, 0xff7f8081, 0, -1, 0x12345678, 0xfffefdfc};
        float[] rgb = new float[18];
        for (int k = 0; k < rgb.length; k++) {
            rgb[k] = k * 0.37f - 2;
        }
        rgb[4] = nan;
        rgb[9] = -0f;
        rgb[17] = Float.POSITIVE_INFINITY;
        TilePixels t = new TilePixels(new PixelWindow(5, 7, 8, 9), argb, rgb);
        byte[] bytes = t.toBytes();
        int[] words = {0x42545431, 5, 7, 8, 9};
        byte[] expected = new byte[20 + 16 * 6];
        int at = 0;
        for (int w : words) {
            at = bigEndian(expected, at, w);
        }
        for (int p : argb) {
            at = bigEndian(expected, at, p);
        }
        for (float f : rgb) {
            at = bigEndian(expected, at, Float.floatToRawIntBits(f));
        }
        assertArrayEquals(expected, bytes);
        TilePixels back = TilePixels.fromBytes(bytes, "t");
        assertEquals(t.window(), back.window());
        assertArrayEquals(argb, back.argb());
        for (int k = 0; k < rgb.length; k++) {
            assertEquals(Float.floatToRawIntBits(rgb[k]), Float.floatToRawIntBits(back.rgb()[k]), "float " + k);
        }
    }

    private static int bigEndian(byte[] out, int at, int v) {
        out[at] = (byte) (v >>> 24);
        out[at + 1] = (byte) (v >>> 16);
        out[at + 2] = (byte) (v >>> 8);
        out[at + 3] = (byte) v;
        return at + 4;
    }

    @Test
    void anAssemblyRefusesOverlapsAndAMissingTile() throws Exception {
        JobFrames frames = JobFrames.of(job("\"spp\": 1"), 1, "job.json");
        FrameAssembly frame = new FrameAssembly(37, 27);
        frame.add(frames.renderTile(1, 1, 2));
        assertTrue(assertThrows(IllegalStateException.class, frame::png).getMessage().contains("a tile is missing"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> frame.add(frames.renderTile(1, 1, 2)))
                .getMessage().contains("twice"));
        assertThrows(IllegalArgumentException.class, () -> new FrameAssembly(36, 27).add(frames.renderTile(1, 2, 2)));
    }

    @Test
    void aFrameOutsideTheJobAndABadCameraAreRefused() {
        JobFrames frames = JobFrames.of(job("\"spp\": 1"), 1, "job.json");
        assertEquals("frame 3 is not in the job's 1-2", assertThrows(IllegalArgumentException.class,
                () -> frames.job(3, PixelWindow.whole(37, 27))).getMessage());
        JobDocument turnsOver = JobFiles.parse("{\"job\": 1, \"scene\": " + SCENE + ", \"camera\": {\"keyframes\": ["
                + "{\"frame\": 0, \"eye\": [60, 0, 0], \"target\": [0, 0, 0]}, {\"frame\": 2, \"eye\": [60, 0, 0],"
                + " \"target\": [0, 0, 0], \"up\": [0, 0, -1]}]}}", "job.json", null, m -> { });
        assertTrue(assertThrows(ModelFormatException.class, () -> JobFrames.of(turnsOver, 1, "job.json")).getMessage()
                .startsWith("job.json: camera: frame 1: "));
    }

    @Test
    void pngBytesHoldExactlyTheGivenPixels() throws IOException {
        java.util.Random random = new java.util.Random(37);
        for (int k = 0; k < 20; k++) {
            int w = 1 + random.nextInt(70), h = 1 + random.nextInt(40);
            int[] argb = new int[w * h];
            for (int p = 0; p < argb.length; p++) {
                argb[p] = 0xff000000 | random.nextInt(1 << 24);
            }
            assertArrayEquals(argb, pixels(Png.encode(w, h, argb)), "random " + w + "x" + h + " image, case " + k);
        }
    }

    static int[] pixels(byte[] png) throws IOException {
        BufferedImage img = ImageIO.read(new ByteArrayInputStream(png));
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }
}
