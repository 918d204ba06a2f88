package org.beziertracer.model.io.fuzz;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.io.ReadLimits;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Seeded mutation fuzzing of every reader, through the format registry: each format's
 * seed files (src/test/resources/fuzz/seeds/FORMAT/ — drop a file there to add a seed) give
 * {@value #DEFAULT_MUTANTS} mutants (or {@code -Dfuzz.mutants=N}) from seed {@code -Dfuzz.seed}
 * (default {@value #DEFAULT_SEED}). Each mutant must load, or fail with one line naming the file,
 * within {@value FuzzHarness#TIMEOUT_SECONDS} s, never with an error or a stack trace. Failing
 * mutants are kept under target/fuzz-failures/ to be copied into the regression folder.
 */
class MutationFuzzTest {

    static final int DEFAULT_MUTANTS = 2000;
    static final long DEFAULT_SEED = 20_240_517L;

    @TempDir
    Path work;

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"bpt", "obj", "igs", "stp", "json"})
    void everyMutantLoadsOrFailsWithOneLineNamingTheFile(String format) throws IOException, InterruptedException {
        int mutants = Integer.getInteger("fuzz.mutants", DEFAULT_MUTANTS);
        long seed = Long.getLong("fuzz.seed", DEFAULT_SEED);
        List<Path> seeds = FuzzHarness.files(FuzzHarness.SEEDS, format);
        assertTrue(seeds.size() >= 3, "at least three " + format + " seeds, found " + seeds);
        List<byte[]> seedBytes = new ArrayList<>();
        Mutator mutator = new Mutator(ReadLimits.DEFAULT.lineChars() + 1);
        FuzzHarness.Failures failures = new FuzzHarness.Failures();
        try (FuzzHarness harness = new FuzzHarness(work)) {
            for (Path s : seeds) {
                seedBytes.add(Files.readAllBytes(s));
                assertNull(harness.judgeFile(format, "seed." + format, seedBytes.get(seedBytes.size() - 1)),
                        "the seed " + s.getFileName() + " itself must load cleanly");
            }
            Random rnd = new Random(seed ^ format.hashCode());
            for (int k = 0; k < mutants; k++) {
                int which = k % seedBytes.size();
                List<String> applied = new ArrayList<>();
                byte[] mutant = mutator.mutate(seedBytes.get(which), rnd, applied);
                String name = "mutant." + format;
                String problem = harness.judge(format, name, mutant);
                if (problem != null) {
                    String what = seeds.get(which).getFileName() + " + " + applied + ": " + problem;
                    Path kept = FuzzHarness.keep(format, "fuzz-" + seed + "-" + k + "." + format, mutant, what);
                    failures.add(kept.getFileName() + ": " + what);
                }
            }
        }
        assertTrue(failures.isEmpty(), () -> failures.report(format + " mutants"));
    }
}
