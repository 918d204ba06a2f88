package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Material;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/**
 * IGES face colours ({@link IgesWriter}, {@link IgesReader}): a scene's diffuse colours go out as
 * colour definitions (314) that the surfaces' directory colour fields point to, one 314 a colour,
 * and come back as the same diffuse materials to the last bit; the default material writes no
 * colour.
 */
class IgesColoursTest {

    private static final int SURFACES = 30;

    private static String write(Scene scene) throws IOException {
        StringWriter out = new StringWriter();
        IgesWriter.write(out, scene);
        return out.toString();
    }

    private static Material colourOf(IgesReader.Model m, int surface) {
        return m.materials().get(m.surfaceMaterial().get(surface));
    }

    /** Directory entries of {@code type} (the D section's first line of each pair). */
    private static int entries(String text, int type) {
        int n = 0;
        for (String line : text.split("\n")) {
            if (line.length() == 80 && line.charAt(72) == 'D' && Integer.parseInt(line.substring(73).trim()) % 2 == 1
                    && Integer.parseInt(line.substring(0, 8).trim()) == type) {
                n++;
            }
        }
        return n;
    }

    @Test
    void surfaceColoursComeBackAsTheSameDiffuseMaterials() throws IOException {
        Random rnd = new Random(314);
        Scene.Builder b = Scene.builder().addMaterial(Material.DEFAULT);
        List<Material> expected = new ArrayList<>();
        for (int s = 0; s < SURFACES; s++) {
            // every third surface shares the red, two in ten keep the default, the others a random colour
            Material m = s % 3 == 0 ? Material.diffuse(0.8, 0.1, 0.1)
                    : s % 5 == 1 ? Material.DEFAULT
                    : Material.diffuse(rnd.nextDouble(), rnd.nextInt(4) == 0 ? 1 : rnd.nextDouble(),
                            rnd.nextInt(4) == 0 ? 0 : rnd.nextDouble());
            b.addMaterial(m);
            FreeFormSurface f = IgesRoundTripTest.randomSurface(rnd, s); // trimmed (a 144) two times in three
            b.addPatches(f.toPatches(), s + 1);
            expected.add(m);
        }
        String text = write(b.build());
        long distinct = expected.stream().filter(m -> !m.equals(Material.DEFAULT)).distinct().count();
        assertEquals(distinct, entries(text, 314), "one colour definition a distinct colour");

        IgesReader.Model read = IgesReader.readModel(TextSource.of(text, "colours.igs"));
        assertEquals(SURFACES, read.surfaces().size());
        for (int s = 0; s < SURFACES; s++) {
            assertEquals(expected.get(s), colourOf(read, s), "surface " + s);
        }
        // and through the whole scene: every patch keeps its surface's material
        Scene back = IgesReader.toScene(read, TextSource.of(text, "colours.igs"), new ArrayList<>());
        assertEquals(Material.diffuse(0.8, 0.1, 0.1), back.materials().get(back.patchMaterial(0)));
        assertEquals(expected.get(SURFACES - 1), back.materials().get(back.patchMaterial(back.patches().size() - 1)));
    }

    @Test
    void aColourAboveOneIsWrittenAsAHundredPercentAndOtherMaterialPartsAreNotKept() throws IOException {
        Random rnd = new Random(3);
        Material shiny = new Material(1.5, 0.25, 0, 0.1, 0.6, 0.9, 80, 0.3, 0, 1.5, 0, 0, 0, 0);
        Scene scene = Scene.builder().addMaterial(shiny).addPatches(IgesRoundTripTest.randomSurface(rnd, 0).toPatches(), 0)
                .build();
        IgesReader.Model read = IgesReader.readModel(TextSource.of(write(scene), "shiny.igs"));
        assertEquals(Material.diffuse(1, 0.25, 0), colourOf(read, 0));
    }

    @Test
    void theDefaultMaterialWritesNoColour() throws IOException {
        Random rnd = new Random(4);
        String text = write(new Scene(IgesRoundTripTest.randomSurface(rnd, 1).toPatches()));
        assertEquals(0, entries(text, 314));
        assertEquals(0, IgesReader.readModel(TextSource.of(text, "plain.igs")).surfaceMaterial().get(0));
    }

    @Test
    void percentTextReadsBackToTheSameFractionForEveryDouble() {
        Random rnd = new Random(100);
        int naiveMisses = 0;
        for (int k = 0; k < 20_000; k++) {
            double f = k < 2 ? k : rnd.nextInt(8) == 0 ? rnd.nextInt(1001) / 1000.0 : rnd.nextDouble();
            String text = IgesWriter.percent(f);
            assertTrue(text.indexOf('.') > 0, text);
            IgesParams p = IgesParams.parse("314," + text + ";", ',', ';', TextSource.of("", "t.igs"), 1, "entity 314");
            assertEquals(f, p.fraction(1), () -> "fraction " + f + " written as " + text);
            if (Double.parseDouble(text) / 100 != f) {
                naiveMisses++;
            }
        }
        // dividing the parsed percentage again would lose some of them: the exact decimal division is needed
        assertTrue(naiveMisses > 0, "no double needed the exact division");
    }
}
