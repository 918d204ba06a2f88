package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

class BptReaderTest {

    private static final String BILINEAR = "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n";

    /** The one-line message of the parse error {@code text} must give (checked by {@link UserMessages}). */
    private static String fails(String text, String fileName) {
        return UserMessages.of(ModelFormatException.class, () -> BptReader.read(text, fileName));
    }

    private static void assertMessage(String msg, String prefix, String... parts) {
        assertTrue(msg.startsWith(prefix), () -> "message should start with \"" + prefix + "\": " + msg);
        for (String part : parts) {
            assertTrue(msg.contains(part), () -> "message should contain \"" + part + "\": " + msg);
        }
        assertTrue(!msg.contains("\n"), () -> "message should be one line: " + msg);
    }

    @Test
    void readsPointsWithTheUIndexFastest() {
        BezierPatch p = BptReader.read("1\n2 1\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 5\n", "a.bpt").get(0);
        assertEquals(2, p.degreeU());
        assertEquals(1, p.degreeV());
        assertEquals(2.0, p.get(2, 0, 0));
        assertEquals(1.0, p.get(0, 1, 1));
        assertEquals(5.0, p.get(2, 1, 2));
    }

    @Test
    void aWholeFileOnOneLineReadsLikeTheMultiLineFile() {
        String oneLine = BILINEAR.replace('\n', ' ');
        assertEquals(BptReader.read(BILINEAR, "a.bpt"), BptReader.read(oneLine, "b.bpt"));
    }

    @Test
    void aFileWrittenOnOneLineFromAnyBptReadsBackEqual() {
        List<BezierPatch> teapot = Models.teapot().patches();
        String oneLine = BptWriter.toString(teapot).replace('\n', ' ').replace(" ", "\t ");
        assertEquals(teapot, BptReader.read(oneLine, "teapot-one-line.bpt"));
    }

    @Test
    void commentsAndBlankLinesAreIgnored() {
        String text = "# a comment line\n1 # one patch\n\n1 1#degrees touching a comment\n"
                + "0 0 0\n1 0 0 # first row\n0 1 0\n#\n1 1 1\n# trailing comment\n";
        assertEquals(BptReader.read(BILINEAR, "a.bpt"), BptReader.read(text, "c.bpt"));
    }

    @Test
    void scientificNotationAndSignsAreNumbers() {
        BezierPatch p = BptReader.read("1 1 1  1e2 -2.5E-1 +3  .5 0. -0  1 1 1  2 2 2", "s.bpt").get(0);
        assertArrayEquals(new double[] {100, -0.25, 3, 0.5, 0, -0.0, 1, 1, 1, 2, 2, 2}, p.copyNet());
    }

    @Test
    void anEmptyFileNamesTheFileAndLineOne() {
        assertMessage(fails("", "empty.bpt"), "empty.bpt:1: ", "expected the patch count", "end of file");
        assertMessage(fails("  # only a comment\n\n", "blank.bpt"), "blank.bpt:1: ", "expected the patch count");
    }

    @Test
    void aTruncatedFileSaysWhatWasMissing() {
        String truncated = "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1\n";
        assertMessage(fails(truncated, "cut.bpt"), "cut.bpt:6: ",
                "expected a number for the z coordinate of point 4 of patch 1", "found end of file");
    }

    @Test
    void fewerPatchesThanAnnouncedIsAnError() {
        assertMessage(fails("2\n" + BILINEAR.substring(2), "few.bpt"), "few.bpt:6: ",
                "expected the u degree of patch 2 (of 2 announced)", "found end of file");
    }

    @Test
    void extraTokensAfterTheAnnouncedPatchesAreAnError() {
        assertMessage(fails(BILINEAR + "1 1\n0 0 0\n", "many.bpt"), "many.bpt:7: ",
                "expected end of file after the 1 announced patches", "found \"1\"");
    }

    @Test
    void aLetterWhereANumberBelongsIsNamedWithItsPlace() {
        String text = "2\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n1 1\n0 0 0\n1 0 0\n0 abc 0\n1 1 1\n";
        assertMessage(fails(text, "teapot.bpt"), "teapot.bpt:10: ",
                "expected a number for the y coordinate of point 3 of patch 2", "found \"abc\"");
    }

    @Test
    void nanAndInfinityCoordinatesAreRejected() {
        for (String bad : new String[] {"NaN", "nan", "Infinity", "-Infinity", "inf", "1e999"}) {
            String text = "1\n1 1\n0 0 0\n1 " + bad + " 0\n0 1 0\n1 1 1\n";
            assertMessage(fails(text, "nan.bpt"), "nan.bpt:4: ",
                    "expected a finite number for the y coordinate of point 2 of patch 1", "\"" + bad + "\"");
        }
    }

    @Test
    void javaOnlyNumberSyntaxIsNotANumber() {
        for (String bad : new String[] {"1d", "2f", "0x1p3", "1,5", "--1"}) {
            String text = "1\n1 1\n" + bad + " 0 0\n1 0 0\n0 1 0\n1 1 1\n";
            assertMessage(fails(text, "j.bpt"), "j.bpt:3: ", "expected a number for the x coordinate of point 1",
                    "\"" + bad + "\"");
        }
    }

    @Test
    void negativeZeroAndHugeDegreesAreOutOfRange() {
        assertMessage(fails("1\n40 3\n", "deg.bpt"), "deg.bpt:2: ", "expected the u degree of patch 1",
                "degree 40 out of range 1..15");
        assertMessage(fails("1\n3 -2\n", "deg.bpt"), "deg.bpt:2: ", "expected the v degree of patch 1",
                "degree -2 out of range 1..15");
        assertMessage(fails("1\n0 3\n", "deg.bpt"), "deg.bpt:2: ", "degree 0 out of range 1..15");
        assertMessage(fails("1\n99999999999999999999999 3\n", "deg.bpt"), "deg.bpt:2: ", "out of range 1..15");
        assertMessage(fails("1\n3.0 3\n", "deg.bpt"), "deg.bpt:2: ", "expected the u degree of patch 1",
                "found \"3.0\"");
    }

    @Test
    void anAbsurdPatchCountFailsWithoutAllocatingForIt() {
        assertMessage(fails("1e12\n1 1\n", "huge.bpt"), "huge.bpt:1: ", "expected the patch count", "\"1e12\"");
        assertMessage(fails("1000000000000\n1 1\n", "huge.bpt"), "huge.bpt:1: ",
                "patch count 1000000000000 out of range 1..1000000");
        // in range but far more than the file holds: fails on the missing data
        assertMessage(fails("1000000 " + BILINEAR.substring(2), "big.bpt"), "big.bpt:5: ",
                "expected the u degree of patch 2 (of 1000000 announced)", "end of file");
    }

    @Test
    void aZeroOrNegativePatchCountIsAnError() {
        assertMessage(fails("0\n", "zero.bpt"), "zero.bpt:1: ", "patch count 0 out of range");
        assertMessage(fails("-3\n", "neg.bpt"), "neg.bpt:1: ", "patch count -3 out of range");
        assertMessage(fails("abc\n", "word.bpt"), "word.bpt:1: ", "expected the patch count", "found \"abc\"");
    }

    @Test
    void aVeryLongBadTokenIsShortenedInTheMessage() {
        String longWord = "x".repeat(500);
        String message = fails(longWord, "long.bpt");
        assertTrue(message.length() < 200, () -> "message too long: " + message);
    }

    @Test
    void theExceptionCarriesFileAndLine() {
        ModelFormatException e = org.junit.jupiter.api.Assertions.assertThrows(ModelFormatException.class,
                () -> BptReader.read("1\n1 1\n0 0 0\n1 0 zz\n", "f.bpt"));
        UserMessages.check(e.getMessage());
        assertEquals("f.bpt", e.fileName());
        assertEquals(4, e.line());
        assertTrue(e.detail().startsWith("expected a number"), e.detail());
    }
}
