package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Material;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/**
 * STEP face colours ({@link StepColours}, {@link StepWriter}): a scene's colours go out as styled
 * items and come back as the same diffuse materials; a colour on a shell reaches its faces, one on
 * a face wins over its shell's, an over-riding styled item over a plain one, a pre-defined colour
 * is read by name, and curve styles and broken styles leave the default.
 */
class StepColoursTest {

    private static Material rgb(IgesReader.Model m, int surface) {
        return m.materials().get(m.surfaceMaterial().get(surface));
    }

    private static double[] colour(Material m) {
        return new double[] {m.r(), m.g(), m.b()};
    }

    @Test
    void aScenesFaceColoursComeBackAsTheirDiffuseMaterials() {
        Random rnd = new Random(46);
        FreeFormSurface a = StepWriterTest.randomSurface(rnd, 0), b = StepWriterTest.randomSurface(rnd, 1),
                c = StepWriterTest.randomSurface(rnd, 0);
        Material red = Material.diffuse(0.8, 0.1, 0.1), blue = Material.diffuse(0.1, 0.2, 0.9);
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addMaterial(red).addMaterial(blue)
                .addPatches(a.toPatches(), 1).addPatches(b.toPatches(), 2).addPatches(c.toPatches(), 0).build();
        String text = StepWriterTest.write(scene);
        assertEquals(2, count(text, "=STYLED_ITEM("), "one styled item a coloured face");
        assertEquals(2, count(text, "=COLOUR_RGB("), "one style a colour");
        IgesReader.Model m = StepReaderTest.read(text, "model.stp");
        assertEquals(3, m.surfaces().size());
        assertEquals(red, rgb(m, 0));
        assertEquals(blue, rgb(m, 1));
        assertEquals(Material.DEFAULT, rgb(m, 2));
        // and through the whole scene: the patches keep their materials
        Scene back = IgesReader.toScene(m, TextSource.of(text, "model.stp"), new java.util.ArrayList<>());
        assertEquals(red, back.materials().get(back.patchMaterial(0)));
        assertEquals(Material.DEFAULT, back.materials().get(back.patchMaterial(back.patches().size() - 1)));
    }

    private static int count(String text, String what) {
        return text.split(Pattern.quote(what), -1).length - 1;
    }

    /** Two uncoloured faces written by us, with the styles {@code extra} (using {@code SHELL}, {@code FACE1}, {@code FACE2}) added. */
    private static IgesReader.Model styled(String extra) {
        Random rnd = new Random(7);
        Scene scene = new Scene(List.of(StepWriterTest.randomSurface(rnd, 0).toPatches().get(0),
                StepWriterTest.randomSurface(rnd, 0).toPatches().get(0)));
        String text = StepWriterTest.write(scene);
        Matcher shell = Pattern.compile("#(\\d+)=OPEN_SHELL\\('',\\((#\\d+),(#\\d+)\\)\\)").matcher(text);
        assertTrue(shell.find(), "no shell");
        String body = extra.replace("SHELL", "#" + shell.group(1)).replace("FACE1", shell.group(2))
                .replace("FACE2", shell.group(3));
        return StepReaderTest.read(text.replace("ENDSEC;\nEND-ISO", body + "ENDSEC;\nEND-ISO"), "model.stp");
    }

    private static final String CHAIN = "#9001=COLOUR_RGB('',0.25,0.5,0.75);\n"
            + "#9002=FILL_AREA_STYLE_COLOUR('',#9001);\n#9003=FILL_AREA_STYLE('',(#9002));\n"
            + "#9004=SURFACE_STYLE_FILL_AREA(#9003);\n#9005=SURFACE_SIDE_STYLE('',(#9004));\n"
            + "#9006=SURFACE_STYLE_USAGE(.BOTH.,#9005);\n#9007=PRESENTATION_STYLE_ASSIGNMENT((#9006));\n";

    @Test
    void aShellsColourReachesItsFacesAndAFacesOwnColourWins() {
        IgesReader.Model m = styled(CHAIN + "#9010=STYLED_ITEM('',(#9007),SHELL);\n"
                + "#9011=DRAUGHTING_PRE_DEFINED_COLOUR('red');\n#9012=FILL_AREA_STYLE_COLOUR('',#9011);\n"
                + "#9013=FILL_AREA_STYLE('',(#9012));\n#9014=SURFACE_STYLE_FILL_AREA(#9013);\n"
                + "#9015=SURFACE_SIDE_STYLE('',(#9014));\n#9016=SURFACE_STYLE_USAGE(.BOTH.,#9015);\n"
                + "#9017=PRESENTATION_STYLE_ASSIGNMENT((#9016));\n#9018=STYLED_ITEM('',(#9017),FACE2);\n");
        assertArrayEquals(new double[] {0.25, 0.5, 0.75}, colour(rgb(m, 0)), "the shell's colour");
        assertArrayEquals(new double[] {1, 0, 0}, colour(rgb(m, 1)), "the face's own, pre-defined red");
    }

    @Test
    void anOverRidingStyledItemWinsOverAPlainOne() {
        IgesReader.Model m = styled(CHAIN + "#9020=COLOUR_RGB('',0.0,1.0,0.0);\n#9021=FILL_AREA_STYLE_COLOUR('',#9020);\n"
                + "#9022=FILL_AREA_STYLE('',(#9021));\n#9023=SURFACE_STYLE_FILL_AREA(#9022);\n"
                + "#9024=SURFACE_SIDE_STYLE('',(#9023));\n#9025=SURFACE_STYLE_USAGE(.BOTH.,#9024);\n"
                + "#9026=PRESENTATION_STYLE_ASSIGNMENT((#9025));\n"
                + "#9030=OVER_RIDING_STYLED_ITEM('',(#9026),FACE1,#9031);\n#9031=STYLED_ITEM('',(#9007),FACE1);\n");
        assertArrayEquals(new double[] {0, 1, 0}, colour(rgb(m, 0)));
        assertEquals(Material.DEFAULT, rgb(m, 1));
    }

    @Test
    void curveStylesAndBrokenStylesLeaveTheDefault() {
        IgesReader.Model m = styled("#9040=COLOUR_RGB('',0.0,0.0,1.0);\n#9041=CURVE_STYLE('',$,$,#9040);\n"
                + "#9042=PRESENTATION_STYLE_ASSIGNMENT((#9041));\n#9043=STYLED_ITEM('',(#9042),FACE1);\n"
                + "#9044=COLOUR_RGB('',2.0,0.0,0.0);\n#9045=FILL_AREA_STYLE_COLOUR('',#9044);\n"
                + "#9046=FILL_AREA_STYLE('',(#9045));\n#9047=SURFACE_STYLE_FILL_AREA(#9046);\n"
                + "#9048=SURFACE_SIDE_STYLE('',(#9047));\n#9049=SURFACE_STYLE_USAGE(.BOTH.,#9048);\n"
                + "#9050=PRESENTATION_STYLE_ASSIGNMENT((#9049));\n#9051=STYLED_ITEM('',(#9050),FACE2);\n");
        assertEquals(Material.DEFAULT, rgb(m, 0), "a curve style colours no face");
        assertEquals(Material.DEFAULT, rgb(m, 1), "a colour channel of 2 is no colour");
        assertFalse(m.summary().contains("STYLED"), m.summary());
    }
}
