package org.beziertracer.app;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Echo;

/**
 * The inspector panel's model: what it shows for the selection — for one handle its patch,
 * indices, coordinates and (for a rational patch) weight; for several, how many and their common
 * centroid — and the edits it makes: a typed coordinate moves the handle (or shifts the whole
 * selection so that its centroid lands there), a typed weight re-weights every copy of the handle;
 * each is one undoable edit, made off the UI thread. A refused value leaves its one-line reason in
 * {@link #message()} until the next value is typed, the selection changes or a model is opened.
 * Reading the state costs the size of the selection. UI thread only.
 */
public final class Inspector {

    /** An editable field. */
    public enum Field {
        X("x"), Y("y"), Z("z"), WEIGHT("weight");

        private final String label;

        Field(String label) { this.label = label; }

        public String label() { return label; }
    }

    /**
     * What the panel shows.
     *
     * @param handles how many handles are selected (coincident copies count once)
     * @param primary the first selected point (its patch and indices are shown for one handle)
     * @param copies  how many copies the first handle has (welded points)
     * @param xyz     the handle's coordinates, or the centroid of several
     * @param weight  the weight of the first point, or NaN when its patch is not rational (or several are selected)
     */
    public record State(int handles, PointRef primary, int copies, double[] xyz, double weight) {

        /** True when the weight row is shown. */
        public boolean hasWeight() { return !Double.isNaN(weight); }

        /** The value of {@code f}, as the field shows it. */
        public String text(Field f) {
            return format(f == Field.WEIGHT ? weight : xyz[f.ordinal()]);
        }
    }

    private final AppModel app;
    private String message;

    Inspector(AppModel app) {
        this.app = app;
    }

    /** The state of the current selection, or null when nothing is selected. */
    public State state() {
        Selection s = app.selection();
        Scene scene = app.document().scene();
        double[] sum = new double[3];
        int n = 0;
        for (List<PointRef> h : s.handles()) {
            PointRef r = h.get(0);
            if (r.in(scene)) {
                BezierPatch p = scene.patches().get(r.patch());
                for (int c = 0; c < 3; c++) {
                    sum[c] += p.get(r.i(), r.j(), c);
                }
                n++;
            }
        }
        if (n == 0) {
            return null;
        }
        PointRef primary = s.handles().get(0).get(0);
        double weight = n == 1 && primary.in(scene)
                ? PatchWeights.weight(scene.patches().get(primary.patch()), primary.i(), primary.j()) : Double.NaN;
        return new State(n, primary, s.handles().get(0).size(), new double[] {sum[0] / n, sum[1] / n, sum[2] / n},
                weight);
    }

    /**
     * The user typed {@code text} into field {@code f} and pressed Enter: applies it as one
     * undoable edit and returns null, or returns the one-line reason it cannot (nothing changes).
     */
    public String set(Field f, String text) {
        message = apply(f, text);
        return message;
    }

    /** Why the last typed value was refused, or null (none, or it was cleared since). */
    public String message() { return message; }

    /** Forgets the refusal: the selection it was about changed, or another model was opened. */
    void clearMessage() { message = null; }

    private String apply(Field f, String text) {
        State st = state();
        if (st == null) {
            return "select a control point first";
        }
        double v;
        try {
            v = Double.parseDouble(text.trim().replace(',', '.'));
        } catch (NumberFormatException e) {
            return f.label() + ": expected a number, found " + Echo.quote(text.trim());
        }
        if (!Double.isFinite(v) || (f == Field.WEIGHT && !(v > 0))) {
            return f.label() + (f == Field.WEIGHT ? " must be a positive number" : " must be a finite number")
                    + ", found " + Echo.quote(text.trim());
        }
        if (f == Field.WEIGHT) {
            return reweigh(st, v);
        }
        double[] d = new double[3];
        d[f.ordinal()] = v - st.xyz()[f.ordinal()];
        if (d[f.ordinal()] != 0) {
            app.selections().move("Set " + f.label(), app.selection(), d);
        }
        return null;
    }

    private String reweigh(State st, double w) {
        if (!st.hasWeight()) {
            return "this patch has no weights (it is not rational)";
        }
        List<PointRef> copies = app.selection().handles().get(0);
        app.editor().apply("Set weight", base -> new SceneEditor.Outcome(PatchWeights.withWeight(base, copies, w), null));
        return null;
    }

    /** A coordinate as the inspector shows it: up to nine significant digits, no exponent for everyday sizes. */
    static String format(double v) {
        if (Double.isNaN(v)) {
            return "";
        }
        if (v == 0) {
            return "0";
        }
        BigDecimal b = new BigDecimal(v).round(new MathContext(9)).stripTrailingZeros();
        return Math.abs(v) >= 1e-4 && Math.abs(v) < 1e9 ? b.toPlainString() : b.toString();
    }
}
