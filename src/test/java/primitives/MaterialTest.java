package primitives;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertSameRejection;

import java.util.List;
import java.util.function.BiFunction;
import java.util.function.ToDoubleFunction;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link primitives.Material}.
 */
class MaterialTest {

    /** Test method for the defaults of {@link primitives.Material}. */
    @Test
    void testDefaults() {
        Material m = new Material();
        // ===== Equivalence Partitions Tests =====
        // TC01: every factor defaults to 0
        assertEquals(0, m.getKd(), 0, "TC01: default kD must be 0");
        assertEquals(0, m.getKs(), 0, "TC01: default kS must be 0");
        assertEquals(0, m.getKt(), 0, "TC01: default kT must be 0");
        assertEquals(0, m.getKr(), 0, "TC01: default kR must be 0");
        assertEquals(0, m.getShininess(), "TC01: default shininess must be 0");
        // TC02: glossiness and blurriness default to 0 (a sharp mirror, clear glass)
        assertEquals(0, m.getKg(), 0, "TC02: default kG must be 0");
        assertEquals(0, m.getKb(), 0, "TC02: default kB must be 0");
    }

    /** Test method for the chaining of the setters of {@link primitives.Material}. */
    @Test
    void testChaining() {
        Material m = new Material();
        // ===== Equivalence Partitions Tests =====
        // TC01: each setter returns the material itself
        assertSame(m, m.setKd(0.5), "TC01: setKd must return this");
        assertSame(m, m.setKs(0.25), "TC01: setKs must return this");
        assertSame(m, m.setKt(0.3), "TC01: setKt must return this");
        assertSame(m, m.setKr(0.7), "TC01: setKr must return this");
        assertSame(m, m.setShininess(30), "TC01: setShininess must return this");
        // TC02: a chain sets every value: kD .3, kS .4, kT .5, kR .6, shininess 20
        Material c = new Material().setKd(0.3).setKs(0.4).setKt(0.5).setKr(0.6).setShininess(20);
        assertEquals(0.3, c.getKd(), 0, "TC02: wrong kD");
        assertEquals(0.4, c.getKs(), 0, "TC02: wrong kS");
        assertEquals(0.5, c.getKt(), 0, "TC02: wrong kT");
        assertEquals(0.6, c.getKr(), 0, "TC02: wrong kR");
        assertEquals(20, c.getShininess(), "TC02: wrong shininess");
    }

    /** Test method for {@link primitives.Material#setKd(double)}. */
    @Test
    void testSetKd() {
        Material m = new Material().setKd(0.5);
        // ===== Equivalence Partitions Tests =====
        // TC01: 0.8 is kept
        assertEquals(0.8, m.setKd(0.8).getKd(), 0, "TC01: wrong kD");
        // TC02: negative kD is rejected, the message names kD and "negative"; kD stays 0.8
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.setKd(-0.1),
                "TC02: negative kD must be rejected");
        assertMessage(e, "kD", "TC02");
        assertMessage(e, "negative", "TC02");
        assertEquals(0.8, m.getKd(), 0, "TC02: a rejected kD must not change the material");
        // TC03: NaN and infinite kD are rejected ("finite")
        e = assertThrows(IllegalArgumentException.class, () -> m.setKd(Double.NaN), "TC03: NaN kD must be rejected");
        assertMessage(e, "finite", "TC03");
        e = assertThrows(IllegalArgumentException.class, () -> m.setKd(Double.POSITIVE_INFINITY),
                "TC03: infinite kD must be rejected");
        assertMessage(e, "finite", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: 0 is accepted (0)
        assertEquals(0, m.setKd(0).getKd(), 0, "TC10: kD 0 must be accepted");
    }

    /** Test method for {@link primitives.Material#setKs(double)}. */
    @Test
    void testSetKs() {
        Material m = new Material();
        // ===== Equivalence Partitions Tests =====
        // TC01: 0.8 is kept
        assertEquals(0.8, m.setKs(0.8).getKs(), 0, "TC01: wrong kS");
        // TC02: negative kS is rejected, the message names kS and "negative"; kS stays 0.8
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.setKs(-2),
                "TC02: negative kS must be rejected");
        assertMessage(e, "kS", "TC02");
        assertMessage(e, "negative", "TC02");
        assertEquals(0.8, m.getKs(), 0, "TC02: a rejected kS must not change the material");
        // TC03: NaN kS is rejected ("finite")
        e = assertThrows(IllegalArgumentException.class, () -> m.setKs(Double.NaN), "TC03: NaN kS must be rejected");
        assertMessage(e, "finite", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: 0 is accepted (0)
        assertEquals(0, m.setKs(0).getKs(), 0, "TC10: kS 0 must be accepted");
        // TC11: the negative value closest to 0 is rejected (-Double.MIN_VALUE)
        assertThrows(IllegalArgumentException.class, () -> m.setKs(-Double.MIN_VALUE),
                "TC11: -MIN_VALUE kS must be rejected");
    }

    /** Test method for {@link primitives.Material#setKt(double)}. */
    @Test
    void testSetKt() {
        Material m = new Material();
        // ===== Equivalence Partitions Tests =====
        // TC01: 0.5 is kept
        assertEquals(0.5, m.setKt(0.5).getKt(), 0, "TC01: wrong kT");
        // TC02: above 1 is rejected, the message names kT; kT stays 0.5
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.setKt(2),
                "TC02: kT above 1 must be rejected");
        assertMessage(e, "kT", "TC02");
        assertMessage(e, "at most 1", "TC02");
        assertEquals(0.5, m.getKt(), 0, "TC02: a rejected kT must not change the material");
        // TC03: negative is rejected, the message names kT and "negative"
        e = assertThrows(IllegalArgumentException.class, () -> m.setKt(-0.5), "TC03: negative kT must be rejected");
        assertMessage(e, "kT", "TC03");
        assertMessage(e, "negative", "TC03");
        // TC04: NaN is rejected ("finite")
        e = assertThrows(IllegalArgumentException.class, () -> m.setKt(Double.NaN), "TC04: NaN kT must be rejected");
        assertMessage(e, "finite", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: 0 is accepted (0)
        assertEquals(0, m.setKt(0).getKt(), 0, "TC10: kT 0 must be accepted");
        // TC11: 1 is accepted (1)
        assertEquals(1, m.setKt(1).getKt(), 0, "TC11: kT 1 must be accepted");
        // TC12: just above 1 is rejected (1.0001)
        e = assertThrows(IllegalArgumentException.class, () -> m.setKt(1.0001), "TC12: kT 1.0001 must be rejected");
        assertMessage(e, "kT", "TC12");
        // TC13: just below 0 is rejected (-0.0001)
        e = assertThrows(IllegalArgumentException.class, () -> m.setKt(-0.0001), "TC13: kT -0.0001 must be rejected");
        assertMessage(e, "kT", "TC13");
    }

    /** Test method for {@link primitives.Material#setKr(double)}. */
    @Test
    void testSetKr() {
        Material m = new Material();
        // ===== Equivalence Partitions Tests =====
        // TC01: 0.5 is kept
        assertEquals(0.5, m.setKr(0.5).getKr(), 0, "TC01: wrong kR");
        // TC02: above 1 is rejected, the message names kR; kR stays 0.5
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.setKr(1.5),
                "TC02: kR above 1 must be rejected");
        assertMessage(e, "kR", "TC02");
        assertMessage(e, "at most 1", "TC02");
        assertEquals(0.5, m.getKr(), 0, "TC02: a rejected kR must not change the material");
        // TC03: negative is rejected, the message names kR and "negative"
        e = assertThrows(IllegalArgumentException.class, () -> m.setKr(-1), "TC03: negative kR must be rejected");
        assertMessage(e, "kR", "TC03");
        assertMessage(e, "negative", "TC03");
        // TC04: NaN is rejected ("finite")
        e = assertThrows(IllegalArgumentException.class, () -> m.setKr(Double.NaN), "TC04: NaN kR must be rejected");
        assertMessage(e, "finite", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: 0 is accepted (0)
        assertEquals(0, m.setKr(0).getKr(), 0, "TC10: kR 0 must be accepted");
        // TC11: 1 is accepted (1)
        assertEquals(1, m.setKr(1).getKr(), 0, "TC11: kR 1 must be accepted");
        // TC12: just above 1 is rejected (1.0001)
        e = assertThrows(IllegalArgumentException.class, () -> m.setKr(1.0001), "TC12: kR 1.0001 must be rejected");
        assertMessage(e, "kR", "TC12");
        // TC13: just below 0 is rejected (-0.0001)
        e = assertThrows(IllegalArgumentException.class, () -> m.setKr(-0.0001), "TC13: kR -0.0001 must be rejected");
        assertMessage(e, "kR", "TC13");
    }

    /** Test method for {@link primitives.Material#setShininess(int)}. */
    @Test
    void testSetShininess() {
        Material m = new Material();
        // ===== Equivalence Partitions Tests =====
        // TC01: 60 is kept
        assertEquals(60, m.setShininess(60).getShininess(), "TC01: wrong shininess");
        // TC02: negative shininess is rejected, the message names shininess and "negative"; stays 60
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.setShininess(-5),
                "TC02: negative shininess must be rejected");
        assertMessage(e, "shininess", "TC02");
        assertMessage(e, "negative", "TC02");
        assertEquals(60, m.getShininess(), "TC02: a rejected shininess must not change the material");

        // ===== Boundary Values Tests =====
        // TC10: 0 is accepted (0)
        assertEquals(0, m.setShininess(0).getShininess(), "TC10: shininess 0 must be accepted");
        // TC11: -1 is rejected
        e = assertThrows(IllegalArgumentException.class, () -> m.setShininess(-1),
                "TC11: shininess -1 must be rejected");
        assertMessage(e, "shininess", "TC11");
    }

    /** Test method for {@link primitives.Material#setKg(double)}. */
    @Test
    void testSetKg() {
        assertSpread("kG", Material::setKg, Material::getKg);
    }

    /** Test method for {@link primitives.Material#setKb(double)}. */
    @Test
    void testSetKb() {
        assertSpread("kB", Material::setKb, Material::getKb);
    }

    /**
     * A factor's setter under the report's name and under the course's, and its getter.
     *
     * @param name     the factor's name
     * @param report   the report's setter ({@code setKd})
     * @param course   the course's setter ({@code setkD})
     * @param getter   the factor's getter
     * @param fraction whether the factor is at most 1
     */
    private record Twin(String name, BiFunction<Material, Double, Material> report,
                        BiFunction<Material, Double, Material> course, ToDoubleFunction<Material> getter,
                        boolean fraction) {
    }

    /** The factors the course sets through the lower-k names. */
    private static final List<Twin> TWINS = List.of(
            new Twin("kD", Material::setKd, Material::setkD, Material::getKd, false),
            new Twin("kS", Material::setKs, Material::setkS, Material::getKs, false),
            new Twin("kT", Material::setKt, Material::setkT, Material::getKt, true),
            new Twin("kR", Material::setKr, Material::setkR, Material::getKr, true),
            new Twin("kG", Material::setKg, Material::setkG, Material::getKg, true),
            new Twin("kB", Material::setKb, Material::setkB, Material::getKb, true));

    /**
     * Test method for {@link primitives.Material#setkD(double)}, {@link primitives.Material#setkS(double)},
     * {@link primitives.Material#setkT(double)}, {@link primitives.Material#setkR(double)},
     * {@link primitives.Material#setkG(double)}, {@link primitives.Material#setkB(double)} and
     * {@link primitives.Material#setnShininess(int)}, the course's names of the report's setters.
     */
    @Test
    void testCourseSetterNames() {
        // ===== Equivalence Partitions Tests =====
        for (Twin twin : TWINS) {
            String tc = " (" + twin.name() + ")";
            Material m = new Material();
            // TC01: the course's setter returns this material and sets the factor (0.25)
            assertSame(m, twin.course().apply(m, 0.25), "TC01: the course's setter must return this" + tc);
            assertEquals(0.25, twin.getter().applyAsDouble(m), 1e-15, "TC01: wrong factor" + tc);
            // TC02: negative (-0.5) and NaN are rejected with the report's setter's message
            assertSameRejection(() -> twin.report().apply(new Material(), -0.5),
                    () -> twin.course().apply(new Material(), -0.5), "TC02" + tc);
            assertSameRejection(() -> twin.report().apply(new Material(), Double.NaN),
                    () -> twin.course().apply(new Material(), Double.NaN), "TC02" + tc);
        }
        // TC03: setnShininess returns this material and sets 20; -5 gets the message of setShininess
        Material m = new Material();
        assertSame(m, m.setnShininess(20), "TC03: setnShininess must return this");
        assertEquals(20, m.getShininess(), "TC03: wrong shininess");
        assertSameRejection(() -> new Material().setShininess(-5), () -> new Material().setnShininess(-5), "TC03");
        // TC04: a chain of the course's names, as the course's tests write it, sets what the report's chain
        // sets: kD .3, kS .4, shininess 20, kT .5, kR .6, kG .1, kB .2
        Material course = new Material().setkD(0.3).setkS(0.4).setnShininess(20).setkT(0.5).setkR(0.6).setkG(0.1)
                .setkB(0.2);
        Material report = new Material().setKd(0.3).setKs(0.4).setShininess(20).setKt(0.5).setKr(0.6).setKg(0.1)
                .setKb(0.2);
        assertEquals(report.toString(), course.toString(), "TC04: the course's chain must set the same material");

        // ===== Boundary Values Tests =====
        for (Twin twin : TWINS) {
            String tc = " (" + twin.name() + ")";
            // TC10: 0 replaces 0.5 (0)
            Material half = twin.report().apply(new Material(), 0.5);
            assertEquals(0, twin.getter().applyAsDouble(twin.course().apply(half, 0.0)), 0,
                    "TC10: 0 must be accepted" + tc);
            // TC11: the negative value closest to 0 (-Double.MIN_VALUE) gets the report's setter's message
            assertSameRejection(() -> twin.report().apply(new Material(), -Double.MIN_VALUE),
                    () -> twin.course().apply(new Material(), -Double.MIN_VALUE), "TC11" + tc);
            if (twin.fraction()) {
                // TC12: a fraction's 1 is accepted (1), and just above 1 gets the report's setter's message
                assertEquals(1, twin.getter().applyAsDouble(twin.course().apply(new Material(), 1.0)), 0,
                        "TC12: 1 must be accepted" + tc);
                assertSameRejection(() -> twin.report().apply(new Material(), Math.nextUp(1.0)),
                        () -> twin.course().apply(new Material(), Math.nextUp(1.0)), "TC12" + tc);
            }
        }
        // TC13: shininess 0 is accepted (0), and -1 gets the message of setShininess
        assertEquals(0, new Material().setnShininess(5).setnShininess(0).getShininess(), "TC13: 0 must be accepted");
        assertSameRejection(() -> new Material().setShininess(-1), () -> new Material().setnShininess(-1), "TC13");
    }

    /** Test method for {@link primitives.Material#setIor(double)}. */
    @Test
    void testSetIor() {
        Material m = new Material();
        // ===== Equivalence Partitions Tests =====
        // TC01: no ior by default (0): the course's straight-through refraction
        assertFalse(m.hasIor(), "TC01: no ior by default");
        assertEquals(0, m.getIor(), 0, "TC01: the default ior is 0, none");
        // TC02: glass's 1.5 is kept, and the setter returns the material
        assertSame(m, m.setIor(1.5), "TC02: setIor must return this");
        assertEquals(1.5, m.getIor(), 0, "TC02: wrong ior");
        assertTrue(m.hasIor(), "TC02: the material has an ior");
        // TC03: below 1, NaN and infinite are refused, naming the ior; the ior stays 1.5
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.setIor(0.5),
                "TC03: ior 0.5 must be refused");
        assertMessage(e, "ior", "TC03");
        assertMessage(e, "at least 1", "TC03");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> m.setIor(Double.NaN), "TC03: NaN"),
                "finite", "TC03");
        assertThrows(IllegalArgumentException.class, () -> m.setIor(Double.POSITIVE_INFINITY), "TC03: infinite");
        assertEquals(1.5, m.getIor(), 0, "TC03: a refused ior must not change it");

        // ===== Boundary Values Tests =====
        // TC11: 1 is accepted (no bending); just below 1 and 0 are refused
        assertEquals(1, new Material().setIor(1).getIor(), 0, "TC11: ior 1 must be accepted");
        assertThrows(IllegalArgumentException.class, () -> m.setIor(Math.nextDown(1.0)), "TC11: just below 1");
        assertThrows(IllegalArgumentException.class, () -> m.setIor(0), "TC11: ior 0");
    }

    /** Test method for {@link primitives.Material#setFresnel(boolean)}. */
    @Test
    void testSetFresnel() {
        // ===== Equivalence Partitions Tests =====
        // TC01: off by default; on, with an ior, it is kept and the setter returns the material
        Material m = new Material().setIor(1.5);
        assertFalse(m.isFresnel(), "TC01: Fresnel is off by default");
        assertSame(m, m.setFresnel(true), "TC01: setFresnel must return this");
        assertTrue(m.isFresnel(), "TC01: Fresnel must be on");
        // TC02: Fresnel without an ior is refused, saying what to set first
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Material().setFresnel(true), "TC02: Fresnel needs an ior");
        assertMessage(e, "setIor", "TC02");

        // ===== Boundary Values Tests =====
        // TC11: turning it off needs no ior, and the material's text names the ior only when there is one
        assertFalse(new Material().setFresnel(false).isFresnel(), "TC11: off without an ior");
        assertFalse(new Material().toString().contains("ior"), "TC11: no ior in the text");
        assertTrue(m.toString().contains("ior=1.5, fresnel=true"), "TC11: the ior in the text: " + m);
    }

    /**
     * Checks a spread factor's setter (glossiness or blurriness): kept in [0, 1], rejected outside
     * with a message naming it, chained.
     */
    private static void assertSpread(String name, BiFunction<Material, Double, Material> setter,
                                     ToDoubleFunction<Material> getter) {
        Material m = new Material();
        // ===== Equivalence Partitions Tests =====
        // TC01: 0.2 is kept, and the setter returns the material
        assertSame(m, setter.apply(m, 0.2), "TC01: the " + name + " setter must return this");
        assertEquals(0.2, getter.applyAsDouble(m), 1e-15, "TC01: wrong " + name);
        // TC02: negative is rejected, the message names it and "negative"; the value stays 0.2
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> setter.apply(m, -0.3),
                "TC02: negative " + name + " must be rejected");
        assertMessage(e, name, "TC02");
        assertMessage(e, "negative", "TC02");
        assertEquals(0.2, getter.applyAsDouble(m), 1e-15, "TC02: a rejected " + name + " must not change it");
        // TC03: above 1 is rejected ("at most 1")
        e = assertThrows(IllegalArgumentException.class, () -> setter.apply(m, 3.0),
                "TC03: " + name + " above 1 must be rejected");
        assertMessage(e, name, "TC03");
        assertMessage(e, "at most 1", "TC03");
        // TC04: NaN and infinite are rejected ("finite")
        e = assertThrows(IllegalArgumentException.class, () -> setter.apply(m, Double.NaN),
                "TC04: NaN " + name + " must be rejected");
        assertMessage(e, "finite", "TC04");
        e = assertThrows(IllegalArgumentException.class, () -> setter.apply(m, Double.POSITIVE_INFINITY),
                "TC04: infinite " + name + " must be rejected");
        assertMessage(e, "finite", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: 0 is accepted (0: sharp)
        assertEquals(0, getter.applyAsDouble(setter.apply(m, 0.0)), 0, "TC10: " + name + " 0 must be accepted");
        // TC11: 1 is accepted (1: 45° off the sharp ray)
        assertEquals(1, getter.applyAsDouble(setter.apply(m, 1.0)), 0, "TC11: " + name + " 1 must be accepted");
        // TC12: just above 1 is rejected (Math.nextUp(1))
        assertThrows(IllegalArgumentException.class, () -> setter.apply(m, Math.nextUp(1.0)),
                "TC12: " + name + " just above 1 must be rejected");
        // TC13: the negative value closest to 0 is rejected (-Double.MIN_VALUE)
        assertThrows(IllegalArgumentException.class, () -> setter.apply(m, -Double.MIN_VALUE),
                "TC13: " + name + " -MIN_VALUE must be rejected");
    }
}
