package org.beziertracer.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

/**
 * {@link RenderSettings}: the model layer keeps the method a plain lower-case word (which words
 * name a method only {@code intersect.Method} knows), while its own vocabularies stay checked here.
 */
class RenderSettingsTest {

    private static RenderSettings withMethod(String method) {
        RenderSettings d = RenderSettings.defaults();
        return new RenderSettings(d.width(), d.height(), d.spp(), d.sampler(), method, d.bvh(), d.shading(),
                d.checker(), d.shadows(), d.maxDepth());
    }

    @Test
    void theMethodIsKeptAsATrimmedLowerCaseWordWhateverItNames() {
        assertEquals("newton", withMethod(" Newton ").method());
        assertEquals("clipping", RenderSettings.defaults().method());
        // a word no method has passes here: Method.parse refuses it where the name becomes a method
        assertEquals("bogus", withMethod("BOGUS").method());
        assertEquals("my-method_2", withMethod("my-method_2").method());
    }

    @Test
    void aMethodThatIsNoWordIsRefusedInOneLine() {
        assertEquals("method must be a name (one word), got \"\"",
                UserMessages.of(IllegalArgumentException.class, () -> withMethod("")));
        assertEquals("method must be a name (one word), got \"  \"",
                UserMessages.of(IllegalArgumentException.class, () -> withMethod("  ")));
        assertEquals("method must be a name (one word), got \"two words\"",
                UserMessages.of(IllegalArgumentException.class, () -> withMethod("two words")));
        assertEquals("method must be a name (one word), got \"a.b\"",
                UserMessages.of(IllegalArgumentException.class, () -> withMethod("a.b")));
        assertEquals("method must be a name (one word), got \"\"",
                UserMessages.of(IllegalArgumentException.class, () -> withMethod(null)));
    }

    @Test
    void theSamplerAndShadingStayCheckedAgainstTheirLists() {
        RenderSettings d = RenderSettings.defaults();
        assertEquals("unknown sampler 'fancy': expected one of adaptive, jittered, regular",
                UserMessages.of(IllegalArgumentException.class, () -> new RenderSettings(d.width(), d.height(), d.spp(),
                        "fancy", d.method(), d.bvh(), d.shading(), d.checker(), d.shadows(), d.maxDepth())));
    }
}
