package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Seeded mutation fuzzing of the command line (issue 36): {@value #MUTANTS} mutants (or
 * {@code -Dfuzz.cli.mutants=N}, seed {@code -Dfuzz.cli.seed}) of valid {@code render}, {@code trace},
 * {@code info} and {@code analyze} lines with small images — an argument deleted, doubled, swapped,
 * replaced by a hostile value, an option added, the command changed — each run in this JVM through
 * picocli. Each must end in exit 0, or in exactly one line on standard error that
 * {@link UserMessages} accepts (no stack trace, no Java name), within {@value #TIMEOUT_SECONDS} s.
 * Files go to a temporary folder: a path a mutant puts after {@code -o} or {@code -i} is moved
 * there, and the working folder is checked to be left as it was.
 */
class CommandLineFuzzTest {

    static final int MUTANTS = 200;
    static final long SEED = 36;
    static final int TIMEOUT_SECONDS = 30;

    /** Values that have broken command lines before: empty, signs, overflows, separators, devices. */
    private static final List<String> HOSTILE = List.of("", " ", "-1", "0", "2", "abc", "1e308", "-1e308", "NaN",
            "Infinity", "99999999999", "0,0,0", "1,2", "1,2,3,4", "-1e308,0,0", "1e308,0,0", "0x0", "8x", "x8", "-8x8",
            "2x2", "/", "/dev/null", "/dev/full", "-", "--", "é", "a\nb", "%s %n", "${x}", "'", "\"", "1_000",
            "clipping", "newton", "subdivision", "checker:0", "checker:3", "zebra", "teapot", "patch", "none", "tent",
            "jittered", "adaptive", "x".repeat(300));

    private static final List<String> OPTIONS = List.of("--size", "--spp", "--sampler", "--filter", "--method",
            "--tessellate", "--kernel", "--shading", "--analysis", "--texture", "--eye", "--target", "--up", "--fov",
            "--light", "--depth", "--threads", "--repeat", "--pixel", "--difference-to", "--random", "--seed", "-i",
            "-o", "--curvature", "--stats", "--no-bvh", "--no-shadows", "-q", "--help", "--version", "--json",
            "--g0", "--unknown");

    private static final Set<String> PATH_OPTIONS = Set.of("-o", "--output", "-i", "--input");

    @TempDir
    Path dir;

    private List<List<String>> seeds() throws IOException {
        Path rays = Files.writeString(dir.resolve("rays.txt"), "0 0 10 0 0 -1\n0.5 0.5 10 0 0 -1\n");
        String png = dir.resolve("out.png").toString(), csv = dir.resolve("hits.csv").toString();
        return List.of(
                List.of("info", "patch"),
                List.of("info", "teapot"),
                List.of("trace", "patch", "--random", "20", "--seed", "3"),
                List.of("trace", "teapot", "-i", rays.toString(), "-o", csv, "--curvature"),
                List.of("render", "patch", "--size", "8x6", "-o", png, "--threads", "1"),
                List.of("render", "teapot", "--size", "6x4", "-o", png, "--stats", "--shading", "normals"),
                List.of("render", "patch", "--size", "4x4", "--pixel", "1,1", "--eye", "0,-5,5", "--target", "0,0,0"),
                List.of("render", "sphere", "--size", "6x6", "-o", png, "--spp", "2", "--sampler", "jittered"),
                List.of("analyze", "patch"));
    }

    /** One mutation of {@code args}; what was done is added to {@code applied}. */
    private static List<String> mutate(List<String> args, Random rnd, List<String> applied) {
        List<String> a = new ArrayList<>(args);
        int k = a.isEmpty() ? 0 : rnd.nextInt(a.size());
        switch (rnd.nextInt(7)) {
            case 0 -> {
                if (!a.isEmpty()) {
                    applied.add("delete " + a.remove(k));
                }
            }
            case 1 -> {
                if (!a.isEmpty()) {
                    a.add(k, a.get(k));
                    applied.add("double " + a.get(k));
                }
            }
            case 2 -> {
                if (a.size() > 1) {
                    int j = rnd.nextInt(a.size());
                    String t = a.get(k);
                    a.set(k, a.get(j));
                    a.set(j, t);
                    applied.add("swap " + k + "," + j);
                }
            }
            case 3, 4 -> {
                if (!a.isEmpty()) {
                    String v = HOSTILE.get(rnd.nextInt(HOSTILE.size()));
                    applied.add("replace " + a.get(k) + " by " + v);
                    a.set(k, v);
                }
            }
            case 5 -> {
                String o = OPTIONS.get(rnd.nextInt(OPTIONS.size())), v = HOSTILE.get(rnd.nextInt(HOSTILE.size()));
                a.add(o);
                a.add(v);
                applied.add("add " + o + " " + v);
            }
            default -> {
                String c = List.of("info", "trace", "render", "analyze", "nonsense", "--help").get(rnd.nextInt(6));
                applied.add("command " + c);
                if (a.isEmpty()) {
                    a.add(c);
                } else {
                    a.set(0, c);
                }
            }
        }
        return a;
    }

    /** Moves a relative path after -o / -i into the temporary folder, so that no mutant writes elsewhere. */
    private List<String> confine(List<String> args) {
        List<String> a = new ArrayList<>(args);
        for (int k = 1; k < a.size(); k++) {
            String v = a.get(k);
            if (PATH_OPTIONS.contains(a.get(k - 1)) && !v.isEmpty() && !v.startsWith("/") && !OPTIONS.contains(v)) {
                a.set(k, dir.resolve("confined").resolve(v.replace('\n', '_')).toString());
            }
        }
        return a;
    }

    private static List<String> listing(Path folder) throws IOException {
        try (Stream<Path> s = Files.list(folder)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    /**
     * Null when the run is acceptable, else why not. The mutant's own arguments are the user's
     * words, shown as given (a model named {@code /dev/null}): they count as quoted input, not as
     * a leaked Java {@code null}.
     */
    private static String judge(Run r, List<String> args) {
        List<String> lines = r.err().lines().toList();
        for (String line : lines) {
            if (line.contains("Exception") || line.contains("\tat ") || line.startsWith("Caused by")) {
                return "a Java trace on standard error: " + line;
            }
        }
        if (r.code() == 0) {
            return null;
        }
        if (lines.size() != 1) {
            return "exit " + r.code() + " with " + lines.size() + " lines on standard error: " + r.err();
        }
        String line = lines.get(0);
        for (String arg : args) {
            if (arg.length() > 1 && !arg.startsWith("-")) {
                line = line.replace(arg, "\"…\"");
            }
        }
        String problem = UserMessages.gather(line);
        return problem == null ? null : "the error line " + problem + ": " + lines.get(0);
    }

    @Test
    void everyMutantSucceedsOrFailsInOneLine() throws Exception {
        int mutants = Integer.getInteger("fuzz.cli.mutants", MUTANTS);
        long seed = Long.getLong("fuzz.cli.seed", SEED);
        Files.createDirectories(dir.resolve("confined"));
        List<List<String>> seeds = seeds();
        Path cwd = Path.of("").toAbsolutePath();
        List<String> before = listing(cwd);
        for (List<String> s : seeds) {
            Run r = Run.of(s.toArray(String[]::new));
            assertEquals(0, r.code(), "the seed " + s + " itself must succeed: " + r.err());
        }
        Random rnd = new Random(seed);
        List<String> failures = new ArrayList<>();
        int succeeded = 0;
        ExecutorService runner = Executors.newSingleThreadExecutor(t -> {
            Thread th = new Thread(t, "cli-fuzz");
            th.setDaemon(true);
            return th;
        });
        try {
            for (int k = 0; k < mutants; k++) {
                List<String> applied = new ArrayList<>();
                List<String> args = seeds.get(k % seeds.size());
                for (int m = 1 + rnd.nextInt(2); m > 0; m--) {
                    args = mutate(args, rnd, applied);
                }
                List<String> mutant = confine(args);
                Future<Run> run = runner.submit(() -> Run.of(mutant.toArray(String[]::new)));
                Run r;
                try {
                    r = run.get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
                } catch (TimeoutException e) {
                    failures.add("mutant " + k + " " + mutant + ": still running after " + TIMEOUT_SECONDS + " s");
                    break; // the runner thread is taken
                }
                String problem = judge(r, mutant);
                if (problem != null) {
                    failures.add("mutant " + k + " " + mutant + " (" + applied + "): " + problem);
                } else if (r.code() == 0) {
                    succeeded++;
                }
            }
        } finally {
            runner.shutdownNow();
        }
        assertEquals(List.of(), failures, failures.size() + " of " + mutants + " mutants failed");
        assertEquals(before, listing(cwd), "no mutant wrote into the working folder");
        for (Path folder : List.of(dir, dir.resolve("confined"))) {
            assertEquals(List.of(), listing(folder).stream().filter(n -> n.endsWith(".tmp")).toList(),
                    "no temporary file of an atomic save is left in " + folder);
        }
        assertTrue(succeeded > 0 && succeeded < mutants, "both outcomes occur: " + succeeded + " succeeded");
    }
}
