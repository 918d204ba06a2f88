package org.beziertracer.model.io;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Placement;

/**
 * The affine placement of a model in a scene file: {@code p' = T + Rz·Ry·Rx·(S·p)} — scale
 * first, then rotations about the x, y and z axes (degrees, right-handed), then translation.
 *
 * <p>Applied to the control points only: a Bézier patch is an affine combination of its control
 * points (the Bernstein weights sum to 1; for a rational patch the coefficients
 * {@code w B / Σ w B} do too), so mapping the net maps the surface exactly. Quarter
 * turns use exact sines and cosines (0, ±1), so rotating by 90° moves (1,0,0) exactly onto an axis.
 * Immutable.
 */
record ModelTransform(double[] translate, double[] scale, double[] rotateDegrees) implements Placement {

    static final ModelTransform IDENTITY = new ModelTransform(new double[3], new double[] {1, 1, 1}, new double[3]);

    boolean isIdentity() {
        for (int c = 0; c < 3; c++) {
            if (translate[c] != 0 || scale[c] != 1 || rotateDegrees[c] != 0) {
                return false;
            }
        }
        return true;
    }

    /** The same steps as {@link #apply(BezierPatch, int)}, point by point (a point that overflows is left part-mapped). */
    @Override
    public void mapPoints(double[] xyz, int offset, int count) {
        if (isIdentity()) {
            return;
        }
        double[] p = new double[3];
        for (int k = offset, end = offset + 3 * count; k < end; k += 3) {
            System.arraycopy(xyz, k, p, 0, 3);
            applyInPlace(p);
            System.arraycopy(p, 0, xyz, k, 3);
        }
    }

    /** Rotations and a translation keep distances; a scale keeps their ratios when it is the same (up to sign) on every axis. */
    @Override
    public boolean similarity() {
        double s = Math.abs(scale[0]);
        return Math.abs(scale[1]) == s && Math.abs(scale[2]) == s && s > 0;
    }

    /** Which step of the transform overflowed which coordinate, and the values that did it. */
    record Overflow(String step, int axis, String values) {}

    /**
     * The patch with every control point mapped.
     *
     * @param number the patch's 1-based number in its model, for the message when a coordinate overflows
     * @throws IllegalArgumentException naming the step, the coordinate and the values when one overflows
     */
    BezierPatch apply(BezierPatch patch, int number) {
        if (isIdentity()) {
            return patch;
        }
        double[] net = patch.copyNet();
        double[] p = new double[3];
        int n = patch.degreeU();
        for (int k = 0; k < net.length; k += 3) {
            System.arraycopy(net, k, p, 0, 3);
            Overflow o = applyInPlace(p);
            if (o != null) {
                int point = k / 3;
                throw new IllegalArgumentException("the " + o.step() + " overflows the " + "xyz".charAt(o.axis())
                        + " coordinate of control point P(" + point % (n + 1) + "," + point / (n + 1) + ") of patch "
                        + number + ": " + o.values() + " is " + NumberText.BEYOND);
            }
            System.arraycopy(p, 0, net, k, 3);
        }
        return patch.withNet(net); // weights and domain kept: a rational patch is affinely invariant too
    }

    /**
     * The mesh with every vertex mapped, and its normals by the inverse transpose (the scale's
     * inverse, then the rotations), made unit again.
     *
     * @throws IllegalArgumentException naming the step, the coordinate and the values when one overflows
     */
    Mesh apply(Mesh mesh) {
        if (isIdentity()) {
            return mesh;
        }
        double[] positions = mesh.positions();
        double[] p = new double[3];
        for (int k = 0; k < positions.length; k += 3) {
            System.arraycopy(positions, k, p, 0, 3);
            Overflow o = applyInPlace(p);
            if (o != null) {
                throw new IllegalArgumentException("the " + o.step() + " overflows the " + "xyz".charAt(o.axis())
                        + " coordinate of mesh vertex " + (k / 3 + 1) + ": " + o.values() + " is " + NumberText.BEYOND);
            }
            System.arraycopy(p, 0, positions, k, 3);
        }
        double[] normals = null;
        if (mesh.hasNormals()) {
            normals = mesh.normals();
            ModelTransform turn = new ModelTransform(new double[3],
                    new double[] {1 / scale[0], 1 / scale[1], 1 / scale[2]}, rotateDegrees);
            for (int k = 0; k < normals.length; k += 3) {
                System.arraycopy(normals, k, p, 0, 3);
                turn.applyInPlace(p);
                double len = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                double f = len > 0 && Double.isFinite(len) ? 1 / len : 0;
                for (int c = 0; c < 3; c++) {
                    normals[k + c] = Double.isFinite(p[c] * f) ? p[c] * f : 0;
                }
            }
        }
        return Mesh.faces(positions, normals, mesh.hasUvs() ? mesh.uvs() : null, mesh.triangles());
    }

    /** Maps the point {@code p} (x, y, z) in place; null, or the step that overflowed (p is then partly mapped). */
    Overflow applyInPlace(double[] p) {
        for (int c = 0; c < 3; c++) {
            double v = p[c] * scale[c];
            if (!Double.isFinite(v)) {
                return new Overflow("scale", c, NumberText.show(p[c]) + " × " + NumberText.show(scale[c]));
            }
            p[c] = v;
        }
        // Rotate about x, then y, then z: in the plane of the two other axes (a, b)
        for (int axis = 0; axis < 3; axis++) {
            double deg = rotateDegrees[axis];
            if (deg == 0) {
                continue;
            }
            int a = (axis + 1) % 3;
            int b = (axis + 2) % 3;
            double cos = cosDegrees(deg);
            double sin = cosDegrees(deg - 90);
            double pa = p[a];
            double pb = p[b];
            p[a] = cos * pa - sin * pb;
            p[b] = sin * pa + cos * pb;
            if (!Double.isFinite(p[a]) || !Double.isFinite(p[b])) {
                return new Overflow("rotation", Double.isFinite(p[a]) ? b : a, "turning (" + NumberText.show(pa)
                        + ", " + NumberText.show(pb) + ") by " + NumberText.show(deg) + "°");
            }
        }
        for (int c = 0; c < 3; c++) {
            double v = p[c] + translate[c];
            if (!Double.isFinite(v)) {
                return new Overflow("translation", c, NumberText.show(p[c]) + " + " + NumberText.show(translate[c]));
            }
            p[c] = v;
        }
        return null;
    }

    /** cos of an angle in degrees, exact (0, ±1) at multiples of 90°. */
    static double cosDegrees(double deg) {
        double r = deg % 360;
        if (r % 90 == 0) {
            int quarter = (int) Math.floorMod((long) (r / 90), 4L);
            return new double[] {1, 0, -1, 0}[quarter];
        }
        return Math.cos(Math.toRadians(r));
    }
}
