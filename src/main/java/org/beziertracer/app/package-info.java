/**
 * The app without its windows: everything the desktop app does that is not drawing or Swing.
 * It sits between {@code render} and {@code ui}, may use every layer below it, and never imports
 * AWT, Swing, FlatLaf, {@code ui} or {@code cli} ({@code ArchitectureTest} checks), so it is
 * tested without a display.
 *
 * <h2>Shape</h2>
 * {@link org.beziertracer.app.AppModel} owns the parts and wires them:
 * <ul>
 *   <li>state — {@link org.beziertracer.app.Document} (scene, {@link org.beziertracer.app.EditHistory
 *       undo history}, dirty flag, file), {@link org.beziertracer.app.SettingsModel} (typed
 *       {@link org.beziertracer.app.Settings}: {@link org.beziertracer.app.Toggle}s,
 *       {@link org.beziertracer.app.Level}s, method, light), {@link org.beziertracer.app.ViewModel}
 *       ({@link org.beziertracer.app.OrbitView}, picture size, {@link org.beziertracer.app.Picture}),
 *       {@link org.beziertracer.app.Selection};</li>
 *   <li>commands — {@link org.beziertracer.app.FileCommands}, {@link org.beziertracer.app.EditCommands},
 *       {@link org.beziertracer.app.PointerTool} (mouse gestures);</li>
 *   <li>snapshots for the view — {@link org.beziertracer.app.OverlaySnapshot} (prepared, bounded
 *       overlay), {@link org.beziertracer.app.StatusModel}, the picture's pixels;</li>
 *   <li>work off the UI thread — {@link org.beziertracer.app.RayTraceEngine} (render snapshots,
 *       progressive renders), {@link org.beziertracer.app.OverlayBuilder} (projection and thinning),
 *       the scene editor and the loader ({@link org.beziertracer.app.BackgroundTasks}).</li>
 * </ul>
 *
 * <h2>Threads</h2>
 * All mutable state belongs to one UI thread ({@link org.beziertracer.app.AppThreads#ui()}, the
 * Swing event thread in the app, the test's own thread in unit tests). Nothing there grows with
 * the model: files are read and written, edited scenes built, control points projected and
 * render snapshots prepared on worker threads, and their immutable results come back through the
 * UI executor. Late results carry the document's epoch and are dropped when it moved on.
 */
package org.beziertracer.app;
