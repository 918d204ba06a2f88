package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import org.beziertracer.ChildJvm;
import org.beziertracer.Main;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** PNGs are encoded in memory: no ImageIO cache file in the temporary folder (issue 36). */
class PngWriterTest {

    @TempDir
    Path dir;

    @Test
    void theWrittenPngHoldsThePixels() throws Exception {
        int[] argb = {0xFF102030, 0xFFFFFFFF, 0xFF000000, 0xFFABCDEF, 0xFF00FF00, 0xFF7F7F7F};
        Path png = dir.resolve("p.png");
        PngWriter.write(png, 3, 2, argb);
        BufferedImage back = ImageIO.read(png.toFile());
        for (int k = 0; k < argb.length; k++) {
            assertEquals(argb[k], back.getRGB(k % 3, k / 3), "pixel " + k);
        }
    }

    @Test
    void aRenderNeedsNoTemporaryFolderForTheImage() throws Exception {
        // ImageIO's file cache would go into java.io.tmpdir; with none there, the write would fail
        Path missing = dir.resolve("no-such-tmp");
        ChildJvm.Result r = ChildJvm.run(dir, List.of("-Djava.io.tmpdir=" + missing), Main.class.getName(),
                "render", "patch", "--size", "8x8", "-o", "p.png");
        assertEquals(0, r.code(), r.err());
        assertEquals(8, ImageIO.read(dir.resolve("p.png").toFile()).getWidth());
        assertFalse(Files.exists(missing));
    }
}
