package org.beziertracer.cli;

import java.util.Random;

import org.beziertracer.math.Aabb;

/** Seeded random rays from a sphere around the box toward points inside it. */
final class RandomRays implements RaySource {
    private final Aabb box;
    private final Random rnd;
    private long left;

    RandomRays(Aabb box, long count, long seed) {
        this.box = box;
        this.rnd = new Random(seed);
        this.left = count;
    }

    @Override
    public boolean next(double[] ray) {
        if (left-- <= 0) {
            return false;
        }
        double r = box.diagonal();
        double cx = box.center().x(), cy = box.center().y(), cz = box.center().z();
        double gx = rnd.nextGaussian(), gy = rnd.nextGaussian(), gz = rnd.nextGaussian();
        double len = Math.sqrt(gx * gx + gy * gy + gz * gz);
        ray[0] = cx + r * gx / len;
        ray[1] = cy + r * gy / len;
        ray[2] = cz + r * gz / len;
        double tx = box.minX() + rnd.nextDouble() * (box.maxX() - box.minX());
        double ty = box.minY() + rnd.nextDouble() * (box.maxY() - box.minY());
        double tz = box.minZ() + rnd.nextDouble() * (box.maxZ() - box.minZ());
        ray[3] = tx - ray[0];
        ray[4] = ty - ray[1];
        ray[5] = tz - ray[2];
        return true;
    }

    @Override
    public void close() {}
}
