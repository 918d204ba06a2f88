package org.beziertracer.cli;

import org.beziertracer.render.PixelWindow;

import picocli.CommandLine.Option;

/**
 * The options that pick a piece of a render (issue 37): {@code --crop x0,y0,x1,y1} or
 * {@code --tile i/N}. A piece's pixels are byte-identical to the same pixels of the whole render. A
 * picocli mixin.
 */
final class PieceOptions {

    @Option(names = "--crop", paramLabel = "x0,y0,x1,y1", description = "render only the pixels x0 <= x < x1, "
            + "y0 <= y < y1 (from the top left) with the whole image's camera; the PNG holds just that rectangle")
    String crop;

    @Option(names = "--tile", paramLabel = "i/N", description = "render only the i-th (from 1) of N bands of rows "
            + "of equal height (the last takes the rest); the PNG holds just that band")
    String tile;

    @Option(names = "--frames", paramLabel = "A-B", description = "with a job file: render only its frames A to B "
            + "(or just A)")
    String frames;

    /** Fails when both are given (before anything is read). */
    void check() {
        if (crop != null && tile != null) {
            throw new IllegalArgumentException("--crop and --tile cannot be used together; pick one");
        }
    }

    /** The window of a {@code width × height} image to render (the whole image without either option). */
    PixelWindow window(int width, int height) {
        check();
        if (crop != null) {
            return PixelWindow.parseCrop(crop, width, height);
        }
        if (tile != null) {
            return PixelWindow.parseTile(tile, width, height);
        }
        return PixelWindow.whole(width, height);
    }
}
