package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;

import org.junit.jupiter.api.Test;

/**
 * A corrupt IGES file is one line naming the file, the line and what is wrong (IGES 5.3 §2: the
 * fixed-column sections, sequence numbers, the directory's pointers and the parameter data's
 * back-pointers). Each case breaks one thing in the independent writer's {@code sampler.igs}.
 */
class IgesErrorsTest {

    private static List<String> sampler() throws IOException, URISyntaxException {
        return new ArrayList<>(Files.readAllLines(Path.of(IgesErrorsTest.class.getResource("/iges/sampler.igs").toURI())));
    }

    /** The message of reading the sampler with line {@code number} (1-based) replaced. */
    private static String withLine(int number, UnaryOperator<String> change) throws Exception {
        List<String> lines = sampler();
        lines.set(number - 1, change.apply(lines.get(number - 1)));
        return message(lines);
    }

    private static String message(List<String> lines) {
        String text = String.join("\n", lines) + "\n";
        ModelFormatException e = assertThrows(ModelFormatException.class, () -> IgesReaderTest.read(text));
        String m = e.getMessage();
        assertEquals(1, m.lines().count(), m);
        return m;
    }

    /** {@code line} with the first match of {@code regex} in its data columns replaced, the columns kept. */
    private static UnaryOperator<String> data(String regex, String replacement, int width) {
        return l -> String.format("%-" + width + "s", l.substring(0, width).replaceFirst(regex, replacement).stripTrailing())
                + l.substring(width);
    }

    private static int lineOf(String prefix) throws Exception {
        List<String> lines = sampler();
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith(prefix)) {
                return i + 1;
            }
        }
        throw new AssertionError(prefix);
    }

    @Test
    void aShortLineIsNamed() throws Exception {
        assertEquals("part.igs:6: expected 80 columns with a section letter in column 73, found 70 columns", withLine(6, l -> l.substring(0, 70)));
    }

    @Test
    void aWrongSequenceNumberIsNamed() throws Exception {
        assertEquals("part.igs:7: expected sequence number 3 in the D section, found 9", withLine(7, l -> l.substring(0, 73) + "      9"));
    }

    @Test
    void aFileCutBeforeItsTerminateLineIsNamed() throws Exception {
        List<String> lines = sampler();
        lines.remove(lines.size() - 1);
        assertEquals("part.igs:87: the file ends without its terminate (T) line: cut short?", message(lines));
    }

    @Test
    void aDirectoryEntryPointingPastTheParameterDataIsNamed() throws Exception {
        assertEquals("part.igs:56: parameter line 2 points to directory entry 3, whose data is lines 999–1002", withLine(7, l -> l.substring(0, 8) + "     999" + l.substring(16)));
    }

    @Test
    void aParameterLinePointingToTheWrongEntryIsNamed() throws Exception {
        int p = lineOf("124,");
        assertEquals("part.igs:55: parameter line 1 points to directory entry 3, whose data is lines 2–5", withLine(p, l -> l.substring(0, 64) + "       3" + l.substring(72)));
    }

    @Test
    void aParameterOfTheWrongTypeIsNamed() throws Exception {
        int p = lineOf("124,");
        assertEquals("part.igs:55: entity 124 (directory line 1): field 2: expected a number, found \"1.2.3\"", withLine(p, data("124,[^,]*,", "124,1.2.3,", 64)));
    }

    @Test
    void aPointerToAMissingEntryIsNamed() throws Exception {
        int p = lineOf("144,");
        assertEquals("part.igs:72: entity 144 (directory line 25): the surface points to directory entry 99, which does not exist", withLine(p, data("144,[^,]*,", "144,99,", 64)));
    }

    @Test
    void aBadUnitFlagIsNamed() throws Exception {
        assertEquals("part.igs:2: the global section: field 14: expected a units flag 1..11, found 42", withLine(3, data("1.0,2,2HMM", "1.0,42,2HMM", 72)));
    }
}
