/**
 * The desktop app's windows: Swing + FlatLaf (the only package that imports them). Views and
 * Swing adapters only; the app itself — document, undo, selection, settings, view, rendering,
 * files — is {@link org.beziertracer.app.AppModel} in {@code org.beziertracer.app}.
 *
 * <h2>Shape</h2>
 * {@link org.beziertracer.ui.BezierTracerApp} bootstraps (properties, {@link org.beziertracer.ui.Theme},
 * the handler of uncaught errors, then the window on the event thread).
 * {@link org.beziertracer.ui.AppFrame} holds one class per panel —
 * {@link org.beziertracer.ui.RenderPanel}, {@link org.beziertracer.ui.ToolboxPanel},
 * {@link org.beziertracer.ui.StatusBar}, {@link org.beziertracer.ui.AppMenuBar} — and the dialogs.
 * Every command is an action in {@link org.beziertracer.ui.AppActions} (name, tooltip, shortcut),
 * shared by menus and toolbox, whose handler is one line into the app layer.
 *
 * <h2>Painting</h2>
 * The render panel draws the picture's pixels (render threads write them; the panel wraps the
 * same array in an image) and the app's {@link org.beziertracer.app.OverlaySnapshot} — a bounded
 * number of shapes prepared off the event thread — and calls nothing back. The picture is at device
 * pixels (the Graphics2D transform's scale, e.g. 2 under {@code GDK_SCALE=2}); the panel converts
 * mouse events to device pixels.
 */
package org.beziertracer.ui;
