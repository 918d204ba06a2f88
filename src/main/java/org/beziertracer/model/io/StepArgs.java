package org.beziertracer.model.io;

import java.util.List;

/**
 * The parameters of one record of a STEP entity instance (a simple instance, or one part of a
 * complex one), read by position with their attribute names: a missing parameter, a value of the
 * wrong kind or a reference to the wrong entity is one line naming the file, the line and the
 * entity ({@code part.stp:41: #12 (B_SPLINE_SURFACE_WITH_KNOTS): expected a number for u_degree,
 * found .T.}). Typed parameters ({@code LENGTH_MEASURE(2.)}) are read as their value.
 */
final class StepArgs {

    final StepFile file;
    final StepFile.Entity entity;
    private final List<Object> params;

    StepArgs(StepFile file, StepFile.Entity entity, StepFile.Part part) {
        this.file = file;
        this.entity = entity;
        this.params = part.params();
    }

    /** The arguments of a simple instance, or of its part {@code type} in a complex one. */
    static StepArgs of(StepFile file, StepFile.Entity e, String type) {
        StepFile.Part p = e.complex() ? e.part(type) : e.parts().get(0);
        if (p == null) {
            throw file.source.error(e.line(), "#" + e.id() + " (" + e.type() + "): expected a " + type + " record");
        }
        return new StepArgs(file, e, p);
    }

    int size() { return params.size(); }

    ModelFormatException error(String detail) {
        return file.source.error(entity.line(), "#" + entity.id() + " (" + entity.type() + "): " + detail);
    }

    /** Requires at least {@code count} parameters, named {@code names} in messages. */
    StepArgs require(int count, String names) {
        if (params.size() < count) {
            throw error("expected " + count + " parameters (" + names + "), found " + params.size());
        }
        return this;
    }

    Object raw(int k) {
        if (k >= params.size()) {
            throw error("expected a parameter " + (k + 1) + ", found only " + params.size());
        }
        return params.get(k);
    }

    static Object untyped(Object v) {
        while (v instanceof StepFile.Typed t) {
            v = t.value();
        }
        return v;
    }

    static String show(Object v) {
        if (v instanceof StepFile.Ref r) {
            return "#" + r.id();
        } else if (v instanceof StepFile.Enum e) {
            return Echo.quote("." + e.name() + ".");
        } else if (v instanceof String s) {
            return Echo.quote("'" + s + "'");
        } else if (v instanceof List<?> l) {
            return "a list of " + l.size();
        } else if (v instanceof StepFile.Typed t) {
            return Echo.quote(t.type() + "(…)");
        }
        return String.valueOf(v);
    }

    double real(int k, String name) {
        return real(raw(k), name);
    }

    /** A number (an integer is a real too). */
    double real(Object v, String name) {
        Object u = untyped(v);
        if (u instanceof Double d) {
            return d;
        } else if (u instanceof Long l) {
            return l;
        }
        throw error("expected a number for " + name + ", found " + show(v));
    }

    int integer(int k, String name) {
        Object u = untyped(raw(k));
        if (u instanceof Long l && l >= Integer.MIN_VALUE && l <= Integer.MAX_VALUE) {
            return (int) (long) l;
        }
        throw error("expected an integer for " + name + ", found " + show(raw(k)));
    }

    /** {@code .T.} or {@code .F.} ({@code .U.}, unknown, reads as {@code ifUnknown}). */
    boolean bool(int k, String name, boolean ifUnknown) {
        Object u = untyped(raw(k));
        if (u instanceof StepFile.Enum e) {
            switch (e.name()) {
                case "T" -> {
                    return true;
                }
                case "F" -> {
                    return false;
                }
                case "U" -> {
                    return ifUnknown;
                }
                default -> { }
            }
        }
        throw error("expected .T. or .F. for " + name + ", found " + show(raw(k)));
    }

    String enumeration(int k, String name) {
        Object u = untyped(raw(k));
        if (u instanceof StepFile.Enum e) {
            return e.name();
        }
        throw error("expected an enumeration .NAME. for " + name + ", found " + show(raw(k)));
    }

    List<?> list(int k, String name) {
        return list(raw(k), name);
    }

    List<?> list(Object v, String name) {
        if (v instanceof List<?> l) {
            return l;
        }
        throw error("expected a list (…) for " + name + ", found " + show(v));
    }

    /** The numbers of a list, e.g. a point's coordinates or the knots. */
    double[] reals(Object v, String name) {
        List<?> l = list(v, name);
        double[] out = new double[l.size()];
        for (int k = 0; k < out.length; k++) {
            out[k] = real(l.get(k), name);
        }
        return out;
    }

    int[] integers(Object v, String name) {
        List<?> l = list(v, name);
        int[] out = new int[l.size()];
        for (int k = 0; k < out.length; k++) {
            Object u = untyped(l.get(k));
            if (!(u instanceof Long n) || n < 0 || n > Integer.MAX_VALUE) {
                throw error("expected non-negative integers for " + name + ", found " + show(l.get(k)));
            }
            out[k] = (int) (long) (Long) u;
        }
        return out;
    }

    StepFile.Entity ref(int k, String name, String... types) {
        return target(raw(k), name, types);
    }

    /** The entity {@code v} refers to, required to be (or to have a part) of one of {@code types} (any when none). */
    StepFile.Entity target(Object v, String name, String... types) {
        if (!(v instanceof StepFile.Ref r)) {
            throw error("expected a reference #N for " + name + ", found " + show(v));
        }
        StepFile.Entity e = file.resolve(r, entity);
        if (types.length == 0) {
            return e;
        }
        for (String t : types) {
            if (e.is(t)) {
                return e;
            }
        }
        throw error(name + " refers to #" + e.id() + ", a " + e.type() + ", expected " + String.join(" or ", types));
    }
}
