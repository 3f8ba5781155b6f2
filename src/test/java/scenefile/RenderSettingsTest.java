package scenefile;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.MissingResourceException;

import org.junit.jupiter.api.Test;

import renderer.RayTracerBase;
import renderer.RayTracerBasic;
import renderer.Render;
import scene.Scene;

/**
 * Unit tests for {@link RenderSettings}: the default settings, the withXxx copies, the count checks and
 * {@link RenderSettings#applyTo(Render)}.
 */
class RenderSettingsTest {
    /** Settings where every component differs from the default. */
    private static final RenderSettings CUSTOM = new RenderSettings(true, true, 4, 3, 7L);

    /**
     * Test method for {@link RenderSettings#withSqrtGlossRays(int)}, its check, its default and its
     * {@link RenderSettings#applyTo(Render)}.
     */
    @Test
    void testSqrtGlossRays() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the default is the ray tracer's, 5; the five-count constructor gives it too
        assertEquals(RayTracerBase.DEFAULT_SQRT_GLOSS_RAYS, RenderSettings.DEFAULT.sqrtGlossRays(),
                "TC01: sqrtGlossRays must be the ray tracer's default");
        assertEquals(5, CUSTOM.sqrtGlossRays(), "TC01: the five-count constructor must give 5");
        // TC02: withSqrtGlossRays(8) changes only sqrtGlossRays, and the other withXxx keep it
        RenderSettings eight = CUSTOM.withSqrtGlossRays(8);
        assertEquals(new RenderSettings(true, true, 4, 3, 7L, 8, false), eight, "TC02: only sqrtGlossRays must change");
        assertEquals(8, eight.withSoftShadows(false).withAdaptiveSoftShadows(false).withSqrtBeamNum(2)
                .withAntiAliasing(2).withSeed(1).sqrtGlossRays(), "TC02: the other withXxx must keep sqrtGlossRays");
        // TC03: applyTo passes it to the ray tracer
        RayTracerBase tracer = new RayTracerBasic(new Scene("gloss"));
        eight.applyTo(new Render().setRayTracer(tracer));
        assertEquals(8, tracer.getSqrtGlossRays(), "TC03: sqrtGlossRays must be 8 in the ray tracer");

        // ===== Boundary Values Tests =====
        // TC11: 1 and 1000 are accepted
        assertEquals(1, CUSTOM.withSqrtGlossRays(1).sqrtGlossRays(), "TC11: 1 must be accepted");
        assertEquals(1000, CUSTOM.withSqrtGlossRays(1000).sqrtGlossRays(), "TC11: 1000 must be accepted");
        // TC12: 0 and 1001 are rejected naming sqrtGlossRays
        assertMessage(assertThrows(IllegalArgumentException.class, () -> CUSTOM.withSqrtGlossRays(0),
                "TC12: 0 must be rejected"), "sqrtGlossRays", "TC12");
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings(false, false, 9, 1, 0, 1001, false),
                "TC12: 1001 must be rejected");
    }

    /** Test method for {@link RenderSettings#DEFAULT}. */
    @Test
    void testDefault() {
        // ===== Equivalence Partitions Tests =====
        // TC01: hard shadows, not adaptive, 9 cells, 1 ray per pixel, seed 20210621
        assertFalse(RenderSettings.DEFAULT.softShadows(), "TC01: soft shadows must be off by default");
        assertFalse(RenderSettings.DEFAULT.adaptiveSoftShadows(), "TC01: adaptive soft shadows must be off by default");
        assertEquals(9, RenderSettings.DEFAULT.sqrtBeamNum(), "TC01: sqrtBeamNum must be 9 by default");
        assertEquals(1, RenderSettings.DEFAULT.antiAliasing(), "TC01: anti-aliasing must be 1 by default");
        assertEquals(RayTracerBase.DEFAULT_SEED, RenderSettings.DEFAULT.seed(), "TC01: wrong default seed");
        assertEquals(20_210_621L, RenderSettings.DEFAULT.seed(), "TC01: the default seed must be 20210621");
        assertEquals(RayTracerBase.DEFAULT_SQRT_BEAM_NUM, RenderSettings.DEFAULT.sqrtBeamNum(),
                "TC01: sqrtBeamNum must be the ray tracer's default");
    }

    /**
     * Test method for {@link RenderSettings#withSoftShadows(boolean)},
     * {@link RenderSettings#withAdaptiveSoftShadows(boolean)}, {@link RenderSettings#withSqrtBeamNum(int)},
     * {@link RenderSettings#withAntiAliasing(int)} and {@link RenderSettings#withSeed(long)}.
     */
    @Test
    void testWithMethods() {
        RenderSettings d = RenderSettings.DEFAULT;

        // ===== Equivalence Partitions Tests =====
        // TC01: withSoftShadows(true) changes only softShadows: (true, false, 9, 1, default seed)
        assertEquals(new RenderSettings(true, false, 9, 1, RayTracerBase.DEFAULT_SEED), d.withSoftShadows(true),
                "TC01: withSoftShadows must change only softShadows");
        // TC02: withAdaptiveSoftShadows(true) changes only adaptiveSoftShadows: (false, true, 9, 1, default seed)
        assertEquals(new RenderSettings(false, true, 9, 1, RayTracerBase.DEFAULT_SEED), d.withAdaptiveSoftShadows(true),
                "TC02: withAdaptiveSoftShadows must change only adaptiveSoftShadows");
        // TC03: withSqrtBeamNum(5) changes only sqrtBeamNum: (false, false, 5, 1, default seed)
        assertEquals(new RenderSettings(false, false, 5, 1, RayTracerBase.DEFAULT_SEED), d.withSqrtBeamNum(5),
                "TC03: withSqrtBeamNum must change only sqrtBeamNum");
        // TC04: withAntiAliasing(4) changes only antiAliasing: (false, false, 9, 4, default seed)
        assertEquals(new RenderSettings(false, false, 9, 4, RayTracerBase.DEFAULT_SEED), d.withAntiAliasing(4),
                "TC04: withAntiAliasing must change only antiAliasing");
        // TC05: withSeed(-3) changes only the seed: (false, false, 9, 1, -3)
        assertEquals(new RenderSettings(false, false, 9, 1, -3L), d.withSeed(-3),
                "TC05: withSeed must change only the seed");
        // TC06: switching flags off from custom settings (true, true, 4, 3, 7) keeps the other components
        assertEquals(new RenderSettings(false, true, 4, 3, 7L), CUSTOM.withSoftShadows(false),
                "TC06: withSoftShadows(false) must change only softShadows");
        assertEquals(new RenderSettings(true, false, 4, 3, 7L), CUSTOM.withAdaptiveSoftShadows(false),
                "TC06: withAdaptiveSoftShadows(false) must change only adaptiveSoftShadows");
        // TC07: the original settings are not changed by the copies
        assertEquals(new RenderSettings(false, false, 9, 1, RayTracerBase.DEFAULT_SEED), d,
                "TC07: DEFAULT must not change");
        assertEquals(new RenderSettings(true, true, 4, 3, 7L), CUSTOM, "TC07: the custom settings must not change");

        // ===== Boundary Values Tests =====
        // TC11: withSqrtBeamNum(1) and withAntiAliasing(1), the smallest counts, are accepted
        assertEquals(1, d.withSqrtBeamNum(1).sqrtBeamNum(), "TC11: sqrtBeamNum 1 must be accepted");
        assertEquals(1, CUSTOM.withAntiAliasing(1).antiAliasing(), "TC11: anti-aliasing 1 must be accepted");
        // TC12: the same value gives equal settings
        assertEquals(CUSTOM, CUSTOM.withSeed(7), "TC12: withSeed of the same seed must give equal settings");
        // TC13: withSqrtBeamNum(0) and withAntiAliasing(0) are rejected
        assertMessage(assertThrows(IllegalArgumentException.class, () -> d.withSqrtBeamNum(0),
                "TC13: withSqrtBeamNum(0) must be rejected"), "sqrtBeamNum", "TC13");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> d.withAntiAliasing(0),
                "TC13: withAntiAliasing(0) must be rejected"), "anti-aliasing", "TC13");
    }

    /** Test method for the checks of {@link RenderSettings#RenderSettings(boolean, boolean, int, int, long)}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: good counts (4, 3) are kept
        assertEquals(4, CUSTOM.sqrtBeamNum(), "TC01: sqrtBeamNum must be 4");
        assertEquals(3, CUSTOM.antiAliasing(), "TC01: anti-aliasing must be 3");
        assertTrue(CUSTOM.softShadows() && CUSTOM.adaptiveSoftShadows(), "TC01: both flags must be on");
        assertEquals(7L, CUSTOM.seed(), "TC01: the seed must be 7");
        // TC02: a negative sqrtBeamNum (-2) is rejected, naming sqrtBeamNum and the value
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new RenderSettings(false, false, -2, 1, 0), "TC02: sqrtBeamNum -2 must be rejected");
        assertMessage(e, "sqrtBeamNum", "TC02");
        assertMessage(e, "-2", "TC02");
        // TC03: a negative anti-aliasing (-3) is rejected, naming anti-aliasing and the value
        e = assertThrows(IllegalArgumentException.class,
                () -> new RenderSettings(false, false, 9, -3, 0), "TC03: anti-aliasing -3 must be rejected");
        assertMessage(e, "anti-aliasing", "TC03");
        assertMessage(e, "-3", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: sqrtBeamNum 0 is rejected
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new RenderSettings(false, false, 0, 1, 0),
                "TC11: sqrtBeamNum 0 must be rejected"), "sqrtBeamNum", "TC11");
        // TC12: anti-aliasing 0 is rejected
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new RenderSettings(false, false, 9, 0, 0),
                "TC12: anti-aliasing 0 must be rejected"), "anti-aliasing", "TC12");
        // TC13: sqrtBeamNum 1 and anti-aliasing 1 are accepted
        RenderSettings ones = assertDoesNotThrow(() -> new RenderSettings(false, false, 1, 1, 0),
                "TC13: counts of 1 must be accepted");
        assertEquals(1, ones.sqrtBeamNum(), "TC13: sqrtBeamNum must be 1");
        assertEquals(1, ones.antiAliasing(), "TC13: anti-aliasing must be 1");
        // TC14: both counts bad: the check of sqrtBeamNum comes first
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new RenderSettings(false, false, 0, 0, 0),
                "TC14: counts of 0 must be rejected"), "sqrtBeamNum", "TC14");
    }

    /** Test method for {@link RenderSettings#applyTo(Render)}. */
    @Test
    void testApplyTo() {
        // ===== Equivalence Partitions Tests =====
        // TC01: custom settings (true, true, 4, 3, 7) reach the ray tracer and the render, and the render is returned
        RayTracerBase tracer = new RayTracerBasic(new Scene("settings"));
        Render render = new Render().setRayTracer(tracer);
        assertSame(render, CUSTOM.applyTo(render), "TC01: applyTo must return the render");
        assertSame(tracer, render.getRayTracer(), "TC01: applyTo must keep the ray tracer");
        assertTrue(render.getRayTracer().isSoftShadows(), "TC01: soft shadows must be on");
        assertTrue(render.getRayTracer().isAdaptiveSoftShadows(), "TC01: adaptive soft shadows must be on");
        assertEquals(4, render.getRayTracer().getSqrtBeamNum(), "TC01: sqrtBeamNum must be 4");
        assertEquals(7L, render.getRayTracer().getSeed(), "TC01: the seed must be 7");
        assertEquals(3, render.getAntiAliasing(), "TC01: anti-aliasing must be 3");
        // TC02: DEFAULT applied over them sets everything back: (false, false, 9, 1, default seed)
        RenderSettings.DEFAULT.applyTo(render);
        assertFalse(render.getRayTracer().isSoftShadows(), "TC02: soft shadows must be off again");
        assertFalse(render.getRayTracer().isAdaptiveSoftShadows(), "TC02: adaptive soft shadows must be off again");
        assertEquals(9, render.getRayTracer().getSqrtBeamNum(), "TC02: sqrtBeamNum must be 9 again");
        assertEquals(RayTracerBase.DEFAULT_SEED, render.getRayTracer().getSeed(), "TC02: the seed must be the default");
        assertEquals(1, render.getAntiAliasing(), "TC02: anti-aliasing must be 1 again");

        // ===== Boundary Values Tests =====
        // TC11: a render without a ray tracer: MissingResourceException naming the ray tracer
        MissingResourceException e = assertThrows(MissingResourceException.class,
                () -> CUSTOM.applyTo(new Render()), "TC11: applyTo without a ray tracer must fail");
        assertMessage(e, "ray tracer", "TC11");
        // TC12: counts of 1 (sqrtBeamNum 1, anti-aliasing 1) are applied
        RayTracerBase tracer1 = new RayTracerBasic(new Scene("ones"));
        Render render1 = new Render().setRayTracer(tracer1).setAntiAliasing(5);
        new RenderSettings(false, false, 1, 1, 0).applyTo(render1);
        assertEquals(1, tracer1.getSqrtBeamNum(), "TC12: sqrtBeamNum must be 1");
        assertEquals(1, render1.getAntiAliasing(), "TC12: anti-aliasing must be back to 1");
        assertEquals(0L, tracer1.getSeed(), "TC12: the seed must be 0");
    }

    /**
     * Test method for {@link RenderSettings#withAdaptiveSuperSampling(boolean)}, the five-argument constructor and
     * {@link RenderSettings#applyTo(Render)} with adaptive super-sampling.
     */
    @Test
    void testAdaptiveSuperSampling() {
        // ===== Equivalence Partitions Tests =====
        // TC01: off by default; withAdaptiveSuperSampling(true) turns it on and keeps the rest (custom settings)
        assertFalse(RenderSettings.DEFAULT.adaptiveSuperSampling(), "TC01: adaptive super-sampling must be off");
        RenderSettings adaptive = CUSTOM.withAdaptiveSuperSampling(true);
        assertEquals(new RenderSettings(true, true, 4, 3, 7L, RayTracerBase.DEFAULT_SQRT_GLOSS_RAYS, true), adaptive, "TC01: only the flag must change");
        // TC02: the other with-methods keep it on
        assertTrue(adaptive.withSoftShadows(false).withAdaptiveSoftShadows(false).withSqrtBeamNum(2)
                .withAntiAliasing(5).withSeed(1).adaptiveSuperSampling(), "TC02: the flag must be kept");
        // TC03: applied to a render, and turned off again by DEFAULT
        Render render = new Render().setRayTracer(new RayTracerBasic(new Scene("adaptive")));
        adaptive.applyTo(render);
        assertTrue(render.isAdaptiveSuperSampling(), "TC03: adaptive super-sampling must be on in the render");
        RenderSettings.DEFAULT.applyTo(render);
        assertFalse(render.isAdaptiveSuperSampling(), "TC03: adaptive super-sampling must be off again");

        // ===== Boundary Values Tests =====
        // TC11: the five-argument constructor is the seven-argument one with 5 x 5 gloss rays and adaptive
        // super-sampling off
        assertEquals(new RenderSettings(true, true, 4, 3, 7L, RayTracerBase.DEFAULT_SQRT_GLOSS_RAYS, false), CUSTOM, "TC11: five arguments mean off");
        assertEquals(CUSTOM, adaptive.withAdaptiveSuperSampling(false), "TC11: turned off again");
    }
}
