/**
 * Acceleration structures over plain axis-aligned boxes: a binned-SAH {@link
 * org.beziertracer.accel.Bvh} and a brute-force {@link org.beziertracer.accel.FlatList}, both
 * behind {@link org.beziertracer.accel.Accelerator}.
 *
 * <p>This package knows nothing of patches: a primitive is an index {@code 0..primCount-1} with a
 * box of six doubles {@code minX, minY, minZ, maxX, maxY, maxZ}; leaves call back through {@link
 * org.beziertracer.accel.LeafIntersector} (closest hit) and {@link
 * org.beziertracer.accel.LeafOccluder} (any hit). Imports only {@code org.beziertracer.math} and the
 * JDK.
 *
 * <p>Rays are given as origin plus reciprocal direction; see {@link org.beziertracer.accel.RayBox}
 * for how zero direction components ({@code invD = ±Infinity}) are handled.
 */
package org.beziertracer.accel;
