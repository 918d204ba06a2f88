package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.io.ByteArrayOutputStream;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

/** The arguments as typed, from the process's command line, where an ASCII locale lost their letters. */
class CommandArgumentsTest {

    private static final Charset ASCII = StandardCharsets.US_ASCII;

    /** {@code parts} NUL-terminated, in UTF-8: what {@code /proc/self/cmdline} holds. */
    private static byte[] cmdline(String... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (String p : parts) {
            out.writeBytes(p.getBytes(StandardCharsets.UTF_8));
            out.write(0);
        }
        return out.toByteArray();
    }

    /** What Java 17 passes to {@code main} under an ASCII locale. */
    private static String asJavaPasses(String typed) {
        return new String(typed.getBytes(StandardCharsets.UTF_8), ASCII);
    }

    @Test
    void argumentsJavaCouldNotDecodeAreTakenFromTheCommandLine() {
        String[] args = {"info", asJavaPasses("modèles/tépot.bpt"), "", asJavaPasses("-o=é")};
        assertEquals("mod\uFFFD\uFFFDles/t\uFFFD\uFFFDpot.bpt", args[1]);
        byte[] line = cmdline("/usr/bin/java", "-cp", "x.jar", "org.beziertracer.Main", "info", "modèles/tépot.bpt", "",
                "-o=é");
        assertArrayEquals(new String[] {"info", "modèles/tépot.bpt", "", "-o=é"}, CommandArguments.asTyped(args, line, ASCII));
    }

    @Test
    void anyMismatchLeavesTheArgumentsAsJavaPassedThem() {
        String[] args = {"info", asJavaPasses("tépot.bpt")};
        assertSame(args, CommandArguments.asTyped(args, cmdline("java", "info", "tapot.bpt"), ASCII), "other bytes");
        assertSame(args, CommandArguments.asTyped(args, cmdline("tépot.bpt"), ASCII), "fewer arguments");
        byte[] latin1 = {'t', (byte) 0xE9, 'p', 'o', 't', 0};
        String[] one = {new String(latin1, 0, 5, ASCII)};
        assertArrayEquals(one, CommandArguments.asTyped(one, latin1, ASCII), "bytes that are not UTF-8 stay as passed");
    }

    @Test
    void messagesAreUtf8OnlyWhereJavaChoseAscii() {
        assertEquals(StandardCharsets.UTF_8, ConsoleEncoding.forMessages(StandardCharsets.US_ASCII));
        assertEquals(StandardCharsets.UTF_8, ConsoleEncoding.forMessages(Charset.forName("ANSI_X3.4-1968")));
        assertEquals(StandardCharsets.ISO_8859_1, ConsoleEncoding.forMessages(StandardCharsets.ISO_8859_1));
        assertEquals(StandardCharsets.UTF_8, ConsoleEncoding.forMessages(StandardCharsets.UTF_8));
    }
}
