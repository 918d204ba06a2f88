package org.beziertracer.app;

/**
 * A control point as drawn: which point, and where on the picture (device pixels).
 *
 * @param ref   the control point
 * @param x     picture x of its projection
 * @param y     picture y of its projection
 * @param depth distance from the eye plane along the view axis
 */
public record Handle(PointRef ref, double x, double y, double depth) {
}
