package org.beziertracer.cli;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The command-line arguments as the user typed them, also under a locale whose encoding is ASCII.
 *
 * <p>Under {@code LANG=C} Java 17 decodes the arguments as ASCII ({@code sun.jnu.encoding}, which
 * {@code -D} cannot change): {@code tépot.bpt} arrives as {@code t\uFFFD\uFFFDpot.bpt}, and every
 * message that names it would print {@code t??pot.bpt}. On Linux the process's own
 * {@code /proc/self/cmdline} still holds the bytes typed; an argument that holds U+FFFD, whose
 * bytes are valid UTF-8 and read in the locale's encoding give exactly the argument Java passed,
 * is replaced by those bytes read as UTF-8 ({@code tépot.bpt}). Everything else is left as Java
 * passed it (other systems, a mismatch, bytes that are not UTF-8). Names so repaired still find
 * their files ({@link org.beziertracer.model.io.FilePaths} reads a UTF-8 name as listed).
 */
public final class CommandArguments {
    private CommandArguments() {}

    /** {@code args} (as {@code main} got them) with the arguments Java could not decode repaired. */
    public static String[] asTyped(String[] args) {
        if (java.util.Arrays.stream(args).noneMatch(a -> a.indexOf('\uFFFD') >= 0)) {
            return args;
        }
        try {
            return asTyped(args, Files.readAllBytes(Path.of("/proc/self/cmdline")), jnuCharset());
        } catch (IOException | RuntimeException e) {
            return args; // no /proc (not Linux): as Java passed them
        }
    }

    /**
     * {@code args} repaired from {@code cmdline} (NUL-terminated arguments of the whole command,
     * the program's last) as decoded in {@code locale}.
     */
    static String[] asTyped(String[] args, byte[] cmdline, Charset locale) {
        List<byte[]> raw = split(cmdline);
        if (raw.size() < args.length) {
            return args;
        }
        String[] typed = args.clone();
        int first = raw.size() - args.length;
        for (int k = 0; k < args.length; k++) {
            byte[] bytes = raw.get(first + k);
            if (!new String(bytes, locale).equals(args[k])) {
                return args; // not the same arguments: change nothing
            }
            if (args[k].indexOf('\uFFFD') >= 0) {
                try {
                    typed[k] = StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(bytes)).toString();
                } catch (CharacterCodingException e) {
                    // Not UTF-8: keep what Java passed
                }
            }
        }
        return typed;
    }

    private static List<byte[]> split(byte[] cmdline) {
        List<byte[]> parts = new ArrayList<>();
        int start = 0;
        for (int k = 0; k < cmdline.length; k++) {
            if (cmdline[k] == 0) {
                parts.add(java.util.Arrays.copyOfRange(cmdline, start, k));
                start = k + 1;
            }
        }
        if (start < cmdline.length) {
            parts.add(java.util.Arrays.copyOfRange(cmdline, start, cmdline.length));
        }
        return parts;
    }

    private static Charset jnuCharset() {
        return Charset.forName(System.getProperty("sun.jnu.encoding", "UTF-8"));
    }
}
