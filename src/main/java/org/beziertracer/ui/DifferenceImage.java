package org.beziertracer.ui;

import java.awt.image.BufferedImage;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.DifferenceMask;
import org.beziertracer.app.Picture;
import org.beziertracer.app.Toggle;

/**
 * View → Difference to clipping as an image to draw over the picture: the app's
 * {@link DifferenceMask} (red marks on a dark veil), made once per mask. Event thread only.
 */
final class DifferenceImage {

    private DifferenceMask mask;
    private BufferedImage image;

    /** The overlay to draw over {@code picture} now, or null (off, being computed, or for another size). */
    BufferedImage of(AppModel app, Picture picture) {
        DifferenceMask m = app.difference().current();
        if (m == null || picture == null || !app.settings().current().on(Toggle.DIFFERENCE_TO_CLIPPING)
                || m.width() != picture.width() || m.height() != picture.height()) {
            return null;
        }
        if (m != mask) {
            mask = m;
            image = new BufferedImage(m.width(), m.height(), BufferedImage.TYPE_INT_ARGB);
            image.setRGB(0, 0, m.width(), m.height(), m.argb(), 0, m.width());
        }
        return image;
    }
}
