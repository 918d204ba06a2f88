package org.beziertracer.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;

import org.beziertracer.model.io.Echo;
import org.beziertracer.model.io.IoReasons;
import org.beziertracer.model.io.TextSource;

/** Rays from text, one a line; errors name the source and line. */
final class RayFile implements RaySource {
    private final InputStream in;
    private final TextSource text;
    private final String name;

    /** Rays of {@code in} (closed by {@link #close()} unless it is standard input). */
    RayFile(InputStream in, String name) {
        this.in = in;
        this.text = new TextSource(in, name);
        this.name = name;
    }

    @Override
    public boolean next(double[] ray) throws IOException {
        String line;
        while ((line = readLine()) != null) {
            int lineNumber = text.lineNumber();
            int hash = line.indexOf('#');
            String text = (hash >= 0 ? line.substring(0, hash) : line).trim();
            if (text.isEmpty()) {
                continue;
            }
            String[] parts = text.split("\\s+");
            if (parts.length != 6) {
                throw new IllegalArgumentException(name + ":" + lineNumber + ": expected 6 numbers "
                        + "\"ox oy oz dx dy dz\", found " + parts.length + (parts.length == 1 ? " field" : " fields"));
            }
            for (int k = 0; k < 6; k++) {
                try {
                    ray[k] = Double.parseDouble(parts[k]);
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException(name + ":" + lineNumber + ": expected a number for "
                            + "oxoyozdxdydz".substring(2 * k, 2 * k + 2) + ", found " + Echo.quote(parts[k]));
                }
                if (!Double.isFinite(ray[k])) {
                    throw new IllegalArgumentException(name + ":" + lineNumber + ": "
                            + "oxoyozdxdydz".substring(2 * k, 2 * k + 2) + " must be finite, found "
                            + Echo.quote(parts[k]));
                }
            }
            if (ray[3] == 0 && ray[4] == 0 && ray[5] == 0) {
                throw new IllegalArgumentException(name + ":" + lineNumber + ": the ray direction is zero");
            }
            double big = Math.max(Math.abs(ray[3]), Math.max(Math.abs(ray[4]), Math.abs(ray[5])));
            if (big < 1e-300 || big > 1e300) {
                throw new IllegalArgumentException(name + ":" + lineNumber + ": the ray direction's length must be "
                        + "between 1e-300 and 1e300, found a largest component of " + big);
            }
            return true;
        }
        return false;
    }

    /**
     * The next line; a failed read names the ray file (the hits may be going to an atomic save,
     * whose own errors name the output, so the failure travels unchecked).
     */
    private String readLine() {
        try {
            return text.readLine();
        } catch (IOException e) {
            throw new UncheckedIOException(new IOException(name + ": cannot read: " + IoReasons.of(e)));
        }
    }

    @Override
    public void close() throws IOException {
        if (in != System.in) {
            in.close();
        }
    }
}
