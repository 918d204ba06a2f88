/**
 * Bézier Tracer: a ray tracer that renders Bézier surfaces directly, without triangles.
 *
 * <p>Layers, each importing only those before it: {@code math → model (+ model.io) → geometry →
 * accel → intersect → render → ui / cli}. See {@code docs/architecture.md}.
 *
 * <p>The hot path, in reading order (one ray):
 * {@code RenderWorker.renderTile → Camera.generateRay → SceneIntersector.closestHit →
 * Bvh.traverse → BezierClipper.intersect → SurfacePoint.evaluate → PhongShader.shade →
 * Film.addSample}
 */
package org.beziertracer;
