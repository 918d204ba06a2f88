package org.beziertracer.app;

import org.beziertracer.math.Aabb;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Scene;

/**
 * The view of the model: the {@link OrbitView}, the picture's size in device pixels and the device
 * scale (2 under {@code GDK_SCALE=2}), and the {@link Picture} the renderer paints into. Mouse
 * coordinates everywhere are device pixels of the picture. UI thread only.
 */
public final class ViewModel {

    /** Zoom factor per wheel click. */
    public static final double ZOOM_PER_CLICK = 1.1;
    /** Picture size assumed before the view has been laid out. */
    static final int DEFAULT_WIDTH = 800, DEFAULT_HEIGHT = 600;

    private final Runnable onMoved;
    private final Runnable onResized;
    private volatile Runnable repaint = () -> {};
    private OrbitView view;
    private Picture picture;
    private double scale = 1;

    ViewModel(OrbitView initial, Runnable onMoved, Runnable onResized) {
        this.view = initial;
        this.onMoved = onMoved;
        this.onResized = onResized;
    }

    /**
     * The home view of a scene whose control points lie in {@code bounds} (measuring them reads
     * every point: do it off the UI thread): along the scene's own camera when it has one, else
     * the default framing.
     */
    public static OrbitView home(Scene s, Aabb bounds, double fovDegrees) {
        return s.camera().map(c -> OrbitView.fromCamera(c, bounds)).orElseGet(() -> OrbitView.fit(bounds, fovDegrees))
                .withFov(fovDegrees);
    }

    public OrbitView view() { return view; }

    /** Replaces the view and tells the owner (overlay and picture follow). */
    public void set(OrbitView v) {
        view = v;
        onMoved.run();
    }

    /** Replaces the view without telling the owner (it follows up itself). */
    void replace(OrbitView v) {
        view = v;
    }

    /**
     * Dragging empty space from {@code (x0, y0)} to {@code (x1, y1)} (device pixels of the picture)
     * turns the model with the picture's {@link Arcball}: the centre to the rim, half the picture's
     * smaller side, is 180°.
     */
    public void turn(double x0, double y0, double x1, double y1) {
        set(view.turned(new Arcball(width(), height()).drag(x0, y0, x1, y1)));
    }

    /** A drag by {@code (dx, dy)} device pixels from the middle of the picture ({@link #turn}). */
    public void rotate(double dx, double dy) {
        double cx = width() / 2.0, cy = height() / 2.0;
        turn(cx, cy, cx + dx, cy + dy);
    }

    /** Wheel: positive {@code clicks} move away from the model. */
    public void zoom(double clicks) {
        set(view.zoomed(Math.pow(ZOOM_PER_CLICK, clicks)));
    }

    /** Device pixels per user-space pixel. */
    public double scale() { return scale; }

    /** The picture, or null before the first layout. */
    public Picture picture() { return picture; }

    public int width() { return picture == null ? DEFAULT_WIDTH : picture.width(); }

    public int height() { return picture == null ? DEFAULT_HEIGHT : picture.height(); }

    /** The camera for the current picture. */
    public CameraSpec camera() {
        return view.camera((double) width() / height());
    }

    /** The projection of the current view onto the picture. */
    public ScreenProjector projector() {
        return new ScreenProjector(camera(), width(), height());
    }

    /** Where the picture asks for repaints (thread-safe; the view's {@code repaint}). */
    public void setRepaint(Runnable r) { repaint = r; }

    /**
     * The view's size in device pixels, or its device scale, changed (or the first layout): a new
     * picture when the size differs, then a render.
     */
    public void resize(int width, int height, double deviceScale) {
        scale = deviceScale;
        if (picture != null && picture.width() == width && picture.height() == height) {
            return;
        }
        picture = new Picture(width, height, () -> repaint.run());
        onResized.run();
    }

    /** Asks the view to repaint (hover, overlay). */
    void repaint() { repaint.run(); }
}
