package org.beziertracer.app;

/** A world axis a drag can be held to (while its key, X, Y or Z, is down). */
public enum Axis {
    X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);

    private final double[] unit;

    Axis(double x, double y, double z) {
        this.unit = new double[] {x, y, z};
    }

    /** Component {@code c} (0 = x, 1 = y, 2 = z) of the unit vector along this axis. */
    public double component(int c) { return unit[c]; }
}
