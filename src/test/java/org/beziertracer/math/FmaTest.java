package org.beziertracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.management.ManagementFactory;

import com.sun.management.HotSpotDiagnosticMXBean;
import org.junit.jupiter.api.Test;

class FmaTest {

    @Test
    void fusesExactlyWhenTheVirtualMachineHasTheInstruction() {
        HotSpotDiagnosticMXBean vm = ManagementFactory.getPlatformMXBean(HotSpotDiagnosticMXBean.class);
        assertEquals(Boolean.parseBoolean(vm.getVMOption("UseFMA").getValue()), Fma.FUSED);
    }

    @Test
    void roundsOnceWhenFusedAndTwiceOtherwise() {
        // (1 + 2^-30)(1 - 2^-30) = 1 - 2^-60: the product alone rounds to 1
        double a = 1 + 0x1p-30, b = 1 - 0x1p-30;
        assertEquals(Fma.FUSED ? -0x1p-60 : 0.0, Fma.mad(a, b, -1));
        assertEquals(7.0, Fma.mad(2, 3, 1));
    }
}
