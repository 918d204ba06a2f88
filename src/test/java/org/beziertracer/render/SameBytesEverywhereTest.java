package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 32's "same pictures everywhere": a render is the same to the bit on one thread and on two,
 * in small tiles and in big ones, with the scalar and the SIMD kernel (the batches, the per-thread
 * memories of failed proofs and the lane order change the work, never a pixel).
 */
class SameBytesEverywhereTest {

    private static final int W = 120, H = 90;

    @ParameterizedTest
    @ValueSource(strings = {"wavy10", "curved", "teapot-room"})
    void aRenderIsTheSameOnAnyThreadCountTileSizeAndKernel(String model) {
        SceneDocument doc = SceneFiles.load(model);
        Scene scene = doc.scene();
        if (!model.equals("teapot-room")) {
            // a light that casts shadows on the surface itself: shadow batches and own-leaf proofs run
            scene = scene.toBuilder().lights(List.of(new PointLight(new Vec3(-8, 0.5, 1.5)))).build();
        }
        float[] reference = null;
        for (LaneKernel kernel : new LaneKernel[] {Kernels.scalar(), Kernels.named("simd")}) {
            for (int threads : new int[] {1, 2}) {
                for (int tile : new int[] {8, 32}) {
                    RenderOptions options = RenderOptions.defaults().withThreads(threads).withTileSize(tile)
                            .withProgressive(false).withKernel(kernel);
                    RenderJob job = RenderJob.prepare(scene, TestScenes.settings(W, H, "phong"), options);
                    float[] rgb = Renderer.renderOnce(job).film().linearRgb();
                    if (reference == null) {
                        reference = rgb;
                        int lit = 0;
                        for (int i = 0; i + 2 < rgb.length; i += 3) {
                            lit += rgb[i] + rgb[i + 1] + rgb[i + 2] > 0.3 ? 1 : 0;
                        }
                        assertTrue(lit > W * H / 20, model + ": only " + lit + " bright pixels, the model is not in view");
                    } else {
                        assertArrayEquals(reference, rgb, model + ": " + kernel.description() + ", " + threads
                                + " threads, tiles of " + tile + " differ from the scalar one-thread render");
                    }
                }
            }
        }
    }

    /** The analysis views too: the same curvature and colours from either kernel and any thread count. */
    @ParameterizedTest
    @ValueSource(strings = {"gaussian", "min-radius", "zebra", "draft"})
    void anAnalysisViewIsTheSameOnAnyThreadCountAndKernel(String view) {
        Scene scene = SceneFiles.load("wavy10").scene();
        float[] reference = null;
        for (LaneKernel kernel : new LaneKernel[] {Kernels.scalar(), Kernels.named("simd")}) {
            for (int threads : new int[] {1, 2}) {
                RenderOptions options = RenderOptions.defaults().withThreads(threads).withTileSize(16)
                        .withProgressive(false).withKernel(kernel);
                float[] rgb = Renderer.renderOnce(RenderJob.prepare(scene, TestScenes.settings(W, H, view), options))
                        .film().linearRgb();
                if (reference == null) {
                    reference = rgb;
                } else {
                    assertArrayEquals(reference, rgb, view + ": " + kernel.description() + ", " + threads + " threads");
                }
            }
        }
    }
}
