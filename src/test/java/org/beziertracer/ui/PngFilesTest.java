package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Export Image encodes in memory: ImageIO's cache file is never needed (issue 36). */
class PngFilesTest {

    @TempDir
    Path dir;

    @Test
    void encodingNeedsNoCacheFolder() throws Exception {
        Path cache = Files.createDirectory(dir.resolve("cache"));
        boolean used = ImageIO.getUseCache();
        File before = ImageIO.getCacheDirectory();
        ImageIO.setUseCache(true);
        ImageIO.setCacheDirectory(cache.toFile());
        Files.delete(cache); // a cache file would now fail to be created
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            PngFiles.encoder(2, 1, new int[] {0xFF123456, 0xFF654321}).writeTo(out);
        } finally {
            ImageIO.setCacheDirectory(before);
            ImageIO.setUseCache(used);
        }
        BufferedImage back = ImageIO.read(new ByteArrayInputStream(out.toByteArray()));
        assertEquals(0xFF654321, back.getRGB(1, 0));
    }
}
