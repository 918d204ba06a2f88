package org.beziertracer.model.io;

import java.util.List;

/**
 * The length and plane angle units of a STEP file: those of its first
 * {@code GLOBAL_UNIT_ASSIGNED_CONTEXT} (ISO 10303-41 §18): an {@code SI_UNIT} with its prefix
 * ({@code .MILLI.,.METRE.}), or a {@code CONVERSION_BASED_UNIT} ({@code 'INCH'}) whose
 * {@code LENGTH_MEASURE_WITH_UNIT} gives its size in another unit. Millimetres and radians when
 * the file names none.
 *
 * @param millimetres the length unit's size in millimetres
 * @param radians     the plane angle unit's size in radians
 */
record StepUnits(double millimetres, double radians) {

    static StepUnits of(StepFile file) {
        for (StepFile.Entity e : file.order) {
            StepFile.Part p = e.part("GLOBAL_UNIT_ASSIGNED_CONTEXT");
            if (p != null) {
                StepArgs a = new StepArgs(file, e, p).require(1, "units");
                double mm = 1, rad = 1;
                for (Object o : a.list(0, "units")) {
                    StepFile.Entity u = a.target(o, "a unit");
                    if (u.is("LENGTH_UNIT")) {
                        mm = size(file, u, 0) * 1000; // metres → millimetres
                    } else if (u.is("PLANE_ANGLE_UNIT")) {
                        rad = size(file, u, 0);
                    }
                }
                return new StepUnits(mm, rad);
            }
        }
        return new StepUnits(1, 1);
    }

    /** A unit's size in its SI base (metres, radians). */
    private static double size(StepFile file, StepFile.Entity u, int depth) {
        if (depth > 8) {
            throw file.source.error(u.line(), "#" + u.id() + ": units defined through more than 8 conversions (a cycle?)");
        }
        StepFile.Part si = u.part("SI_UNIT");
        if (si != null) {
            StepArgs a = new StepArgs(file, u, si).require(2, "prefix, name");
            double f = a.raw(0) == StepFile.UNSET ? 1 : prefix(a, a.enumeration(0, "prefix"));
            String name = a.enumeration(1, "name");
            if (!name.equals("METRE") && !name.equals("RADIAN")) {
                throw a.error("expected the unit METRE or RADIAN, found " + Echo.quote("." + name + "."));
            }
            return f;
        }
        StepFile.Part c = u.part("CONVERSION_BASED_UNIT");
        if (c != null) {
            StepArgs a = new StepArgs(file, u, c).require(2, "name, conversion_factor");
            StepFile.Entity m = a.ref(1, "conversion_factor");
            StepFile.Part mp = m.complex() ? m.part("MEASURE_WITH_UNIT") : m.parts().get(0);
            if (mp == null) {
                throw a.error("its conversion factor #" + m.id() + " is not a measure with unit");
            }
            StepArgs ma = new StepArgs(file, m, mp).require(2, "value_component, unit_component");
            double value = ma.real(0, "value_component");
            double base = size(file, ma.ref(1, "unit_component"), depth + 1);
            double s = value * base;
            if (!(s > 0) || !Double.isFinite(s)) {
                throw ma.error("a unit of size " + s);
            }
            return s;
        }
        throw file.source.error(u.line(), "#" + u.id() + " (" + u.type() + "): expected an SI_UNIT or a CONVERSION_BASED_UNIT");
    }

    private static double prefix(StepArgs a, String p) {
        List<String> names = List.of("EXA", "PETA", "TERA", "GIGA", "MEGA", "KILO", "HECTO", "DECA", "DECI", "CENTI",
                "MILLI", "MICRO", "NANO", "PICO", "FEMTO", "ATTO");
        double[] factors = {1e18, 1e15, 1e12, 1e9, 1e6, 1e3, 1e2, 1e1, 1e-1, 1e-2, 1e-3, 1e-6, 1e-9, 1e-12, 1e-15, 1e-18};
        int k = names.indexOf(p);
        if (k < 0) {
            throw a.error("expected an SI prefix such as .MILLI., found " + Echo.quote("." + p + "."));
        }
        return factors[k];
    }
}
