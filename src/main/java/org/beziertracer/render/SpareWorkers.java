package org.beziertracer.render;

import java.util.Iterator;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The {@link RenderWorker}s of the pool threads of closed {@link RenderSession}s, kept for the
 * threads of the next sessions: a one-shot render ({@link Renderer#renderOnce}, the CLI's
 * {@code --repeat}, a benchmark's frame) starts a new session with new threads every time, and each
 * new worker would allocate and zero its query contexts' scratch again (about half a megabyte a
 * thread) for the collector to take back after the frame.
 *
 * <p>A worker left here holds no scene (its threads {@linkplain RenderWorker#release release}
 * it after every pass), only its scratch, so the spares keep no model alive; at most {@link #LIMIT}
 * are kept. A worker is reused only for a job it {@linkplain RenderWorker#fits fits} (the kernel of
 * its contexts), and it first forgets what its earlier renders left in its contexts that could
 * change the work (not the answers) of the next ({@link RenderWorker#forgetHistory}), so a
 * one-thread render counts the same work as on new threads. Thread-safe.
 */
final class SpareWorkers {
    private SpareWorkers() {}

    /** Most spare workers kept (more threads than this end without leaving theirs). */
    static final int LIMIT = Math.max(2, Runtime.getRuntime().availableProcessors());

    private static final ConcurrentLinkedQueue<RenderWorker> SPARE = new ConcurrentLinkedQueue<>();
    private static final AtomicInteger COUNT = new AtomicInteger();
    private static final AtomicInteger REUSES = new AtomicInteger();

    /** A spare worker that fits {@code job}, or a new one. */
    static RenderWorker take(RenderJob job) {
        for (Iterator<RenderWorker> it = SPARE.iterator(); it.hasNext(); ) {
            RenderWorker w = it.next();
            if (w.fits(job) && SPARE.remove(w)) {
                COUNT.decrementAndGet();
                REUSES.incrementAndGet();
                w.forgetHistory();
                return w;
            }
        }
        return new RenderWorker(job.intersector());
    }

    /** Keeps {@code w} (already released) for a later session, unless {@link #LIMIT} are kept. */
    static void leave(RenderWorker w) {
        w.release();
        if (COUNT.incrementAndGet() <= LIMIT) {
            SPARE.offer(w);
        } else {
            COUNT.decrementAndGet();
        }
    }

    /** Spare workers kept right now. */
    static int count() {
        return COUNT.get();
    }

    /** Spare workers taken by a session's thread so far (tests). */
    static int reuses() {
        return REUSES.get();
    }
}
