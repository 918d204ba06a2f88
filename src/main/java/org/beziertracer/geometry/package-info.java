/**
 * The stateless Bézier kernel on flat arrays: de Casteljau evaluation, exact first
 * derivatives, splitting, restriction and sub-patch extraction ({@link
 * org.beziertracer.geometry.DeCasteljau}); unit normals with a limit normal at degenerate points
 * ({@link org.beziertracer.geometry.PatchNormals}); control-point bounds and flatness ({@link
 * org.beziertracer.geometry.NetMeasures}); degree elevation; uniform tessellation for export.
 *
 * <p>Net layout everywhere: point {@code k = j*(n+1) + i} holds {@code P_ij}, u fastest,
 * {@code dim} coordinates per point (3 for patches, 2 for nets projected into ray space, 1 for
 * distance nets). The hot methods take explicit offsets and a caller-owned scratch array of
 * {@link org.beziertracer.geometry.DeCasteljau#SCRATCH_LENGTH} doubles and never allocate.
 * {@link org.beziertracer.geometry.Patches} offers allocating {@code BezierPatch}/{@code Vec3}
 * conveniences for set-up code and tests.
 *
 * <p>May import {@code math} and {@code model} only.
 */
package org.beziertracer.geometry;
