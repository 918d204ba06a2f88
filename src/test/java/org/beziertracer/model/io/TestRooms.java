package org.beziertracer.model.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Small scene files the tests of several layers write. */
public final class TestRooms {
    private TestRooms() {}

    /**
     * {@code dir/room.json}: one unit sphere, its {@code render.method} set to {@code method}, lit by
     * a light above it when {@code lit} (else by the renderer's light at the eye).
     */
    public static Path withMethod(Path dir, String method, boolean lit) throws IOException {
        Path p = dir.resolve("room.json");
        Files.writeString(p, "{\"version\": 1, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1}],"
                + (lit ? " \"lights\": [{\"position\": [0, 0, 50]}]," : "")
                + " \"render\": {\"method\": \"" + method + "\"}}");
        return p;
    }
}
