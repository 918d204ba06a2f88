package org.beziertracer.render;

import java.awt.image.BufferedImage;
import java.io.File;

import javax.imageio.ImageIO;

/** Writes the golden scenes to /tmp for a look (not a test). */
final class GoldenPreview {
    public static void main(String[] args) throws Exception {
        for (GoldenImageTest.Case c : GoldenImageTest.cases()) {
            RenderResult r = Renderer.renderOnce(c.job(Integer.parseInt(args[0]), Integer.parseInt(args[1])));
            BufferedImage img = new BufferedImage(r.film().width(), r.film().height(), BufferedImage.TYPE_INT_RGB);
            img.setRGB(0, 0, r.film().width(), r.film().height(), r.argb(), 0, r.film().width());
            ImageIO.write(img, "png", new File("/tmp/golden-" + c.name() + ".png"));
            System.out.println(c.name() + " " + r.stats());
        }
    }
}
