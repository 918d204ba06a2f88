package org.beziertracer.model.io;

import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;

import org.beziertracer.model.io.FileFormat.Holds;

/**
 * The registry of file formats: each is declared here once, with its name, extensions, reader
 * and writer. Opening ({@link SceneFiles#load}), saving, the scene file's {@code "file"} key, the
 * command line and the app's file dialogs all ask this class, so a new format is one declaration
 * here (and a new OBJ statement is a change to {@link ObjReader} only).
 *
 * <pre>
 * FileFormats.find("teapot.OBJ")            → Optional[OBJ]       (by extension, any case)
 * FileFormats.ALL                           → [BPT, OBJ, IGES, STEP, scene]
 * FileFormats.holding(Holds.MODEL)          → [BPT, OBJ, IGES, STEP]  (what a scene's "file" may name)
 * FileFormats.writable()                    → [BPT, OBJ, IGES, STEP, scene]
 * FileFormats.extensionList(FileFormats.ALL) → ".bpt, .obj, .igs, .iges, .stp, .step or .json"
 * FileFormats.OBJ.read(path) / .write(path, doc)
 * </pre>
 * Stateless and thread-safe.
 */
public final class FileFormats {
    private FileFormats() {}

    /** Bézier patch text ({@link BptReader}, {@link BptWriter}). */
    public static final FileFormat BPT = FileFormat.model("BPT", "Bézier patch text", List.of("bpt"),
            (text, baseDir, notes) -> BptReader.readScene(text), (out, scene, progress) -> {
                // a BPT file holds Bézier patches only: a mesh would be lost without a word
                int meshes = scene.meshes().size();
                if (meshes > 0) {
                    throw new IllegalArgumentException("a BPT file holds Bézier patches only but the model has "
                            + meshes + (meshes == 1 ? " triangle mesh" : " triangle meshes")
                            + "; save the model as .obj");
                }
                BptWriter.write(out, scene.patches(), progress);
            });

    /** Wavefront OBJ free-form surfaces and polygon faces ({@link ObjReader}, {@link ObjWriter}). */
    public static final FileFormat OBJ = FileFormat.model("OBJ", "Wavefront OBJ free-form surfaces", List.of("obj"),
            ObjReader::readScene, ObjWriter::write);

    /** IGES 5.3 surfaces ({@link IgesReader}, {@link IgesWriter}). */
    public static final FileFormat IGES = FileFormat.model("IGES", "IGES surfaces", List.of("igs", "iges"),
            (text, baseDir, notes) -> IgesReader.readScene(text, notes), IgesWriter::write);

    /** STEP (ISO 10303-21) faces: B-spline and analytic surfaces with parameter-space trims ({@link StepReader}, {@link StepWriter}). */
    public static final FileFormat STEP = FileFormat.model("STEP", "STEP surfaces", List.of("stp", "step"),
            (text, baseDir, notes) -> StepReader.readScene(text, notes), StepWriter::write);

    /** Bézier Tracer scene files, JSON ({@link SceneFiles}; {@code docs/scene-file.md}). */
    public static final FileFormat SCENE = new FileFormat("scene", "Bézier Tracer scene (JSON)", List.of("json"),
            Holds.SCENE, SceneFiles::read, (out, doc, progress) -> out.write(SceneWriter.toJson(doc)));

    /** Every format, in the order shown to users. */
    public static final List<FileFormat> ALL = List.of(BPT, OBJ, IGES, STEP, SCENE);

    /** The format whose extension {@code path} has (any case), if any. */
    public static Optional<FileFormat> find(String path) {
        return ALL.stream().filter(f -> f.matches(path)).findFirst();
    }

    /** The formats whose files hold {@code holds}, in registry order. */
    public static List<FileFormat> holding(Holds holds) {
        return ALL.stream().filter(f -> f.holds() == holds).toList();
    }

    /** The formats that can be saved, in registry order. */
    public static List<FileFormat> writable() {
        return ALL.stream().filter(FileFormat::canWrite).toList();
    }

    /** Every extension of {@code formats}, without dots: {@code [bpt, obj, json]}. */
    public static List<String> extensions(List<FileFormat> formats) {
        return formats.stream().flatMap(f -> f.extensions().stream()).toList();
    }

    /** For messages: {@code .bpt, .obj, .igs, .iges, .stp, .step or .json}. */
    public static String extensionList(List<FileFormat> formats) {
        List<String> dotted = extensions(formats).stream().map(e -> "." + e).toList();
        if (dotted.size() == 1) {
            return dotted.get(0);
        }
        return String.join(", ", dotted.subList(0, dotted.size() - 1)) + " or " + dotted.get(dotted.size() - 1);
    }

    /** For file dialogs: {@code *.bpt, *.obj}. */
    public static String patterns(List<FileFormat> formats) {
        return extensions(formats).stream().map(e -> "*." + e).collect(Collectors.joining(", "));
    }
}
