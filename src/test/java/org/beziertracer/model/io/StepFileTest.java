package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

/** The Part 21 tokenizer and entity table: every kind of value, complex instances, line numbers, one-line errors. */
class StepFileTest {

    static final String HEAD = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\n"
            + "FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n";
    static final String TAIL = "ENDSEC;\nEND-ISO-10303-21;\n";

    static StepFile read(String data) {
        try {
            return StepFile.read(TextSource.of(HEAD + data + TAIL, "part.stp"));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void everyKindOfValueIsRead() {
        StepFile f = read("#1=THING('it''s','\\X2\\00E9\\X0\\',.T.,$,*,#2,(1,-2.5E-3,(3.)),LENGTH_MEASURE(25.4),'a\\\\b');\n"
                + "/* a comment */ #2 = OTHER ( ) ;\n");
        StepFile.Entity e = f.entities.get(1);
        assertEquals("THING", e.type());
        assertEquals(7, e.line());
        List<Object> p = e.parts().get(0).params();
        assertEquals("it's", p.get(0));
        assertEquals("\\X2\\00E9\\X0\\", p.get(1), "encodings are kept raw");
        assertEquals(new StepFile.Enum("T"), p.get(2));
        assertEquals(StepFile.UNSET, p.get(3));
        assertEquals(StepFile.DERIVED, p.get(4));
        assertEquals(new StepFile.Ref(2), p.get(5));
        assertEquals(List.of(1L, -2.5E-3, List.of(3.0)), p.get(6));
        assertEquals(new StepFile.Typed("LENGTH_MEASURE", 25.4), p.get(7));
        assertEquals("a\\b", p.get(8));
        assertEquals(List.of(), f.entities.get(2).parts().get(0).params());
        assertEquals(List.of("AUTOMOTIVE_DESIGN"), f.schemas);
    }

    @Test
    void numbersReadInPlaceHaveTheBitsOfTheJdkParse() {
        java.util.Random rnd = new java.util.Random(10303);
        StringBuilder data = new StringBuilder();
        List<String> texts = new java.util.ArrayList<>();
        for (int k = 0; k < 5000; k++) {
            double v = (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(40) - 20);
            String t = switch (k % 6) {
                case 0 -> Double.toString(v);
                case 1 -> String.format(java.util.Locale.ROOT, "%.17E", v);
                case 2 -> String.format(java.util.Locale.ROOT, "%.6f", v);
                case 3 -> (v < 0 ? "-" : "+") + Math.abs((long) (v * 1e3) % 1_000_000_000_000L) + ".";
                case 4 -> (v < 0 ? "-" : "") + Math.abs((long) (v * 1e3) % 1_000_000_000_000L) + ".E-07";
                default -> Long.toString(rnd.nextLong() >> rnd.nextInt(64));
            };
            texts.add(t);
            data.append("#").append(k + 1).append("=N(").append(t).append(");\n");
        }
        StepFile f = read(data.toString());
        for (int k = 0; k < texts.size(); k++) {
            String t = texts.get(k);
            Object expected = t.contains(".") || t.contains("E") ? (Object) Double.parseDouble(t) : (Object) Long.parseLong(t);
            assertEquals(expected, f.entities.get(k + 1).parts().get(0).params().get(0), t);
        }
    }

    @Test
    void complexInstancesKeepTheirRecordsInOrder() {
        StepFile f = read("#5=(BOUNDED_SURFACE()B_SPLINE_SURFACE(2,1)\nRATIONAL_B_SPLINE_SURFACE(((1.,2.))));\n");
        StepFile.Entity e = f.entities.get(5);
        assertTrue(e.complex());
        assertEquals("BOUNDED_SURFACE+B_SPLINE_SURFACE+RATIONAL_B_SPLINE_SURFACE", e.type());
        assertEquals(List.of(2L, 1L), e.part("B_SPLINE_SURFACE").params());
        assertTrue(e.is("RATIONAL_B_SPLINE_SURFACE"));
    }

    @Test
    void linesAreCountedAcrossCrlfAndLoneCr() throws IOException {
        String text = HEAD.replace("\n", "\r\n") + "#1=A();\r#2=B();\r\n\r\n#3=C(\n1.);\n" + TAIL;
        StepFile f = StepFile.read(TextSource.of(text, "part.stp"));
        assertEquals(7, f.entities.get(1).line());
        assertEquals(8, f.entities.get(2).line());
        assertEquals(10, f.entities.get(3).line());
    }

    @Test
    void linesAreCountedAcrossManyBuffersOfMixedLineEnds() throws IOException {
        java.util.Random rnd = new java.util.Random(35);
        String[] ends = {"\n", "\r\n", "\r"};
        StringBuilder data = new StringBuilder();
        int line = 7; // HEAD is 6 lines
        int[] expected = new int[5001];
        for (int id = 1; id <= 5000; id++) {
            expected[id] = line;
            data.append("#").append(id).append("=P(").append(rnd.nextDouble()).append(',');
            String end = ends[rnd.nextInt(3)]; // a line break inside the parameters
            data.append(end).append(id).append(");").append(end);
            line += 2;
            for (int k = rnd.nextInt(3); k > 0; k--) { // blank lines (never an LF after a lone CR: that is one CRLF)
                data.append(ends[1 + rnd.nextInt(2)]);
                line++;
            }
        }
        StepFile f = StepFile.read(TextSource.of(HEAD + data + TAIL, "part.stp"));
        for (int id = 1; id <= 5000; id++) {
            assertEquals(expected[id], f.entities.get(id).line(), "#" + id);
        }
        String bad = HEAD + data + "#5001=P(1.,\r\n2.);\r\n#5002=P(.T);\n" + TAIL;
        assertEquals("part.stp:" + (line + 2) + ": expected an enumeration .NAME., found \")\"",
                UserMessages.of(ModelFormatException.class, () -> StepFile.read(TextSource.of(bad, "part.stp"))));
    }

    private static String error(String data) {
        return UserMessages.of(ModelFormatException.class, () -> read(data));
    }

    @Test
    void badSyntaxIsOneLineNamingTheFileAndTheLine() {
        assertEquals("part.stp:9: expected ';' after the entity #2, found \"#\"", error("#1=A();\n#2=B()\n#3=C();\n"));
        assertEquals("part.stp:7: a string that never ends (no closing ')", error("#1=A('abc);\n"));
        assertEquals("part.stp:8: #1 is defined twice (first on line 7)", error("#1=A();\n#1=B();\n"));
        assertEquals("part.stp:7: expected a number, found \"1.E\"", error("#1=A(1.E);\n"));
        assertEquals("part.stp:7: the number \"1.E999\" is too large", error("#1=A(1.E999);\n"));
        assertEquals("part.stp:7: expected an entity name after #1=, found \"(\"".replace("\"(\"", "\";\""),
                error("#1=;\n"));
        assertEquals("part.stp:7: expected an enumeration .NAME., found \")\"", error("#1=A(.T);\n"));
        assertEquals("part.stp:7: parameters nested more than 32 deep", error("#1=A(" + "(".repeat(40) + ");\n"));
        assertEquals("part.stp:7: a comment /* … */ that never ends", error("/* no end #1=A();\n"));
        assertEquals("part.stp:1: not a STEP file: it does not start with ISO-10303-21;", UserMessages.of(
                ModelFormatException.class, () -> StepFile.read(TextSource.of("solid x\n", "part.stp"))));
    }

    @Test
    void aReferenceToAMissingEntityNamesBoth() {
        StepFile f = read("#1=A(#9);\n");
        StepArgs a = StepArgs.of(f, f.entities.get(1), "A");
        assertEquals("part.stp:7: #1 (A) refers to #9, which the file does not define",
                UserMessages.of(ModelFormatException.class, () -> a.ref(0, "x")));
        assertEquals("part.stp:7: #1 (A): expected a number for radius, found #9",
                UserMessages.of(ModelFormatException.class, () -> a.real(0, "radius")));
    }

    @Test
    void aFileAboveTheMemoryCapIsRefusedNotRead() {
        ReadLimits small = new ReadLimits(1 << 10, 1 << 20, 10, 10, 10, 10);
        String text = HEAD + "#1=A('" + "x".repeat(900) + "');\n".repeat(1) + ("#2=B(" + "1.,".repeat(400_000) + "1.);\n") + TAIL;
        TextSource src = new TextSource(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), "big.stp", small);
        assertEquals("big.stp: the file holds more than the 1 MB a STEP file may hold",
                UserMessages.of(ModelFormatException.class, () -> StepFile.read(src)));
        String longString = HEAD + "#1=A('" + "x".repeat(2000) + "');\n" + TAIL;
        TextSource src2 = new TextSource(new ByteArrayInputStream(longString.getBytes(StandardCharsets.UTF_8)), "big.stp", small);
        assertEquals("big.stp:7: a string longer than 1024 characters",
                UserMessages.of(ModelFormatException.class, () -> StepFile.read(src2)));
    }

    @Test
    void anInterruptedReadStops() {
        StringBuilder sb = new StringBuilder();
        for (int k = 1; k <= 5000; k++) {
            sb.append('#').append(k).append("=A();\n");
        }
        Thread.currentThread().interrupt();
        try {
            assertThrows(InterruptedIOException.class, () -> StepFile.read(TextSource.of(HEAD + sb + TAIL, "part.stp")));
        } finally {
            Thread.interrupted();
        }
    }
}
