package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/** The hand-written scanners and splitter against the regular expressions they replace, on random text. */
class NumberTextTest {

    private static final Pattern DECIMAL = Pattern.compile("[+-]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?");
    private static final Pattern WHOLE = Pattern.compile("[+-]?\\d+");
    private static final String ALPHABET = "0123456789+-.eEx \t\u000B\f\r\u00A0\u2003٣";

    private static String random(Random rnd, int maxLength) {
        int n = rnd.nextInt(maxLength + 1);
        StringBuilder sb = new StringBuilder(n);
        for (int i = 0; i < n; i++) {
            // digits more often, so that long valid numbers occur too
            sb.append(rnd.nextInt(3) == 0 ? ALPHABET.charAt(rnd.nextInt(ALPHABET.length())) : (char) ('0' + rnd.nextInt(10)));
        }
        return sb.toString();
    }

    @Test
    void decimalAndWholeAgreeWithTheirRegularExpressions() {
        Random rnd = new Random(61);
        int decimals = 0;
        for (int n = 0; n < 200_000; n++) {
            String s = random(rnd, 8);
            boolean decimal = DECIMAL.matcher(s).matches();
            assertEquals(decimal, NumberText.isDecimal(s), s);
            assertEquals(WHOLE.matcher(s).matches(), NumberText.isWhole(s), s);
            decimals += decimal ? 1 : 0;
        }
        assertEquals(true, decimals > 20_000, "too few valid numbers drawn: " + decimals);
        for (String s : new String[] {"1.", ".5", "+.5", "-1e-3", "1E+9", "0"}) {
            assertEquals(true, NumberText.isDecimal(s), s);
        }
        for (String s : new String[] {"", ".", "+", "e5", "1e", "1e+", "1.2.3", "٣", "NaN", "0x1p3"}) {
            assertEquals(false, NumberText.isDecimal(s), s);
        }
    }

    @Test
    void fieldsAreWhatStripAndSplitGive() {
        Random rnd = new Random(67);
        for (int n = 0; n < 100_000; n++) {
            String s = random(rnd, 12);
            assertArrayEquals(s.strip().split("\\s+"), Fields.of(s), "[" + s + "]");
        }
    }

    @Test
    void inPlaceParsingGivesTheBitsOfDoubleParseDouble() {
        Random rnd = new Random(73);
        for (int n = 0; n < 200_000; n++) {
            String number = (rnd.nextBoolean() ? "-" : "") + rnd.nextInt(1000) + "." + Long.toString(rnd.nextLong() & Long.MAX_VALUE)
                    + (rnd.nextInt(4) == 0 ? "e" + (rnd.nextInt(700) - 350) : "");
            String line = "v " + number + " ";
            double expected = Double.parseDouble(number);
            double actual = NumberText.finiteOrNaN(line, 2, 2 + number.length());
            if (Double.isFinite(expected)) {
                assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual), number);
            } else {
                assertEquals(true, Double.isNaN(actual), number);
            }
        }
        assertEquals(true, Double.isNaN(NumberText.finiteOrNaN("v 1.5x", 2, 6)));
        assertEquals(true, Double.isNaN(NumberText.finiteOrNaN("v ", 2, 2)));
    }

    @Test
    void theCharArrayFormAgreesWithTheStringFormOnDecimalsAndNearMisses() {
        Random rnd = new Random(35);
        String alphabet = "0123456789+-.eEdDx ";
        for (int n = 0; n < 200_000; n++) {
            StringBuilder sb = new StringBuilder();
            if (rnd.nextBoolean()) { // a likely decimal
                sb.append(rnd.nextBoolean() ? "-" : "").append(rnd.nextInt(1000)).append('.').append(rnd.nextInt(1_000_000));
                if (rnd.nextInt(3) == 0) {
                    sb.append(rnd.nextBoolean() ? 'e' : 'E').append(rnd.nextInt(3) == 0 ? "+" : "").append(rnd.nextInt(400) - 200);
                }
            }
            for (int k = rnd.nextInt(3); k > 0; k--) { // and perhaps a stray character anywhere
                sb.insert(rnd.nextInt(sb.length() + 1), alphabet.charAt(rnd.nextInt(alphabet.length())));
            }
            String text = "#" + sb + "#";
            int from = 1, to = 1 + sb.length();
            double a = NumberText.finiteOrNaN(text, from, to), b = NumberText.finiteOrNaN(text.toCharArray(), from, to);
            assertEquals(NumberText.isDecimal(text, from, to), NumberText.isDecimal(text.toCharArray(), from, to), text);
            assertEquals(Double.doubleToRawLongBits(a), Double.doubleToRawLongBits(b), text);
        }
    }
}
