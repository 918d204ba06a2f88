/**
 * Turns exact hits into pictures: {@link org.beziertracer.render.Camera}, sampling
 * ({@link org.beziertracer.render.PixelSampler}), Whitted/Phong shading
 * ({@link org.beziertracer.render.WhittedTracer}), the float {@link org.beziertracer.render.Film},
 * and the tiled, progressive, multi-threaded {@link org.beziertracer.render.RenderSession} with
 * cancellation by generation number. Output goes to a {@link org.beziertracer.render.FrameSink};
 * no AWT or Swing here. See {@code docs/rendering.md}.
 *
 * <p>Hot path: {@code RenderWorker.renderTile → Camera.generateRay → WhittedTracer.trace →
 * SceneIntersector.closestHit / occluded → Film.addSample}; nothing is allocated per ray.
 */
package org.beziertracer.render;
