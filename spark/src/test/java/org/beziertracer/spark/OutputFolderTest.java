package org.beziertracer.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import org.apache.hadoop.fs.RawLocalFileSystem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The output folder on {@code file://}: files written whole, read back in one piece, no checksum files. */
class OutputFolderTest {

    @TempDir
    Path dir;

    @Test
    void aLocalFolderReadsAndWritesTilesWithoutHadoopsChecksumLayer() throws Exception {
        OutputFolder folder = new OutputFolder(dir.toUri().toString());
        // LocalFileSystem (checksummed) would read a tile 512 bytes a call through FSInputChecker
        assertInstanceOf(RawLocalFileSystem.class, folder.fileSystem());
        byte[] bytes = new byte[3 * 1024 * 1024 + 17];
        new Random(5).nextBytes(bytes);
        org.apache.hadoop.fs.Path tile = folder.tile("job-f0000001-t0001of0002.tile");
        folder.writeAtomically(tile, bytes, OutputFolder.attemptTag());
        assertArrayEquals(bytes, folder.read(tile));
        assertArrayEquals(bytes, Files.readAllBytes(dir.resolve("tiles/job-f0000001-t0001of0002.tile")));
        // the file only: no temporary name left, no .crc beside it
        try (Stream<Path> files = Files.list(dir.resolve("tiles"))) {
            assertEquals(List.of("job-f0000001-t0001of0002.tile"),
                    files.map(p -> p.getFileName().toString()).toList());
        }
        assertArrayEquals(new byte[0], readEmpty(folder));
    }

    private static byte[] readEmpty(OutputFolder folder) throws Exception {
        org.apache.hadoop.fs.Path empty = folder.frame("empty.png");
        folder.writeAtomically(empty, new byte[0], "t");
        return folder.read(empty);
    }
}
