package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.beziertracer.Main;
import org.beziertracer.model.io.FilePaths;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Under {@code LANG=C} (Java 17 decodes arguments and file names as ASCII) an existing file whose
 * name has other than ASCII letters is read, written over and named in scene files as under a
 * UTF-8 locale; a new such name is one line saying which locale to use. Each case runs the command
 * line in a child JVM with the locale variables set to C.
 */
class NonUtf8LocaleTest {

    private static final String ONE_PATCH = "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n";
    private static final String LOCALE_HINT = "not a valid file name in this locale's encoding (ANSI_X3.4-1968): Java"
            + " cannot pass on a name with other than ASCII characters; run with a UTF-8 locale, e.g. LC_ALL=C.UTF-8";

    @TempDir
    Path dir;

    private record Result(int code, String out, String err) {}

    @BeforeEach
    void files() throws Exception {
        Files.writeString(dir.resolve("théière.bpt"), ONE_PATCH);
        Files.createDirectory(dir.resolve("modèles"));
        Files.writeString(dir.resolve("modèles").resolve("tépot.bpt"), ONE_PATCH);
    }

    /** {@code beziertracer args} in {@link #dir} with {@code LANG=C}, no {@code LC_*}, headless. */
    private Result langC(String... args) throws Exception {
        return langC(Main.class, args);
    }

    /** Prints the code points of {@link FilePaths#name} of the file its argument names (one line, hex). */
    public static final class NameOf {
        public static void main(String[] args) {
            System.out.println(FilePaths.name(FilePaths.of(args[0])).codePoints()
                    .mapToObj(Integer::toHexString).collect(java.util.stream.Collectors.joining(" ")));
        }
    }

    private Result langC(Class<?> main, String... args) throws Exception {
        return langC(List.of(), main, args);
    }

    private Result langC(List<String> jvmOptions, Class<?> main, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        command.addAll(jvmOptions);
        command.addAll(List.of("-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), main.getName()));
        command.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(command).directory(dir.toFile());
        pb.environment().keySet().removeIf(k -> k.startsWith("LC_") || k.equals("LANG") || k.contains("JAVA_OPTIONS")
                || k.equals("JAVA_TOOL_OPTIONS") || k.equals("DISPLAY"));
        pb.environment().put("LANG", "C");
        pb.redirectError(dir.resolve("err.txt").toFile()).redirectOutput(dir.resolve("out.txt").toFile());
        Process p = pb.start();
        assertTrue(p.waitFor(90, TimeUnit.SECONDS), "finished");
        return new Result(p.exitValue(), Files.readString(dir.resolve("out.txt"), StandardCharsets.ISO_8859_1),
                Files.readString(dir.resolve("err.txt"), StandardCharsets.ISO_8859_1));
    }

    @Test
    void anExistingNonAsciiModelIsReadRenderedAnalysedAndConverted() throws Exception {
        Result info = langC("info", "théière.bpt");
        assertEquals(0, info.code(), info.err());
        assertTrue(info.out().contains("patches: 1"), info.out());
        Result nested = langC("info", "modèles/tépot.bpt");
        assertEquals(0, nested.code(), "a non-ASCII folder too: " + nested.err());
        Result render = langC("render", "théière.bpt", "-o", "out.png", "--size", "16x12", "-q");
        assertEquals(0, render.code(), render.err());
        assertTrue(Files.size(dir.resolve("out.png")) > 0);
        Result analyze = langC("analyze", "théière.bpt", "-q");
        assertEquals(0, analyze.code(), analyze.err());
        Result convert = langC("convert", "théière.bpt", "back.obj");
        assertEquals(0, convert.code(), convert.err());
        assertTrue(Files.readString(dir.resolve("back.obj")).contains("cstype bezier"));
    }

    @Test
    void anExistingNonAsciiOutputIsWrittenOverAndASceneNamesANonAsciiModel() throws Exception {
        Files.writeString(dir.resolve("sortie.png"), "old");
        Files.move(dir.resolve("sortie.png"), dir.resolve("sortié.png"));
        Result render = langC("render", "patch", "-o", "sortié.png", "--size", "16x12", "-q");
        assertEquals(0, render.code(), render.err());
        assertFalse(Files.readString(dir.resolve("sortié.png"), StandardCharsets.ISO_8859_1).equals("old"), "written over");
        Files.writeString(dir.resolve("scène.json"), "{\"version\": 1, \"models\": [{\"file\": \"modèles/tépot.bpt\"}]}");
        Result scene = langC("info", "scène.json");
        assertEquals(0, scene.code(), scene.err());
        assertTrue(scene.out().contains("patches: 1"), scene.out());
    }

    @Test
    void aNewNonAsciiNameIsOneLineSayingWhichLocaleToUse() throws Exception {
        Result render = langC("render", "patch", "-o", "neuf-é.png", "--size", "16x12", "-q");
        assertEquals(2, render.code(), render.err());
        assertEquals(1, render.err().lines().count(), render.err());
        assertTrue(render.err().startsWith("beziertracer render: --output: expected a file name, found ")
                && render.err().strip().endsWith(LOCALE_HINT + " (see beziertracer render --help)"), render.err());
        Result convert = langC("convert", "patch", "neuf-é.obj");
        assertEquals(1, convert.code(), convert.err());
        assertEquals(1, convert.err().lines().count(), convert.err());
        assertTrue(convert.err().strip().endsWith(LOCALE_HINT), convert.err());
        Result missing = langC("info", "absent-é.bpt");
        assertEquals(1, missing.code(), missing.err());
        assertTrue(missing.err().strip().endsWith(LOCALE_HINT), missing.err());
    }

    @Test
    void theNameShownInTheAppIsTheNameOnDiskNotItsAsciiReading() throws Exception {
        Result r = langC(NameOf.class, "modèles/tépot.bpt");
        assertEquals(0, r.code(), r.err());
        String expected = "tépot.bpt".codePoints().mapToObj(Integer::toHexString)
                .collect(java.util.stream.Collectors.joining(" "));
        assertEquals(expected, r.out().strip(), "t, é, p, o, t: not t, U+FFFD, U+FFFD, p, o, t");
    }

    @Test
    void theAppAcceptsAnExistingNonAsciiModelAsItsArgument() throws Exception {
        Result app = langC("théière.bpt");
        assertFalse(app.err().contains("is not a command"), app.err());
        assertTrue(app.err().contains("display"), "it goes on to look for a display: " + app.err());
    }

    /** Prints {@code tépot.bpt} on standard output and standard error after {@link ConsoleEncoding#install()}, as {@code Main} does. */
    public static final class PrintsAName {
        public static void main(String[] args) {
            ConsoleEncoding.install();
            System.out.println("out: tépot.bpt");
            System.err.println("err: tépot.bpt");
        }
    }

    /** {@code text} as the child's output is read back here: its UTF-8 bytes, a char per byte. */
    private static String utf8(String text) {
        return new String(text.getBytes(StandardCharsets.UTF_8), StandardCharsets.ISO_8859_1);
    }

    @Test
    void messagesNameNonAsciiFilesWithTheirBytesOnDiskNotQuestionMarks() throws Exception {
        Result info = langC("info", "modèles/tépot.bpt");
        assertEquals(0, info.code(), info.err());
        assertTrue(info.out().startsWith(utf8("model: modèles/tépot.bpt\n")), info.out());
        Files.writeString(dir.resolve("modèles").resolve("bâd.bpt"), "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 x\n");
        Result bad = langC("info", "modèles/bâd.bpt");
        assertEquals(1, bad.code(), bad.err());
        assertEquals(utf8("beziertracer info: modèles/bâd.bpt:6: expected a number for the z coordinate of point 4"
                + " of patch 1 (of 1 announced), found \"x\"\n"), bad.err(), "the reader names the file as typed");
        Result output = langC("render", "théière.bpt", "-o", "théière.bpt", "-q");
        assertEquals(1, output.code(), output.err());
        assertEquals(utf8("beziertracer render: théière.bpt: the output must be a .png (or .hdr or .pfm) file\n"),
                output.err(), "a path from -o as typed");
        Result rays = langC("trace", "patch", "-i", "théière.bpt", "-o", "théière.bpt");
        assertEquals(1, rays.code(), rays.err());
        assertEquals(utf8("beziertracer trace: -o théière.bpt is the ray file -i théière.bpt: the hits would replace"
                + " the rays; choose another output file\n"), rays.err());
        Result missing = langC("info", "absent-é.bpt");
        assertEquals(utf8("beziertracer info: absent-é.bpt: " + LOCALE_HINT + "\n"), missing.err(),
                "a name Java could not decode is echoed as typed");
        Result notACommand = langC("rendré");
        assertEquals(2, notACommand.code(), notACommand.err());
        assertTrue(notACommand.err().startsWith(utf8("beziertracer: \"rendré\" is not a command")), notACommand.err());
    }

    @Test
    void theAppsStandardStreamsWriteUtf8WhereJavaChoseAscii() throws Exception {
        Result r = langC(PrintsAName.class);
        assertEquals(0, r.code(), r.err());
        assertEquals(utf8("out: tépot.bpt\n"), r.out());
        assertEquals(utf8("err: tépot.bpt\n"), r.err());
    }

    /** Prints {@code tépot.bpt} through Java's own {@code System.out} and {@code System.err}, as a library would. */
    public static final class PrintsThroughJava {
        public static void main(String[] args) {
            System.out.println("out: tépot.bpt");
            System.err.println("err: tépot.bpt");
        }
    }

    /** The JVM options between {@code java} and {@code -jar} in the README's launch command. */
    private static List<String> readmeLaunchOptions() throws Exception {
        String line = Files.readAllLines(Path.of("README.md")).stream()
                .filter(l -> l.startsWith("    ./mvnw -B -q package -DskipTests && java ")).findFirst().orElseThrow();
        String options = line.substring(line.indexOf("&& java ") + "&& java ".length(), line.indexOf(" -jar "));
        return List.of(options.trim().split("\\s+"));
    }

    /** The {@code --java-options} jpackage gives the packaged launcher ({@code -Pdist} in pom.xml). */
    private static List<String> packagedLauncherOptions() throws Exception {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile(
                "<argument>--java-options</argument><argument>([^<]*)</argument>").matcher(Files.readString(Path.of("pom.xml")));
        List<String> options = new ArrayList<>();
        while (m.find()) {
            options.add(m.group(1));
        }
        return options;
    }

    @Test
    void theReadmeCommandAndThePackagedLauncherStartJavaWritingUtf8() throws Exception {
        for (List<String> options : List.of(readmeLaunchOptions(), packagedLauncherOptions())) {
            Result r = langC(options, PrintsThroughJava.class);
            assertEquals(0, r.code(), options + ": " + r.err());
            assertEquals(utf8("out: tépot.bpt\n"), r.out(), options.toString());
            assertTrue(r.err().endsWith(utf8("err: tépot.bpt\n")), options + ": " + r.err());
        }
        Result plain = langC(List.of(), PrintsThroughJava.class);
        assertEquals("out: t?pot.bpt\n", plain.out(), "without the options Java 17 writes ASCII (else this test proves nothing)");
    }
}
