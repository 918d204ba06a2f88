package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import org.beziertracer.ChildJvm;
import org.beziertracer.Main;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The same pictures with and without the Vector API module: a JVM started without
 * {@code --add-modules jdk.incubator.vector} runs the scalar kernel (and says so), one started with
 * it runs the SIMD kernel; their PNGs are the same bytes and their work counts the same numbers, on
 * the degree-9 and degree-5 wavy grids, the curved bicubic with its shadows and the teapot room.
 */
class KernelChoiceTest {

    private static final String VECTOR = "--add-modules=jdk.incubator.vector";

    @Test
    void versionSaysWhichKernelRuns(@TempDir Path dir) throws IOException, InterruptedException {
        ChildJvm.Result plain = ChildJvm.run(dir, List.of(), Main.class.getName(), "--version");
        assertEquals(0, plain.code(), plain.err());
        assertTrue(plain.out().contains("kernel: scalar: start Java with --add-modules jdk.incubator.vector"),
                plain.out());
        ChildJvm.Result simd = ChildJvm.run(dir, List.of(VECTOR), Main.class.getName(), "--version");
        assertTrue(simd.out().matches("(?s).*kernel: SIMD, \\d+ double lanes.*"), simd.out());
    }

    @Test
    void picturesAreTheSameBytesWithAndWithoutTheVectorModule(@TempDir Path dir)
            throws IOException, InterruptedException {
        for (String model : new String[] {"wavy10", "wavy6", "curved", "teapot-room"}) {
            JsonObject scalar = render(dir, model, List.of(), "scalar.png");
            JsonObject simd = render(dir, model, List.of(VECTOR), "simd.png");
            assertTrue(scalar.get("kernel").getAsString().startsWith("scalar"), scalar.toString());
            assertTrue(simd.get("kernel").getAsString().startsWith("SIMD"), simd.toString());
            assertArrayEquals(Files.readAllBytes(dir.resolve("scalar.png")), Files.readAllBytes(dir.resolve("simd.png")),
                    model + ": the PNGs differ");
            for (String work : new String[] {"solverCalls", "clipSteps", "patchEvaluations", "laneEvaluations"}) {
                assertEquals(scalar.get(work).getAsLong(), simd.get(work).getAsLong(), model + ": " + work);
            }
            if (!model.equals("teapot-room")) {
                assertTrue(simd.get("laneEvaluations").getAsLong() > 0, model + ": " + simd);
            }
        }
    }

    private static JsonObject render(Path dir, String model, List<String> jvm, String png)
            throws IOException, InterruptedException {
        ChildJvm.Result r = ChildJvm.run(dir, jvm, Main.class.getName(), "render", model, "-o",
                dir.resolve(png).toString(), "--size", "200x150", "--threads", "1", "--stats");
        assertEquals(0, r.code(), model + ": " + r.err());
        return JsonParser.parseString(r.out().trim()).getAsJsonObject();
    }
}
