package org.beziertracer.model.io;

import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Output names of a job's frames: in the file name, each run of {@code #} stands for the frame number
 * padded with zeros to the run's length ({@code teapot-####.png}, frame 7: {@code teapot-0007.png}); and
 * frame ranges as written, {@code A-B} or {@code A}.
 */
public final class FramePattern {
    private FramePattern() {}

    private static final Pattern HASHES = Pattern.compile("#+");
    private static final Pattern RANGE = Pattern.compile("\\s*(\\d{1,9})\\s*(?:-\\s*(\\d{1,9})\\s*)?");

    /** True when the file name of {@code pattern} holds a {@code #}. */
    public static boolean numbered(Path pattern) {
        Path name = pattern.getFileName();
        return name != null && name.toString().contains("#");
    }

    /** The file of {@code frame} (the pattern itself when it has no {@code #}). */
    public static Path fileOf(Path pattern, int frame) {
        Path name = pattern.getFileName();
        if (name == null) {
            return pattern;
        }
        Matcher m = HASHES.matcher(name.toString());
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            String digits = Integer.toString(frame);
            int pad = m.end() - m.start() - digits.length();
            m.appendReplacement(out, "0".repeat(Math.max(0, pad)) + digits);
        }
        m.appendTail(out);
        return pattern.resolveSibling(out.toString());
    }

    /**
     * The linear {@code .pfm} written beside a frame's PNG: the same name with {@code .pfm} in place of
     * {@code .png} (any case), or {@code .pfm} added when the name has no {@code .png}. {@code render JOB.json}
     * and the Spark module's assembly name it the same way.
     */
    public static String pfmName(String pngName) {
        int cut = pngName.toLowerCase(java.util.Locale.ROOT).endsWith(".png") ? pngName.length() - 4 : pngName.length();
        return pngName.substring(0, cut) + ".pfm";
    }

    /** {@link #pfmName} of {@code png}'s file name, in the same folder. */
    public static Path pfmOf(Path png) {
        return png.resolveSibling(pfmName(png.getFileName().toString()));
    }

    /**
     * {@code A-B} or {@code A} (whole numbers 0 or more, {@code A <= B}) as {@code {A, B}}.
     *
     * @param what names the value in the message ({@code --frames}, {@code job.json: frames})
     * @throws IllegalArgumentException one line naming {@code what}
     */
    public static int[] range(String text, String what) {
        Matcher m = RANGE.matcher(text);
        if (!m.matches()) {
            throw new IllegalArgumentException(what + " must be A-B or A (whole frame numbers), got '"
                    + Echo.cut(text) + "'");
        }
        int a = Integer.parseInt(m.group(1));
        int b = m.group(2) == null ? a : Integer.parseInt(m.group(2));
        if (b < a) {
            throw new IllegalArgumentException(what + " " + a + "-" + b + ": the last frame is before the first");
        }
        return new int[] {a, b};
    }
}
