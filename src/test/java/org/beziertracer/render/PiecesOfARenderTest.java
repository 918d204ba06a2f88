package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Issue 37: a crop or a tile of a render holds exactly the bytes of the same pixels of the whole
 * render, for every sampler, a few sample counts and shadings, so pieces rendered anywhere assemble
 * into the whole picture.
 */
class PiecesOfARenderTest {

    private static final int W = 61, H = 43;
    /** Crops whose edges cross the sphere, the bump and the shadow, at odd places and sizes. */
    private static final List<PixelWindow> CROPS = List.of(new PixelWindow(0, 0, W, H), new PixelWindow(7, 5, 30, 22),
            new PixelWindow(29, 13, 61, 43), new PixelWindow(40, 0, 41, 43), new PixelWindow(3, 17, 58, 18),
            new PixelWindow(33, 9, 34, 10), new PixelWindow(11, 21, 52, 40));

    @ParameterizedTest(name = "{0} sampler, {1} spp, {2}")
    @CsvSource({"regular, 1, phong", "regular, 4, phong", "jittered, 1, phong", "jittered, 5, phong",
            "adaptive, 2, phong", "adaptive, 9, phong", "jittered, 3, normals", "adaptive, 4, gaussian"})
    void aCropHoldsTheBytesOfTheSamePixelsOfTheWholeRender(String sampler, int spp, String shading) {
        RenderJob whole = job(sampler, spp, shading, 32);
        int[] all = Renderer.renderOnce(whole).argb();
        assertTrue(Arrays.stream(all).distinct().count() > 20, "the picture has detail: " + sampler);
        for (PixelWindow crop : CROPS) {
            // small tiles inside the crop: another split of the work, the same pixels
            RenderResult piece = Renderer.renderOnce(job(sampler, spp, shading, 8).withWindow(crop));
            int[] argb = piece.argb();
            assertEquals(crop.width() * crop.height(), argb.length, "crop " + crop);
            for (int y = crop.y0(); y < crop.y1(); y++) {
                int[] expected = Arrays.copyOfRange(all, y * W + crop.x0(), y * W + crop.x1());
                int[] actual = Arrays.copyOfRange(argb, (y - crop.y0()) * crop.width(), (y - crop.y0() + 1) * crop.width());
                assertArrayEquals(expected, actual, sampler + " " + spp + " spp " + shading + ": crop " + crop
                        + " differs from the whole render in row " + y);
            }
        }
    }

    @Test
    void theAdaptiveSamplerGivesExtraSamplesToSomePixelsAndNotOthers() {
        // the adaptive case above only proves something when the neighbour test decides per pixel
        RenderResult r = Renderer.renderOnce(job("adaptive", 9, "phong", 32));
        int one = 0, nine = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                one += r.film().sampleCount(x, y) == 1 ? 1 : 0;
                nine += r.film().sampleCount(x, y) == 9 ? 1 : 0;
            }
        }
        assertTrue(one > 0 && nine > 0, "pixels with 1 sample: " + one + ", with 9: " + nine);
    }

    @Test
    void theTilesOfARenderAssembleIntoTheWholeRender() {
        RenderJob job = job("jittered", 2, "phong", 16);
        int[] all = Renderer.renderOnce(job).argb();
        for (int n : new int[] {1, 2, 5, 7, H}) {
            int[] assembled = new int[W * H];
            int next = 0;
            for (int i = 1; i <= n; i++) {
                PixelWindow tile = PixelWindow.tile(i, n, W, H);
                assertEquals(next, tile.y0(), "tile " + i + "/" + n + " starts where the previous ended");
                int[] argb = Renderer.renderOnce(job.withWindow(tile)).argb();
                System.arraycopy(argb, 0, assembled, tile.y0() * W, argb.length);
                next = tile.y1();
            }
            assertEquals(H, next, n + " tiles end at the last row");
            assertArrayEquals(all, assembled, n + " tiles assembled");
        }
    }

    @Test
    void aFilmOfAWindowKeepsImageCoordinates() {
        Film film = new Film(new PixelWindow(10, 20, 13, 22), false);
        film.addSample(12, 21, 1, 0.5, 0);
        assertEquals(1, film.sampleCount(12, 21));
        assertEquals(0, film.sampleCount(10, 20));
        float[] px = new float[3];
        film.pixel(12, 21, px);
        assertArrayEquals(new float[] {1, 0.5f, 0}, px);
        int[] argb = film.toArgb(new PixelWindow(11, 21, 13, 22));
        assertEquals(Srgb.argb(1f, 0.5f, 0f), argb[1], "the last pixel of the bottom row");
        assertEquals(new PixelWindow(10, 20, 13, 22), film.window());
        org.beziertracer.UserMessages.of(IllegalArgumentException.class, () -> film.toArgb(new PixelWindow(0, 0, 5, 5)));
    }

    private static RenderJob job(String sampler, int spp, String shading, int tileSize) {
        Scene scene = TestScenes.shadows();
        RenderSettings s = new RenderSettings(W, H, spp, sampler, "clipping", true, shading, 0, true, 5);
        RenderOptions o = RenderOptions.defaults().withThreads(2).withProgressive(false).withTileSize(tileSize);
        return RenderJob.prepare(scene, s, o).withCamera(TestScenes.camera());
    }
}
