package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

/**
 * The in-place parse of IGES fields (reals by FastDoubleParser, whole numbers digit by digit)
 * gives the bits {@link Double#parseDouble} and {@link Integer#parseInt} give the same text, on
 * seeded random fields in every form a file writes (signs, blanks, exponents with E or Fortran's
 * D, leading or trailing points); and a bad field is still one line naming it.
 */
class IgesParamsTest {

    private static IgesParams parse(String record) {
        return IgesParams.parse(record, ',', ';', TextSource.of("", "part.igs"), 7, "entity 128");
    }

    private static String randomReal(Random rnd) {
        double v = switch (rnd.nextInt(4)) {
            case 0 -> rnd.nextDouble();
            case 1 -> (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(40) - 20);
            case 2 -> rnd.nextInt(2000) - 1000;
            default -> Double.longBitsToDouble(rnd.nextLong() & 0x3fffffffffffffffL) % 1e12;
        };
        String t = switch (rnd.nextInt(6)) {
            case 0 -> Double.toString(v);
            case 1 -> String.format(java.util.Locale.ROOT, "%.17E", v);
            case 2 -> String.format(java.util.Locale.ROOT, "%.9E", v).replace('E', 'D');
            case 3 -> String.format(java.util.Locale.ROOT, "%.6f", v);
            case 4 -> (v < 0 ? "-" : "+") + Math.abs((long) v) + ".";
            default -> Double.toString(v).replace("0.", ".");
        };
        return (rnd.nextBoolean() ? " " : "") + t + (rnd.nextBoolean() ? "  " : "");
    }

    @Test
    void realsAndWholeNumbersParsedInPlaceHaveTheBitsOfTheJdkParse() {
        Random rnd = new Random(53);
        for (int trial = 0; trial < 20_000; trial++) {
            String real = randomReal(rnd);
            int whole = rnd.nextInt(3) == 0 ? rnd.nextInt() : rnd.nextInt(2000) - 1000;
            String wholeText = (rnd.nextBoolean() && whole >= 0 ? "+" : "") + whole;
            IgesParams p = parse("128," + real + "," + wholeText + ",,;");
            double expected = Double.parseDouble(real.trim().replace('D', 'E'));
            assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(p.real(1)), "field " + real);
            assertEquals(whole, p.integer(2), "field " + wholeText);
            assertEquals(0, p.integer(3), "an empty field");
            assertEquals(-1.5, p.real(3, -1.5), "an empty field's default");
        }
    }

    @Test
    void aBadFieldIsStillOneLineNamingIt() {
        assertEquals("part.igs:7: entity 128: field 2: expected a number, found \"1.2.3\"",
                UserMessages.of(ModelFormatException.class, () -> parse("128,1.2.3;").real(1)));
        assertEquals("part.igs:7: entity 128: field 2: expected a whole number, found \"12x\"",
                UserMessages.of(ModelFormatException.class, () -> parse("128,12x;").integer(1)));
        assertEquals("part.igs:7: entity 128: field 2: expected a finite number, found \"1e999\"",
                UserMessages.of(ModelFormatException.class, () -> parse("128,1e999;").real(1)));
        assertTrue(UserMessages.of(ModelFormatException.class, () -> parse("128,3HABC;").real(1))
                .endsWith("field 2: expected a number, found the string \"ABC\""));
    }
}
