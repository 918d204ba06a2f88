package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.math.Kernels;
import org.junit.jupiter.api.Test;

class AboutTextTest {

    @Test
    void aboutNamesTheJavaVersionAndTheKernelThatRuns() {
        String text = AboutText.text();
        assertTrue(text.contains("Java " + System.getProperty("java.version")), text);
        assertTrue(text.endsWith("kernel: " + Kernels.best().description()), text);
        // the test JVM runs with the Vector API module (pom.xml), so About says SIMD
        assertTrue(text.contains("kernel: SIMD, "), text);
    }
}
