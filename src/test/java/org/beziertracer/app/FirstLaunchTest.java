package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.ChildJvm;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The first launch with a fresh home says nothing on standard error (issue 36). */
class FirstLaunchTest {

    @TempDir
    Path dir;

    @Test
    void aFreshHomeGetsItsPreferencesFolderWithoutALineOnStandardError() throws Exception {
        Path home = Files.createDirectory(dir.resolve("home"));
        ChildJvm.Result r = ChildJvm.run(dir, List.of("-Duser.home=" + home), PreferencesProbe.class.getName());
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err(), "standard error of a first launch");
        assertEquals("dark", r.out().strip(), "the preference was kept");
        assertTrue(Files.isDirectory(home.resolve(".java/.userPrefs")));
    }
}
