package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;

import org.junit.jupiter.api.Test;

class ErrorTextTest {

    @Test
    void aMessageForUsersIsKeptOnOneLine() {
        assertEquals("teapot.bpt:3: expected a number, found \"x\" (line 3)",
                ErrorText.oneLine(new IllegalArgumentException("teapot.bpt:3: expected a number,\n found \"x\" (line 3)")));
    }

    @Test
    void classNamesNullAndEmptyMessagesBecomeASentence() {
        List<Throwable> internal = List.of(new NullPointerException(),
                new NullPointerException("Cannot invoke \"java.nio.file.Path.toString()\" because the value is null"),
                new IllegalStateException("failed: java.lang.ArithmeticException"),
                new IOException("ClosedByInterruptException"), new RuntimeException(" "));
        for (Throwable e : internal) {
            String line = ErrorText.oneLine(e);
            assertEquals("an internal error occurred (details on the console)", line, String.valueOf(e));
        }
    }

    @Test
    void memoryAndStackErrorsSaySoWithoutTheirClassName() {
        String oom = ErrorText.oneLine(new OutOfMemoryError("Java heap space"));
        assertTrue(oom.startsWith("not enough memory: this Java allows "), oom);
        assertTrue(oom.contains("-Xmx"), oom);
        for (String line : List.of(oom, ErrorText.oneLine(new StackOverflowError()))) {
            assertFalse(line.contains("Error") || line.contains("null") || line.contains("\n"), line);
        }
    }

    @Test
    void aVeryLongMessageIsCut() {
        String line = ErrorText.oneLine(new IllegalArgumentException("x".repeat(5000)));
        assertEquals(ErrorText.MAX_LENGTH, line.length());
        assertTrue(line.endsWith("…"));
    }
}
