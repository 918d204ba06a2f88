package org.beziertracer.app;

/**
 * The modifier keys held when the mouse was pressed.
 *
 * @param shift adds to the selection (a handle, or a rubber band on empty space)
 * @param ctrl  toggles in the selection (a handle, or a rubber band on empty space)
 * @param alt   takes one copy of a welded point instead of all of them
 */
public record Modifiers(boolean shift, boolean ctrl, boolean alt) {

    public static final Modifiers NONE = new Modifiers(false, false, false);
    public static final Modifiers SHIFT = new Modifiers(true, false, false);
    public static final Modifiers CTRL = new Modifiers(false, true, false);
    public static final Modifiers ALT = new Modifiers(false, false, true);

    /** True when Shift or Ctrl is held: a press on empty space draws a rubber band instead of turning the view. */
    public boolean selecting() { return shift || ctrl; }
}
