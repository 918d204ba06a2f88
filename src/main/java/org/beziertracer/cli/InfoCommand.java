package org.beziertracer.cli;

import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code info MODEL}: prints patch count, degrees and the control-point bounding box. */
@Command(name = "info", mixinStandardHelpOptions = true,
        description = "Prints patch count, degrees and control-point bounding box of a model.")
final class InfoCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "MODEL", description = "a .bpt or .obj file, or a built-in name (patch, teapot)")
    String model;

    @Override
    public Integer call() {
        throw new UnsupportedOperationException("info is not implemented yet");
    }
}
