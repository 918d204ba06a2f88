package org.beziertracer.cli;

import java.util.Iterator;

import org.beziertracer.intersect.Method;

/**
 * The values of {@code --method} and {@code --difference-to}: every {@link Method}'s label, in
 * the enum's order, for picocli's help ({@code ${COMPLETION-CANDIDATES}}) and shell completion,
 * so the commands list whatever methods the enum declares.
 */
final class MethodLabels implements Iterable<String> {

    @Override
    public Iterator<String> iterator() {
        return Method.labels().iterator();
    }
}
