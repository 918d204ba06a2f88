package org.beziertracer.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real multi-process path (issue 37): Spark's {@code local-cluster[2,1,1024]} runs a master, two
 * workers and two executor JVMs; tasks, the broadcast job and the tiles cross process boundaries, and the
 * assembled frames are still the one-machine render byte for byte.
 *
 * <p>The executors are started by Spark's launcher, which looks for {@code $SPARK_HOME/jars} (surefire sets
 * {@code SPARK_HOME} to {@code target/spark-home}; this test makes its empty {@code jars/}) and gets our
 * classes and Spark's from {@code spark.executor.extraClassPath} = this JVM's class path.
 */
class LocalClusterTest {

    @TempDir
    Path dir;

    @Test
    void twoExecutorJvmsRenderTheFramesOfTheOneMachineRenderByteForByte() throws Exception {
        String home = System.getenv("SPARK_HOME");
        assertTrue(home != null, "surefire sets SPARK_HOME (see spark/pom.xml)");
        Files.createDirectories(Path.of(home, "jars"));
        Path job = SparkJobs.job(dir, "");
        SparkJobs.renderOnOneMachine(job, dir);
        Path out = dir.resolve("out");
        System.setProperty("spark.executor.extraClassPath", classPath());
        System.setProperty("spark.executor.memory", "512m");
        SparkJobs.Result r;
        try {
            r = SparkJobs.run(job.toString(), out.toString(), "--tiles", "4", "--master", "local-cluster[2,1,1024]");
        } finally {
            System.clearProperty("spark.executor.extraClassPath");
            System.clearProperty("spark.executor.memory");
        }
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("8 tiles rendered, 0 already there; 2 frames assembled"), r.out());
        SparkJobs.assertExecutorsUseThisJvmsKernel(r.out());
        assertEquals(0, JobSource.loadCount() - loadsBefore, "the executors are other JVMs: this one loaded nothing");
        assertEquals(0, FrameAssembler.assembledCount() - assembledBefore,
                "the frames were assembled by tasks in the executor JVMs, not by the driver");
        SparkJobs.assertSameFrames(dir, out, "local-cluster[2,1,1024]");
    }

    private final int loadsBefore = JobSource.loadCount();
    private final int assembledBefore = FrameAssembler.assembledCount();

    /** This JVM's class path (surefire's manifest-only jar opened into its entries when it is one). */
    static String classPath() throws Exception {
        String cp = System.getProperty("java.class.path");
        String[] parts = cp.split(File.pathSeparator);
        if (parts.length == 1 && parts[0].endsWith(".jar")) {
            try (java.util.jar.JarFile jar = new java.util.jar.JarFile(parts[0])) {
                String manifestCp = jar.getManifest().getMainAttributes().getValue("Class-Path");
                if (manifestCp != null) {
                    StringBuilder sb = new StringBuilder();
                    for (String u : manifestCp.trim().split("\\s+")) {
                        sb.append(sb.length() == 0 ? "" : File.pathSeparator)
                                .append(new File(new java.net.URI(u).getPath()).getPath());
                    }
                    return sb.toString();
                }
            }
        }
        return cp;
    }
}
