package org.beziertracer.cli;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimRegion;

/**
 * The free-form lines of {@code info}: how many patches are rational and trimmed, and each
 * free-form surface the model was read as (basis, rational or not, degrees, control points,
 * parameter range, trim loops) with the Bézier pieces it became.
 * <pre>
 * rational patches: 8
 * trimmed patches: 0
 * surfaces: 1
 *   surface 1: rational bspline, degree 2x2, 9x5 control points, u[0,4] v[0,2], untrimmed -&gt; 8 Bézier pieces (patches 1-8)
 * </pre>
 */
final class SurfaceSummary {
    private SurfaceSummary() {}

    /** Surfaces listed one per line; the rest are counted. */
    static final int LISTED = 20;

    static List<String> lines(Scene scene) {
        List<BezierPatch> patches = scene.patches();
        int rational = 0, trimmed = 0;
        Map<FreeFormSurface, int[]> pieces = new IdentityHashMap<>(); // first patch, last patch, count
        List<FreeFormSurface> order = new ArrayList<>();
        for (int k = 0; k < patches.size(); k++) {
            BezierPatch p = patches.get(k);
            rational += p.isRational() ? 1 : 0;
            trimmed += p.trim() != null ? 1 : 0;
            if (p.origin() != null) {
                int index = k;
                int[] range = pieces.computeIfAbsent(p.origin().surface(), s -> {
                    order.add(s);
                    return new int[] {index, index, 0};
                });
                range[1] = k;
                range[2]++;
            }
        }
        List<String> out = new ArrayList<>();
        out.add("rational patches: " + rational);
        out.add("trimmed patches: " + trimmed);
        out.add("surfaces: " + order.size());
        for (int s = 0; s < Math.min(order.size(), LISTED); s++) {
            FreeFormSurface f = order.get(s);
            int[] r = pieces.get(f);
            double[] range = f.range();
            out.add(String.format(Locale.ROOT, "  surface %d: %s%s, degree %dx%d, %dx%d control points, u[%s,%s] v[%s,%s], %s"
                            + " -> %d Bézier piece%s (patches %d-%d)", s + 1, f.rational() ? "rational " : "",
                    f.basis().objName(), f.degreeU(), f.degreeV(), f.countU(), f.countV(), num(range[0]), num(range[1]),
                    num(range[2]), num(range[3]), trim(f.trim()), r[2], r[2] == 1 ? "" : "s", r[0] + 1, r[1] + 1));
        }
        if (order.size() > LISTED) {
            out.add("  … and " + (order.size() - LISTED) + " more");
        }
        return out;
    }

    private static String trim(TrimRegion t) {
        if (t == null) {
            return "untrimmed";
        }
        return "trimmed by " + loops(t.outer(), "outer loop") + " and " + loops(t.holes(), "hole");
    }

    private static String loops(List<TrimLoop> loops, String what) {
        StringBuilder sb = new StringBuilder().append(loops.size()).append(' ').append(what)
                .append(loops.size() == 1 ? "" : "s");
        if (!loops.isEmpty()) {
            sb.append(" (");
            for (int k = 0; k < loops.size(); k++) {
                int curves = loops.get(k).pieces().size();
                sb.append(k > 0 ? ", " : "").append(curves).append(curves == 1 ? " curve" : " curves");
            }
            sb.append(')');
        }
        return sb.toString();
    }

    private static String num(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
