package org.beziertracer.model.io;

import java.io.IOException;

/**
 * How far a model save or a mesh export got, in patches: a writer calls it on its own thread every
 * {@value #STEP} patches (or a step of its own) and once at the end. It may throw (an {@link java.io.InterruptedIOException}
 * when the save is cancelled) to stop the save; an atomic save then leaves the old file as it was
 * ({@link AtomicFiles}).
 */
@FunctionalInterface
public interface WriteProgress {

    /** Patches between two reports. */
    int STEP = 1024;

    /** Reports nothing. */
    WriteProgress NONE = (done, total) -> { };

    /** {@code done} of the model's {@code total} patches are written (or prepared, for the CAD writers). */
    void patches(int done, int total) throws IOException;

    /** Reports {@code done} when it is a multiple of {@link #STEP} or the last. */
    default void patch(int done, int total) throws IOException {
        patch(done, total, STEP);
    }

    /**
     * Reports {@code done} when it is a multiple of {@code step} or the last: for writers whose
     * patches are each much bigger than a model's (a tessellated patch is some 1,400 lines).
     */
    default void patch(int done, int total, int step) throws IOException {
        if (done % step == 0 || done == total) {
            patches(done, total);
        }
    }
}
