package org.beziertracer.model.io;

/**
 * The caps every reader keeps, so that no file, however large or malformed, makes the program
 * hold more than it can: each is named in the message of the error it causes.
 *
 * @param lineChars     longest line held in memory, in characters
 * @param bytesInMemory largest file read whole into memory (scene files), in bytes
 * @param patches       most patches in one model or scene
 * @param vertices      most OBJ vertices ({@code v}) in one file
 * @param sceneModels   most entries of a scene file's {@code models}
 * @param sceneObjects  most entries of each of a scene file's {@code materials}, {@code planes},
 *                      {@code spheres} and {@code lights}
 */
public record ReadLimits(int lineChars, long bytesInMemory, int patches, int vertices, int sceneModels,
                         int sceneObjects) {

    /** The caps of every file the program opens. */
    public static final ReadLimits DEFAULT = new ReadLimits(4 << 20, 64L << 20, 1_000_000, 25_000_000, 10_000,
            100_000);
}
