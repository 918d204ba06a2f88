package org.beziertracer.app;

/** A control point {@code P_ij} of patch {@code patch} of the current scene. */
public record PointRef(int patch, int i, int j) {
}
