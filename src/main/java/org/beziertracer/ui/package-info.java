/**
 * The desktop app: Swing + FlatLaf (the only package that imports them).
 *
 * <h2>Shape</h2>
 * {@link org.beziertracer.ui.BezierTracerApp} bootstraps (properties, {@link org.beziertracer.ui.Theme},
 * then the window on the event thread). {@link org.beziertracer.ui.AppFrame} holds one class per
 * panel — {@link org.beziertracer.ui.RenderPanel}, {@link org.beziertracer.ui.ToolboxPanel},
 * {@link org.beziertracer.ui.StatusBar}, {@link org.beziertracer.ui.AppMenuBar} — whose handlers
 * are one-liners into {@link org.beziertracer.ui.AppController}, which owns the document
 * ({@link org.beziertracer.ui.EditHistory}: scene snapshots, undo, dirty flag), the
 * {@link org.beziertracer.ui.OrbitView view}, the {@link org.beziertracer.ui.ToolSettings toolbox
 * state} and the {@link org.beziertracer.ui.PictureEngine render engine}. Every command is an
 * action in {@link org.beziertracer.ui.AppActions} (name, tooltip, shortcut), shared by menus and
 * toolbox.
 *
 * <h2>Threads</h2>
 * The event thread never renders: it builds an immutable {@link org.beziertracer.ui.RenderRequest}
 * and hands it to {@link org.beziertracer.ui.RayTraceEngine}, which cancels the render in progress
 * at once, coalesces pending requests in one slot, prepares the scene snapshot on its own thread
 * ({@code SceneIntersector.withPatch} for a dragged point) and starts a progressive
 * {@code RenderSession}. Render threads never touch Swing: tiles are copied row by row into the
 * {@link org.beziertracer.ui.FrameBuffer}'s {@code int[]} raster and one pending flag coalesces
 * repaints; status reports reach the event thread through one pending slot.
 *
 * <h2>Pixels</h2>
 * The picture is rendered at device pixels (the Graphics2D transform's scale, e.g. 2 under
 * {@code GDK_SCALE=2}); the controller works in device pixels, the panel converts mouse events.
 * Projection ({@link org.beziertracer.ui.ScreenProjector}) follows the renderer's camera
 * convention exactly, so picked points sit on the rendered surface.
 */
package org.beziertracer.ui;
