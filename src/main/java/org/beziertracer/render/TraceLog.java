package org.beziertracer.render;

/** Receives a human-readable line for every ray, hit and shading term (the {@code --pixel} debug trace). */
@FunctionalInterface
public interface TraceLog {
    void line(String text);
}
