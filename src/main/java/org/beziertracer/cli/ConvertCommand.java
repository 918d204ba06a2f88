package org.beziertracer.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.beziertracer.model.io.FilePaths;
import org.beziertracer.intersect.Method;
import org.beziertracer.model.io.FileFormat;
import org.beziertracer.model.io.FileFormats;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code convert IN OUT}: reads a model or scene in any format (or a built-in) and writes it in the
 * format {@code OUT}'s extension names, atomically, so that a model goes back to the CAD tool it
 * came from ({@code convert part.obj part.igs}). The output may not be the input; a format that
 * cannot hold what was read (a mesh into IGES or BPT) refuses in one line before anything is
 * written, as the app's Save does. What the reader skipped is noted on standard error ({@link ReadNotes}).
 */
@Command(name = "convert", mixinStandardHelpOptions = true,
        description = "Writes a model or scene in the format the output's extension names (for example "
                + "convert part.obj part.igs); the output is written atomically and may not be the input.")
final class ConvertCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "IN", descriptionKey = CliText.INPUT)
    String input;

    @Parameters(index = "1", paramLabel = "OUT",
            description = "The file to write: its extension picks the format (${COMPLETION-CANDIDATES}).",
            completionCandidates = WritableExtensions.class)
    String output;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        FileFormat format = FileFormats.find(output).filter(FileFormat::canWrite).orElseThrow(() ->
                new IllegalArgumentException(output + ": expected a file name ending in "
                        + FileFormats.extensionList(FileFormats.writable()) + " (the format to write)"));
        Path target = FilePaths.of(output);
        Path source = FilePaths.of(input);
        if (Files.exists(source) && Files.exists(target) && Files.isSameFile(source, target)) {
            throw new IllegalArgumentException(output + ": is the input file; write to another name");
        }
        SceneDocument doc = ReadNotes.show(SceneFiles.load(input, Method::parse), spec.commandLine().getErr());
        format.write(target, doc);
        int patches = doc.scene().patchCount();
        spec.commandLine().getOut().println("wrote " + output + " (" + format + "): " + patches
                + (patches == 1 ? " patch" : " patches"));
        return 0;
    }

    /** The extensions a model can be written in, for the help text. */
    static final class WritableExtensions implements Iterable<String> {
        @Override
        public java.util.Iterator<String> iterator() {
            return FileFormats.extensions(FileFormats.writable()).iterator();
        }
    }
}
