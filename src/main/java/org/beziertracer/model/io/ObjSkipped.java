package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.List;

/**
 * The OBJ statements a read passes over without drawing them — 3-D curves ({@code curv}), special
 * curves and points ({@code scrv}, {@code sp}), connectivity ({@code con}), points and lines
 * ({@code p}, {@code l}) — counted by keyword, for one note line instead of a failure:
 * {@code "cad.obj: skipped 12 curv, 4 con (3-D curves and connectivity hints are not drawn)"}.
 * One per read (a {@code call}ed file adds to its caller's); not thread-safe.
 */
final class ObjSkipped {

    /** Each kind counted: its keyword and what it is, in the order the note lists them. */
    private static final String[][] KINDS = {{"curv", "3-D curves"}, {"scrv", "special curves"},
            {"sp", "special points"}, {"con", "connectivity hints"}, {"p", "points"}, {"l", "lines"}};

    private final long[] counts = new long[KINDS.length];

    /** True when {@code keyword} is a statement counted here. */
    static boolean counts(String keyword) {
        return kind(keyword) >= 0;
    }

    /** Counts one {@code keyword} statement (one of {@link #counts}). */
    void add(String keyword) {
        counts[kind(keyword)]++;
    }

    /** The note for {@code file}, or null when nothing was skipped. */
    String note(String file) {
        List<String> counted = new ArrayList<>(), what = new ArrayList<>();
        for (int k = 0; k < KINDS.length; k++) {
            if (counts[k] > 0) {
                counted.add(counts[k] + " " + KINDS[k][0]);
                what.add(KINDS[k][1]);
            }
        }
        if (counted.isEmpty()) {
            return null;
        }
        String kinds = what.size() == 1 ? what.get(0)
                : String.join(", ", what.subList(0, what.size() - 1)) + " and " + what.get(what.size() - 1);
        return file + ": skipped " + String.join(", ", counted) + " (" + kinds + " are not drawn)";
    }

    private static int kind(String keyword) {
        for (int k = 0; k < KINDS.length; k++) {
            if (KINDS[k][0].equals(keyword)) {
                return k;
            }
        }
        return -1;
    }
}
