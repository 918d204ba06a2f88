package org.beziertracer.cli;

import java.io.IOException;

/** A stream of rays for {@code trace}: six numbers {@code ox oy oz dx dy dz} a ray. */
interface RaySource extends AutoCloseable {
    boolean next(double[] ray) throws IOException;

    @Override
    void close() throws IOException;
}
