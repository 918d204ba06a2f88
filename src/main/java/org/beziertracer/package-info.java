/**
 * Bézier Tracer: a ray tracer that renders Bézier surfaces directly, without triangles.
 *
 * <p>Layers, each importing only those before it: {@code math → model (+ model.io) → geometry →
 * accel → intersect → render → ui / cli}. See {@code docs/architecture.md}.
 *
 * <p>The hot path, in reading order (one ray):
 * {@code RenderWorker.renderTile → PixelSampler.offset → Camera.generateRay →
 * WhittedTracer.trace → SceneIntersector.closestHit → Bvh.closestHit → PatchLeaves.intersect →
 * ClippingLeaves.solve → BezierClipper.intersect → SceneIntersector.surfacePoint →
 * PatchLeaves.surfacePoint → WhittedTracer.shade (→ SceneIntersector.occluded per light) →
 * Film.addSample}
 */
package org.beziertracer;
