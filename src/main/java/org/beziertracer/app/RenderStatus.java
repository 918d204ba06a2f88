package org.beziertracer.app;

import org.beziertracer.intersect.Method;

/**
 * What the status bar shows about the latest render; made on render threads, shown on the UI
 * thread.
 *
 * @param pass           1-based pass just finished
 * @param passCount      passes of a full frame
 * @param millis         time since the render started
 * @param mraysPerSecond millions of rays (all kinds) per second
 * @param spp            samples per pixel of the final pass
 * @param method         solver
 * @param bvh            sub-patch BVH on
 * @param bvhSpeedUp     measured frame time without the BVH divided by the time with it, for the
 *                       same picture; 0 when not measured yet
 * @param prepMillis     time to re-split and refit (or build) the scene snapshot
 * @param tessellate     0: exact; {@code K ≥ 1}: rendered as a K×K triangle mesh per patch
 */
public record RenderStatus(int pass, int passCount, double millis, double mraysPerSecond, int spp, Method method,
                           boolean bvh, double bvhSpeedUp, double prepMillis, int tessellate) {
}
