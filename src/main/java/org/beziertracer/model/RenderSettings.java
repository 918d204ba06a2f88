package org.beziertracer.model;

import java.util.Locale;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * Render settings a scene file may carry (and the CLI or app may override). Plain values, so
 * the model layer needs nothing from the renderer; {@code render} interprets them.
 *
 * @param width, height image size in pixels, 1..{@value #MAX_SIZE}
 * @param spp           samples per pixel, 1..{@value #MAX_SPP}
 * @param sampler       {@code regular}, {@code jittered} or {@code adaptive}
 * @param method        the ray–patch method's name, a lower-case word; which words name a method
 *                      only the intersection layer knows ({@code intersect.Method.parse} checks
 *                      it where the name becomes a method, and as a scene file loads)
 * @param bvh           sub-patch BVH on
 * @param shading       {@code phong}, {@code flat}, {@code normals}, {@code uv}, {@code patch-id}, or an analysis
 *                      view: {@code zebra}, {@code emap}, {@code isophotes}, {@code gaussian}, {@code mean}, {@code min-radius},
 *                      {@code max-radius}, {@code draft}
 * @param checker       checker squares per unit (u,v) on patches; 0 = material's own
 * @param shadows       shadow rays on
 * @param maxDepth      hard cap on the reflection/refraction depth, 0..{@value #MAX_DEPTH}
 */
public record RenderSettings(int width, int height, int spp, String sampler, String method, boolean bvh,
                             String shading, int checker, boolean shadows, int maxDepth) {

    public static final int MAX_SIZE = 16384;
    public static final int MAX_SPP = 1024;
    public static final int MAX_DEPTH = 32;
    /** Most pixels in one image (about 64 Mpixels), so a frame buffer always fits in memory. */
    public static final long MAX_PIXELS = 1L << 26;
    public static final Set<String> SAMPLERS = Set.of("regular", "jittered", "adaptive");
    /**
     * What a method's name may look like here: one word of letters, digits, _ or -
     * ({@code intersect.Method} says which).
     */
    private static final Pattern WORD = Pattern.compile("[\\p{L}\\p{N}_-]+");
    public static final Set<String> SHADINGS = Set.of("phong", "flat", "normals", "uv", "patch-id", "zebra", "emap", "isophotes",
            "gaussian", "mean", "min-radius", "max-radius", "draft");

    public RenderSettings {
        if (width < 1 || width > MAX_SIZE || height < 1 || height > MAX_SIZE) {
            throw new IllegalArgumentException("image size must be 1.." + MAX_SIZE + " in each direction, got "
                    + width + "x" + height);
        }
        if ((long) width * height > MAX_PIXELS) {
            throw new IllegalArgumentException("image of " + width + "x" + height + " pixels is too large (at most "
                    + MAX_PIXELS + " pixels)");
        }
        if (spp < 1 || spp > MAX_SPP) {
            throw new IllegalArgumentException("samples per pixel must be 1.." + MAX_SPP + ", got " + spp);
        }
        if (maxDepth < 0 || maxDepth > MAX_DEPTH) {
            throw new IllegalArgumentException("depth must be 0.." + MAX_DEPTH + ", got " + maxDepth);
        }
        if (checker < 0 || checker > 10_000) {
            throw new IllegalArgumentException("checker squares must be 0..10000, got " + checker);
        }
        sampler = oneOf("sampler", sampler, SAMPLERS);
        method = word("method", method);
        shading = oneOf("shading", shading, SHADINGS);
    }

    private static String oneOf(String what, String value, Set<String> allowed) {
        String v = value == null ? "" : value.trim().toLowerCase(Locale.ROOT);
        if (!allowed.contains(v)) {
            throw new IllegalArgumentException("unknown " + what + " " + echo(value, '\'') + ": expected one of "
                    + String.join(", ", allowed.stream().sorted().toList()));
        }
        return v;
    }

    /**
     * {@code value} in double quotes for a message: control characters and line separators as {@code \\uXXXX}, cut to
     * 60 characters (the model layer's copy of {@code model.io.Echo.quote}, which it cannot use).
     */
    static String echo(String value) {
        return echo(value, '"');
    }

    /** {@link #echo(String)} between {@code quote} characters. */
    static String echo(String value, char quote) {
        StringBuilder sb = new StringBuilder().append(quote);
        String v = value == null ? "" : value;
        for (int i = 0; i < v.length() && sb.length() <= 60; i++) {
            char c = v.charAt(i);
            boolean hidden = Character.isISOControl(c) || c == 0x2028 || c == 0x2029 || c == 0xFEFF; // as Echo.cut
            sb.append(hidden ? String.format(Locale.ROOT, "\\u%04X", (int) c) : String.valueOf(c));
        }
        return sb.append(v.length() > 60 ? "…" : "").append(quote).toString();
    }

    /** {@code value} trimmed and in lower case, refused unless it is one {@link #WORD}. */
    private static String word(String what, String value) {
        String v = value == null ? "" : value.trim().toLowerCase(Locale.ROOT);
        if (!WORD.matcher(v).matches()) {
            throw new IllegalArgumentException(what + " must be a name (one word), got " + echo(value));
        }
        return v;
    }

    /**
     * What a file that says nothing starts from; its method, {@code clipping}, is
     * {@code IntersectOptions.defaults()}'s.
     */
    public static RenderSettings defaults() {
        return new RenderSettings(800, 600, 1, "regular", "clipping", true, "phong", 0, true, 5);
    }
}
