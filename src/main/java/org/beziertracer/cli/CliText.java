package org.beziertracer.cli;

import java.util.ListResourceBundle;

import org.beziertracer.model.io.BuiltIns;
import org.beziertracer.model.io.FileFormats;

/**
 * Help texts computed from the registries, so that {@code --help} lists the formats and built-in
 * names declared in {@link FileFormats} and {@link BuiltIns} (picocli reads a description from
 * this bundle by the parameter's {@code descriptionKey}).
 */
final class CliText extends ListResourceBundle {

    /**
     * Key of the MODEL / MODEL_OR_SCENE parameter's description. Not {@code input}: picocli looks
     * an option's description up by its long name, and {@code trace --input RAYS} would get this text.
     */
    static final String INPUT = "model-or-scene";

    @Override
    protected Object[][] getContents() {
        return new Object[][] {{INPUT, "a " + FileFormats.extensionList(FileFormats.ALL) + " file, or a built-in: "
                + String.join(", ", BuiltIns.names())}};
    }
}
