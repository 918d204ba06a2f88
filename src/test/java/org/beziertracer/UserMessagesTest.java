package org.beziertracer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;

/**
 * The message test: every error-case test in the suite routes its expected error through
 * {@link UserMessages}; this class runs last (see {@code junit-platform.properties}) and checks
 * everything gathered — no Java exception class name, no {@code java.} package, no word
 * {@code null}, no stack-trace line, exactly one line each.
 */
@Order(Integer.MAX_VALUE)
class UserMessagesTest {

    @Test
    void theCheckFlagsJavaNamesTheWordNullAndLineBreaks() {
        for (String bad : List.of("m.bpt: cannot read: MalformedInputException Input length = 1",
                "beziertracer render: Cannot invoke \"java.nio.file.Path.toString()\" because the return value of"
                        + " \"java.nio.file.Path.getFileName()\" is null",
                "trace: OutOfMemoryError", "x: java.lang.IllegalStateException", "value is null", "Null value",
                "two\nlines", "two\u2028lines", "at org.beziertracer.Main.main(Main.java:12)", "", "Error: boom")) {
            assertNotNull(UserMessages.problem(bad), bad);
        }
        for (String good : List.of("scene.json: objects[3].material.diffuse[1]: expected a number, found \"x\"",
                "teapot.bpt: cannot write: permission denied", "m.obj:3: unsupported: trim (trimmed surfaces)",
                "t.bpt:1: expected the patch count, found \"null\"", "a.json: radius: expected a positive number,"
                        + " found no value", "input/output error")) {
            assertNull(UserMessages.problem(good), good);
        }
    }

    @Test
    void everyGatheredErrorMessageIsOneLineWithoutJavaNamesOrNull() {
        List<UserMessages.Gathered> all = UserMessages.gathered();
        Assumptions.assumeFalse(all.isEmpty(),
                "nothing gathered: run this test with the suite (it checks what the other tests gathered)");
        Map<String, Integer> perClass = new TreeMap<>();
        StringBuilder bad = new StringBuilder();
        for (UserMessages.Gathered g : all) {
            perClass.merge(g.testClass().replaceFirst("^org\\.beziertracer\\.", ""), 1, Integer::sum);
            String problem = UserMessages.problem(g.message());
            if (problem != null) {
                bad.append('\n').append(g.testClass()).append(": ").append(problem).append(": ").append(g.message());
            }
        }
        System.out.println("UserMessagesTest: " + all.size() + " error messages gathered from " + perClass);
        assertEquals("", bad.toString(), "messages unfit for a user");
    }
}
