package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * The OBJ reader's in-place paths (plain {@code v} and {@code surf} statements parsed from the
 * line's characters, {@link TextSource#nextLine()}) against its string path: seeded random files
 * in the many spellings writers use — signs, exponents, tabs, comments, continuation lines, CR LF,
 * lines crossing the decoder's buffer, slash and negative indices, weights — and with errors
 * planted, read both ways: the same patches to the bit, or the same one-line error.
 */
class ObjInPlaceTest {

    /** The model or the error message, both ways; asserts they agree and returns the in-place counts. */
    private static int[] bothWays(String text) throws IOException {
        int[] on = new int[3], off = new int[3];
        String a = outcome(text, true, on), b = outcome(text, false, off);
        assertEquals(b, a, () -> "in place and string path differ for:\n" + text);
        assertEquals(0, off[0] + off[1] + off[2], "the string path took no in-place step");
        return on;
    }

    private static String outcome(String text, boolean inPlace, int[] counts) throws IOException {
        TextSource source = new TextSource(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), "r.obj");
        try {
            ObjReader.Model m = ObjReader.readModel(source, inPlace, counts);
            StringBuilder sb = new StringBuilder();
            m.patches().forEach(p -> sb.append(p.degreeU()).append('x').append(p.degreeV())
                    .append(java.util.Arrays.toString(p.copyNet())).append(java.util.Arrays.toString(p.weights()))
                    .append(p.domain()).append('\n'));
            if (m.mesh() != null) {
                sb.append(m.mesh()).append(java.util.Arrays.toString(m.mesh().positions()))
                        .append(java.util.Arrays.toString(m.mesh().triangles()))
                        .append(java.util.Arrays.toString(m.mesh().normals()))
                        .append(java.util.Arrays.toString(m.mesh().uvs()));
            }
            return sb.append(m.notes()).toString();
        } catch (ModelFormatException e) {
            return "error: " + e.getMessage();
        }
    }

    @Test
    void randomFilesReadTheSameBothWays() throws IOException {
        Random rnd = new Random(20261206);
        int vertices = 0, surfs = 0, errors = 0;
        for (int round = 0; round < 400; round++) {
            String text = randomFile(rnd, round % 3 == 0);
            int[] counts = bothWays(text);
            vertices += counts[0];
            surfs += counts[1];
            errors += outcome(text, true, new int[3]).startsWith("error") ? 1 : 0;
        }
        // both paths were really exercised: most statements in place, and errors among the files
        assertTrue(vertices > 5_000, "in-place vertices: " + vertices);
        assertTrue(surfs > 300, "in-place surfs: " + surfs);
        assertTrue(errors > 40 && errors < 360, "files with an error: " + errors);
    }

    @Test
    void randomMeshesReadTheSameBothWays() throws IOException {
        Random rnd = new Random(35_006);
        int faces = 0, errors = 0;
        for (int round = 0; round < 300; round++) {
            String text = randomMesh(rnd, round % 3 == 0);
            faces += bothWays(text)[2];
            errors += outcome(text, true, new int[3]).startsWith("error") ? 1 : 0;
        }
        assertTrue(faces > 3_000, "in-place faces: " + faces);
        assertTrue(errors > 30 && errors < 250, "files with an error: " + errors);
    }

    /**
     * Vertices, texture vertices and normals, then faces of 3 to 6 corners in every reference form
     * (plain, negative, {@code v/vt}, {@code v//vn}, {@code v/vt/vn}), plain corners repeated so
     * that mesh vertices are shared; with {@code planted}, one corner is out of range or malformed.
     */
    private static String randomMesh(Random rnd, boolean planted) {
        StringBuilder sb = new StringBuilder();
        int count = 4 + rnd.nextInt(20);
        for (int k = 0; k < count; k++) {
            sb.append("v ").append(number(rnd)).append(' ').append(number(rnd)).append(' ').append(number(rnd))
                    .append('\n');
            if (rnd.nextBoolean()) {
                sb.append("vt ").append(rnd.nextDouble()).append(' ').append(rnd.nextDouble()).append('\n');
                sb.append("vn 0 0 ").append(1 + rnd.nextInt(3)).append('\n');
            }
        }
        boolean fancy = rnd.nextInt(3) == 0; // v/vt/vn forms in a third of the files
        int faceCount = 5 + rnd.nextInt(30), plantAt = planted ? rnd.nextInt(faceCount) : -1;
        for (int f = 0; f < faceCount; f++) {
            sb.append(blank(rnd)).append('f');
            int corners = 3 + rnd.nextInt(4);
            for (int c = 0; c < corners; c++) {
                int v = 1 + rnd.nextInt(count);
                String ref = switch (fancy ? rnd.nextInt(8) : 3 + rnd.nextInt(5)) {
                    case 0 -> v + "/1";
                    case 1 -> v + "//1";
                    case 2 -> v + "/1/1";
                    case 3 -> Integer.toString(v - count - 1);
                    case 4 -> "+" + v;
                    default -> Integer.toString(v);
                };
                sb.append(rnd.nextInt(4) == 0 ? "\t" : " ").append(ref);
            }
            if (f == plantAt) {
                sb.append(' ').append(switch (rnd.nextInt(4)) {
                    case 0 -> Integer.toString(count + 1);
                    case 1 -> "0";
                    case 2 -> "1//";
                    default -> "x";
                });
            }
            sb.append(blank(rnd)).append(rnd.nextInt(10) == 0 ? " # c" : "").append('\n');
        }
        return sb.toString();
    }

    @Test
    void aMeshAsExportersWriteItTakesTheInPlacePathForEveryStatement() throws IOException {
        StringBuilder sb = new StringBuilder("o quad\n");
        for (int k = 0; k < 40; k++) {
            sb.append("v ").append(k).append(" 0 0\nv ").append(k).append(" 1 0\nv ").append(k).append(" 1 1\n")
                    .append("vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n")
                    .append("f -3/-3/-1 -2/-2/-1 -1/-1/-1\nf ").append(3 * k + 1).append("//").append(k + 1).append(' ')
                    .append(3 * k + 2).append("//").append(k + 1).append(' ').append(3 * k + 3).append("//")
                    .append(k + 1).append('\n');
        }
        int[] counts = bothWays(sb.toString());
        assertEquals(120, counts[0]);
        assertEquals(40 * (2 + 3 + 1), counts[2], "faces, texture vertices and normals in place");
    }

    @Test
    void aPlainModelTakesTheInPlacePathForEveryVertexAndSurf() throws IOException {
        StringBuilder sb = new StringBuilder("cstype bezier\ndeg 1 1\n");
        for (int k = 0; k < 50; k++) {
            sb.append("v ").append(k).append(" 0 0\nv ").append(k).append(" 1 0\nv ").append(k).append(" 0 1\n")
                    .append("v ").append(k).append(" 1 1\nsurf 0 1 0 1 -4 -3 -2 -1\nend\n");
        }
        int[] counts = bothWays(sb.toString());
        assertEquals(200, counts[0]);
        assertEquals(50, counts[1]);
    }

    /** A file of random vertices and surfs; with {@code planted}, one token somewhere is wrong. */
    private static String randomFile(Random rnd, boolean planted) {
        StringBuilder sb = new StringBuilder();
        String eol = rnd.nextInt(4) == 0 ? "\r\n" : "\n";
        sb.append("cstype ").append(rnd.nextInt(3) == 0 ? "rat " : "").append("bezier").append(eol);
        int du = 1 + rnd.nextInt(3), dv = 1 + rnd.nextInt(3);
        sb.append("deg ").append(du).append(' ').append(dv).append(eol);
        int defined = 0;
        int surfCount = 1 + rnd.nextInt(4);
        int plantAt = planted ? rnd.nextInt(surfCount) : -1;
        boolean slashes = rnd.nextBoolean(); // v/vt forms (the string path) in half the files
        for (int s = 0; s < surfCount; s++) {
            int points = (du + 1) * (dv + 1);
            for (int k = 0; k < points + rnd.nextInt(3); k++) {
                sb.append(blank(rnd)).append('v').append(rnd.nextBoolean() ? " " : "\t");
                for (int c = 0; c < 3; c++) {
                    sb.append(number(rnd)).append(c < 2 ? blank(rnd) + " " : "");
                }
                if (rnd.nextInt(8) == 0) {
                    sb.append(' ').append(1 + rnd.nextInt(3)); // a weight: the string path
                }
                if (rnd.nextInt(10) == 0) {
                    sb.append(" # ").append("x".repeat(rnd.nextInt(3) == 0 ? 9_000 : 5)); // across the buffer
                }
                sb.append(blank(rnd)).append(eol);
                defined++;
            }
            sb.append(blank(rnd)).append("surf ").append(range(rnd)).append(' ').append(range(rnd));
            for (int k = 0; k < points; k++) {
                int index = 1 + rnd.nextInt(defined);
                sb.append(rnd.nextInt(40) == 0 ? " \\" + eol : " ").append(reference(rnd, index, defined, slashes));
            }
            if (s == plantAt) {
                sb.append(' ').append(plant(rnd, defined));
            }
            sb.append(blank(rnd)).append(eol).append("end").append(eol);
        }
        return sb.toString();
    }

    private static String blank(Random rnd) {
        return switch (rnd.nextInt(6)) {
            case 0 -> " ";
            case 1 -> "\t";
            default -> "";
        };
    }

    private static String number(Random rnd) {
        double v = (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(7) - 3);
        return switch (rnd.nextInt(6)) {
            case 0 -> Double.toString(v);
            case 1 -> String.format(java.util.Locale.ROOT, "%.4e", v);
            case 2 -> "+" + String.format(java.util.Locale.ROOT, "%.3f", Math.abs(v));
            case 3 -> Integer.toString((int) (v * 10));
            case 4 -> String.format(java.util.Locale.ROOT, "%.6f", v).replace("0.", ".");
            default -> String.format(java.util.Locale.ROOT, "%.17g", v);
        };
    }

    private static String range(Random rnd) {
        return switch (rnd.nextInt(5)) {
            case 0 -> "0.0 1.0";
            case 1 -> "0 0.5";
            case 2 -> "+0 1e0";
            default -> "0 1";
        };
    }

    private static String reference(Random rnd, int index, int defined, boolean slashes) {
        return switch (rnd.nextInt(slashes ? 10 : 6) + (slashes ? 0 : 4)) {
            case 0, 6 -> Integer.toString(index - defined - 1); // negative: counts back
            case 1 -> index + "/" + index;
            case 2 -> index + "//1";
            case 3, 4 -> "+" + index;
            case 5 -> "00" + index;
            default -> Integer.toString(index);
        };
    }

    /** A token that makes the surf wrong: an index out of range, not a number, a count off by one. */
    private static String plant(Random rnd, int defined) {
        return switch (rnd.nextInt(5)) {
            case 0 -> Integer.toString(defined + 1);
            case 1 -> "-" + (defined + 1);
            case 2 -> "x1";
            case 3 -> "99999999999999999999";
            default -> "1";
        };
    }
}
