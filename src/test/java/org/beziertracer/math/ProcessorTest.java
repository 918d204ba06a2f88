package org.beziertracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.lang.management.ManagementFactory;

import com.sun.management.HotSpotDiagnosticMXBean;
import org.junit.jupiter.api.Test;

class ProcessorTest {

    private static String option(String name) {
        return ManagementFactory.getPlatformMXBean(HotSpotDiagnosticMXBean.class).getVMOption(name).getValue();
    }

    @Test
    void roundsTheProductThenTheSumOnEveryProcessor() {
        // (1 + 2^-30)(1 - 2^-30) = 1 - 2^-60: the product alone rounds to 1, so an unfused
        // multiply-add gives 0 where a fused one would give -2^-60 (a picture would then differ
        // between processors with and without the instruction)
        double a = 1 + 0x1p-30, b = 1 - 0x1p-30;
        assertEquals(0.0, Processor.mad(a, b, -1));
        assertEquals(7.0, Processor.mad(2, 3, 1));
    }

    @Test
    void aWideRegisterFileIsAArch64OrAvx512() {
        boolean aarch64 = "aarch64".equals(System.getProperty("os.arch"));
        boolean avx512 = !aarch64 && Long.parseLong(option("UseAVX")) >= 3;
        assertEquals(aarch64 || avx512, Processor.WIDE_REGISTER_FILE);
    }

    @Test
    void optionsReadAsFlagsOrNumbersAndUnknownOnesAreOff() {
        assertEquals(Boolean.parseBoolean(option("UseFMA")), Processor.option("UseFMA", 1));
        assertFalse(Processor.option("NoSuchOptionAnywhere", 0));
    }
}
