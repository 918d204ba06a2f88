package org.beziertracer.bench.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordedFrame;
import jdk.jfr.consumer.RecordedStackTrace;
import jdk.jfr.consumer.RecordingFile;

/**
 * Aggregates the {@code jdk.ExecutionSample} events of a JFR recording into the methods where the
 * samples were (self) and the methods on their stacks (inclusive), in per cent of the samples of
 * the render threads (threads named {@code render-worker-*}; {@code --all} counts every thread).
 * Record a frame loop with, for example,
 * {@code java -XX:StartFlightRecording=filename=patch.jfr,settings=profile -jar target/beziertracer.jar
 * render patch -o /tmp/p.png --size 800x600 --repeat 40}, then run
 * {@code java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.JfrTop patch.jfr [N]}.
 */
public final class JfrTop {
    private JfrTop() {}

    public static void main(String[] args) throws IOException {
        Path file = null;
        int top = 25;
        boolean all = false;
        for (String a : args) {
            if (a.equals("--all")) {
                all = true;
            } else if (file == null) {
                file = Path.of(a);
            } else {
                top = Integer.parseInt(a);
            }
        }
        if (file == null) {
            System.err.println("usage: JfrTop FILE.jfr [N] [--all]");
            System.exit(2);
        }
        Map<String, Integer> self = new HashMap<>(), inclusive = new HashMap<>();
        int samples = 0;
        for (RecordedEvent e : RecordingFile.readAllEvents(file)) {
            if (!e.getEventType().getName().equals("jdk.ExecutionSample")) {
                continue;
            }
            String thread = e.getThread("sampledThread") == null ? "" : e.getThread("sampledThread").getJavaName();
            if (!all && (thread == null || !thread.startsWith("render-worker"))) {
                continue;
            }
            RecordedStackTrace st = e.getStackTrace();
            if (st == null || st.getFrames().isEmpty()) {
                continue;
            }
            samples++;
            List<RecordedFrame> frames = st.getFrames();
            self.merge(name(frames.get(0)), 1, Integer::sum);
            Set<String> seen = new HashSet<>();
            for (RecordedFrame f : frames) {
                String n = name(f);
                if (seen.add(n)) {
                    inclusive.merge(n, 1, Integer::sum);
                }
            }
        }
        System.out.printf(Locale.ROOT, "%s: %d samples%n", file, samples);
        print("self", self, samples, top);
        print("inclusive", inclusive, samples, top);
    }

    private static String name(RecordedFrame f) {
        String type = f.getMethod().getType().getName();
        return type.substring(type.lastIndexOf('.') + 1) + "." + f.getMethod().getName();
    }

    private static void print(String title, Map<String, Integer> counts, int samples, int top) {
        System.out.println("-- " + title);
        counts.entrySet().stream().sorted((a, b) -> b.getValue() - a.getValue()).limit(top)
                .forEach(en -> System.out.printf(Locale.ROOT, "%6.1f%%  %s%n", 100.0 * en.getValue() / samples,
                        en.getKey()));
    }
}
