package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

/** The shared text source: decoding, line ends, byte-order marks and caps, across buffer boundaries. */
class TextSourceTest {

    private static TextSource source(byte[] bytes) {
        return new TextSource(new ByteArrayInputStream(bytes), "t.txt");
    }

    private static List<String> lines(byte[] bytes) throws IOException {
        TextSource s = source(bytes);
        List<String> out = new ArrayList<>();
        for (String line = s.readLine(); line != null; line = s.readLine()) {
            out.add(s.lineNumber() + ":" + line);
        }
        return out;
    }

    @Test
    void lfCrlfAndLoneCrEndLinesAndNumberThem() throws IOException {
        assertEquals(List.of("1:a", "2:b", "3:", "4:c", "5:d"), lines("a\nb\r\n\rc\rd".getBytes(StandardCharsets.UTF_8)));
        assertEquals(List.of("1:a", "2:"), lines("a\n\n".getBytes(StandardCharsets.UTF_8)));
        assertEquals(List.of(), lines(new byte[0]));
    }

    @Test
    void aCrlfSplitAcrossTheDecodeBufferIsOneLineEnd() throws IOException {
        for (int at = 16_380; at < 16_390; at++) {
            char[] text = new char[at + 5];
            Arrays.fill(text, 'x');
            text[at] = '\r';
            text[at + 1] = '\n';
            List<String> got = lines(new String(text).getBytes(StandardCharsets.UTF_8));
            assertEquals(2, got.size(), "CRLF at " + at);
            assertEquals("2:xxx", got.get(1), "CRLF at " + at);
        }
    }

    @Test
    void linesReadInPlaceAreTheLinesReadAsStrings() throws IOException {
        java.util.Random rnd = new java.util.Random(35);
        StringBuilder sb = new StringBuilder();
        String[] ends = {"\n", "\r\n", "\r"};
        for (int k = 0; k < 3_000; k++) { // lines of 0 to 20,000 characters: many cross the 16 K buffer
            int length = rnd.nextInt(10) == 0 ? rnd.nextInt(20_000) : rnd.nextInt(40);
            for (int i = 0; i < length; i++) {
                sb.append(rnd.nextInt(50) == 0 ? 'é' : (char) ('a' + rnd.nextInt(26)));
            }
            sb.append(ends[rnd.nextInt(3)]);
        }
        String text = sb.append("last").toString();
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        List<String> expected = new ArrayList<>(); // independent of TextSource: the text split at its line ends
        String[] split = text.split("\r\n|\r|\n", -1);
        for (int k = 0; k < split.length; k++) {
            expected.add((k + 1) + ":" + split[k]);
        }
        TextSource s = source(bytes);
        List<String> inPlace = new ArrayList<>();
        while (s.nextLine()) {
            inPlace.add(s.lineNumber() + ":" + new String(s.lineChars(), s.lineStart(), s.lineEnd() - s.lineStart()));
        }
        assertEquals(expected, inPlace);
        assertEquals(expected, lines(bytes));
        assertTrue(inPlace.size() > 2_900, "lines: " + inPlace.size()); // a lone CR then an empty LF line is one end
        assertTrue(inPlace.get(inPlace.size() - 1).endsWith(":last"));
    }

    @Test
    void charactersCountLinesLikeReadLine() throws IOException {
        TextSource s = source("a\r\nb\rc\nd".getBytes(StandardCharsets.UTF_8));
        StringBuilder seen = new StringBuilder();
        for (int c = s.read(); c != -1; c = s.read()) {
            if (c >= 'a') {
                seen.append((char) c).append(s.line());
            }
        }
        assertEquals("a1b2c3d4", seen.toString());
    }

    @Test
    void onlyALeadingByteOrderMarkIsSkipped() throws IOException {
        byte[] bom = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
        byte[] text = "a\n\uFEFFb".getBytes(StandardCharsets.UTF_8);
        byte[] both = new byte[bom.length + text.length];
        System.arraycopy(bom, 0, both, 0, 3);
        System.arraycopy(text, 0, both, 3, text.length);
        assertEquals(List.of("1:a", "2:\uFEFFb"), lines(both));
        assertEquals("", source(bom).readAll("a file"));
    }

    @Test
    void invalidUtf8IsReportedAtItsOffsetWhereverTheBufferEnds() {
        for (int at : new int[] {0, 1, 16_383, 16_384, 16_385, 40_000}) {
            byte[] b = new byte[at + 10];
            Arrays.fill(b, (byte) 'x');
            b[at] = (byte) 0xE2; // a three-byte sequence cut short by an ASCII byte
            b[at + 1] = (byte) 0x82;
            String message = UserMessages.of(ModelFormatException.class, () -> source(b).readAll("a file"));
            assertEquals("t.txt: not a text file (invalid UTF-8 at byte " + at + ")", message);
        }
    }

    @Test
    void aStreamLargerThanTheInMemoryCapIsRefusedWhileReading() throws IOException {
        ReadLimits small = new ReadLimits(100, 1 << 20, 10, 10, 10, 10);
        byte[] big = new byte[(1 << 20) + 20_000];
        Arrays.fill(big, (byte) ' ');
        String message = UserMessages.of(ModelFormatException.class,
                () -> new TextSource(new ByteArrayInputStream(big), "s.json", small).readAll("a scene file"));
        assertEquals("s.json: the file holds more than the 1 MB a scene file may hold", message);
        byte[] fits = Arrays.copyOf(big, 1 << 20);
        assertEquals(1 << 20, new TextSource(new ByteArrayInputStream(fits), "s.json", small).readAll("x").length());
    }

    @Test
    void theLineCapCountsCharactersNotBytes() throws IOException {
        ReadLimits small = new ReadLimits(4, 1 << 20, 10, 10, 10, 10);
        TextSource s = new TextSource(new ByteArrayInputStream("éééé\nééééé\n".getBytes(StandardCharsets.UTF_8)),
                "t.obj", small);
        assertEquals("éééé", s.readLine());
        assertEquals("t.obj:2: line longer than 4 characters, the most a line may hold",
                UserMessages.of(ModelFormatException.class, s::readLine));
        assertNull(source(new byte[0]).readLine());
    }

    @Test
    void readingIntoAnArrayGivesTheCharactersAndLinesOfReadingOneByOne() throws java.io.IOException {
        java.util.Random rnd = new java.util.Random(35);
        String alphabet = "ab\r\n\u00e9\u20ac ";
        for (int round = 0; round < 200; round++) {
            StringBuilder sb = new StringBuilder(rnd.nextBoolean() ? "\uFEFF" : "");
            for (int k = rnd.nextInt(40_000); k > 0; k--) {
                sb.append(alphabet.charAt(rnd.nextInt(alphabet.length())));
            }
            TextSource one = TextSource.of(sb.toString(), "t.txt"), many = TextSource.of(sb.toString(), "t.txt");
            char[] buffer = new char[1 + rnd.nextInt(20_000)];
            StringBuilder byOne = new StringBuilder(), byMany = new StringBuilder();
            List<Integer> lineAfter = new ArrayList<>();
            for (int c = one.read(); c >= 0; c = one.read()) {
                byOne.append((char) c);
                lineAfter.add(one.line());
            }
            for (int n = many.read(buffer); n >= 0; n = many.read(buffer)) {
                assertTrue(n > 0, "an empty read before the end");
                byMany.append(buffer, 0, n);
                assertEquals(lineAfter.get(byMany.length() - 1), many.line(), "round " + round + ", after " + byMany.length());
            }
            assertEquals(byOne.toString(), byMany.toString(), "round " + round);
            assertEquals(one.line(), many.line(), "round " + round);
        }
    }
}
