/**
 * Bézier Tracer: a ray tracer that renders Bézier surfaces directly, without triangles.
 *
 * <p>Layers, each importing only those before it: {@code math → model (+ model.io) → geometry →
 * accel → intersect → render → ui / cli}. See {@code docs/architecture.md}.
 *
 * <p>The hot path, in reading order (a packet of camera rays, see {@code RayPacket}):
 * {@code RenderWorker.renderTile → PixelSampler.offset → Camera.generateRay →
 * WhittedTracer.tracePacket → SceneIntersector.gather → SceneIntersector.closestHits →
 * Bvh.closestHitsIn → ClippingLeaves.intersect (lanes) → BezierClipper.begin → NewtonLanes.solve →
 * SceneIntersector.surfacePoint → PatchLeaves.surfacePoint → (per light: SceneIntersector.gather,
 * SceneIntersector.occludedLeaving) → WhittedTracer.shadeHit → Film.addSample}
 */
package org.beziertracer;
