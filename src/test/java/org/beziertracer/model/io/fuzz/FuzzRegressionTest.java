package org.beziertracer.model.io.fuzz;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Replays every mutant that ever failed the fuzzer (src/test/resources/fuzz/regressions/FORMAT/):
 * each must now load or fail with one line naming the file, within the time limit.
 */
class FuzzRegressionTest {

    @TempDir
    Path work;

    @Test
    void everyKeptMutantNowLoadsOrFailsWithOneLineNamingTheFile() throws IOException, InterruptedException {
        FuzzHarness.Failures failures = new FuzzHarness.Failures();
        int replayed = 0;
        try (FuzzHarness harness = new FuzzHarness(work)) {
            for (String format : List.of("bpt", "obj", "igs", "stp", "json")) {
                for (Path p : FuzzHarness.files(FuzzHarness.REGRESSIONS, format)) {
                    String problem = harness.judgeFile(format, "replay." + format, Files.readAllBytes(p));
                    replayed++;
                    if (problem != null) {
                        failures.add(format + "/" + p.getFileName() + ": " + problem);
                    }
                }
            }
        }
        assertTrue(replayed > 0, "no regression files found");
        assertTrue(failures.isEmpty(), () -> failures.report("kept mutants"));
    }
}
