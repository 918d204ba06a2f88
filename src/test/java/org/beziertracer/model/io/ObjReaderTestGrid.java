package org.beziertracer.model.io;

/** A two-segment bicubic Bézier surf, for the round-trip tests. */
final class ObjReaderTestGrid {
    private ObjReaderTestGrid() {}

    static final String GRID = grid();

    private static String grid() {
        StringBuilder sb = new StringBuilder();
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 7; i++) {
                sb.append("v ").append(i).append(' ').append(j).append(' ').append((i * j) % 3).append('\n');
            }
        }
        sb.append("cstype bezier\ndeg 3 3\nsurf 0 2 0 1");
        for (int k = 1; k <= 28; k++) {
            sb.append(' ').append(k);
        }
        return sb.append("\nparm u 0 1 2\nparm v 0 1\nend\n").toString();
    }
}
