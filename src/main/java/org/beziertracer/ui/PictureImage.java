package org.beziertracer.ui;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;

import org.beziertracer.app.Picture;

/**
 * A {@link BufferedImage} over a {@link Picture}'s own pixel array ({@code TYPE_INT_RGB} layout):
 * what render threads write is what the panel draws, with no copy and no {@code setRGB}.
 * Event thread only; one image per picture, made once.
 */
final class PictureImage {

    private Picture picture;
    private BufferedImage image;

    /** The image showing {@code p} (the same object until the picture is replaced). */
    BufferedImage of(Picture p) {
        if (p != picture) {
            picture = p;
            image = wrap(p);
        }
        return image;
    }

    static BufferedImage wrap(Picture p) {
        DirectColorModel rgb = new DirectColorModel(24, 0xFF0000, 0x00FF00, 0x0000FF);
        DataBufferInt data = new DataBufferInt(p.pixels(), p.pixels().length);
        WritableRaster raster = Raster.createPackedRaster(data, p.width(), p.height(), p.width(),
                rgb.getMasks(), null);
        return new BufferedImage(rgb, raster, false, null);
    }
}
