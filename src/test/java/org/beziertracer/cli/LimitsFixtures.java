package org.beziertracer.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.io.BptWriter;

/** Models for the limit tests. */
public final class LimitsFixtures {
    private LimitsFixtures() {}

    /**
     * Writes {@code count} wavy degree-15 patches (random points in a 10-unit cube, seeded): small
     * files whose patches split into the most sub-patches.
     */
    public static Path wavyModel(Path file, int count) throws IOException {
        Random rnd = new Random(7);
        List<BezierPatch> patches = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            double[] net = new double[16 * 16 * 3];
            for (int i = 0; i < net.length; i++) {
                net[i] = rnd.nextDouble() * 10;
            }
            patches.add(new BezierPatch(15, 15, net));
        }
        BptWriter.write(file, patches);
        return file;
    }
}
