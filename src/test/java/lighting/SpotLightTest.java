package lighting;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

/**
 * Unit tests for {@link lighting.SpotLight}: a light at the origin shining down the -z axis.
 */
class SpotLightTest {
    /** Tolerance for comparing doubles. */
    private static final double DELTA = 1e-10;
    /** The light's intensity. */
    private static final Color I = new Color(200, 100, 40);
    /** sqrt(3). */
    private static final double SQRT3 = Math.sqrt(3);
    /** A point on the axis at distance 10. */
    private static final Point3D ON_AXIS = new Point3D(0, 0, -10);
    /** A point 60 degrees off the axis at distance 2 (dir·l = 0.5). */
    private static final Point3D AT_60 = new Point3D(SQRT3, 0, -1);

    /** @return a fresh spot light at the origin toward -z, given as the non-unit (0, 0, -5) */
    private static SpotLight light() {
        return new SpotLight(I, Point3D.ZERO, new Vector(0, 0, -5));
    }

    /** Test method for {@link lighting.SpotLight#SpotLight(primitives.Color, primitives.Point3D, primitives.Vector)}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: direction (0, 3, -4) is kept as the unit (0, 0.6, -0.8), caller's vector unchanged; beam 1
        Vector d = new Vector(0, 3, -4);
        SpotLight spot = new SpotLight(I, new Point3D(1, 1, 1), d);
        assertEquals(new Vector(0, 0.6, -0.8), spot.getDirection(), "TC01: wrong direction");
        assertEquals(1, spot.getDirection().length(), DELTA, "TC01: direction must be unit");
        assertEquals(0, d.getX(), 0, "TC01: caller's vector changed");
        assertEquals(3, d.getY(), 0, "TC01: caller's vector changed");
        assertEquals(-4, d.getZ(), 0, "TC01: caller's vector changed");
        assertEquals(new Point3D(1, 1, 1), spot.getPosition(), "TC01: wrong position");
        assertEquals(1, spot.getNarrowBeam(), 0, "TC01: default narrow beam must be 1");
        assertEquals(1, spot.getKc(), 0, "TC01: default kC must be 1");
        assertEquals(0, spot.getKl(), 0, "TC01: default kL must be 0");
        assertEquals(0, spot.getKq(), 0, "TC01: default kQ must be 0");
        // TC02: a null direction is rejected, the message names the "direction"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new SpotLight(I, Point3D.ZERO, null), "TC02: null direction must be rejected");
        assertMessage(e, "direction", "TC02");
        // TC03: a null position is rejected, the message names the "position"
        e = assertThrows(IllegalArgumentException.class,
                () -> new SpotLight(I, null, new Vector(0, 0, -1)), "TC03: null position must be rejected");
        assertMessage(e, "position", "TC03");
    }

    /** Test method for {@link lighting.SpotLight#getIntensity(primitives.Point3D)}. */
    @Test
    void testGetIntensity() {
        SpotLight spot = light();
        // ===== Equivalence Partitions Tests =====
        // TC01: a point on the axis gets the full point-light intensity (200, 100, 40)
        assertColor(200, 100, 40, spot.getIntensity(ON_AXIS), "TC01: wrong intensity on the axis");
        // TC02: a point 60° off the axis gets half: (100, 50, 20)
        assertColor(100, 50, 20, spot.getIntensity(AT_60), "TC02: wrong intensity at 60°");
        // TC03: another point 60° off the axis, (0, 5·sqrt3, -5), also gets (100, 50, 20)
        assertColor(100, 50, 20, spot.getIntensity(new Point3D(0, 5 * SQRT3, -5)), "TC03: wrong intensity at 60°");
        // TC04: a point behind the light (0, 0, 10) gets black
        assertColor(0, 0, 0, spot.getIntensity(new Point3D(0, 0, 10)), "TC04: behind the light must be black");
        // TC05: a point obliquely behind (3, 4, 1) gets black
        assertColor(0, 0, 0, spot.getIntensity(new Point3D(3, 4, 1)), "TC05: behind the light must be black");
        // TC06: on the axis with kL 0.1 at d 10: attenuation 2 -> (100, 50, 20)
        assertColor(100, 50, 20, light().setKl(0.1).getIntensity(ON_AXIS), "TC06: wrong attenuated intensity");
        // TC07: 60° with kQ 0.25 at d 2: attenuation 2, factor 0.5 -> (50, 25, 10)
        assertColor(50, 25, 10, light().setKq(0.25).getIntensity(AT_60), "TC07: wrong attenuated intensity at 60°");
        // TC08: kC 0.5, kL 0.1, kQ 0.01, beam 2, 60° at d 10: 0.25 / 2.5 -> (20, 10, 4)
        assertColor(20, 10, 4, light().setKc(0.5).setKl(0.1).setKq(0.01).setNarrowBeam(2)
                .getIntensity(new Point3D(0, 5 * SQRT3, -5)), "TC08: wrong combined intensity");
        // TC09: all attenuation factors 0 on the axis is rejected, the message names the "attenuation"
        SpotLight dark = light().setKc(0);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> dark.getIntensity(ON_AXIS),
                "TC09: all-zero attenuation must be rejected");
        assertMessage(e, "attenuation", "TC09");

        // ===== Boundary Values Tests =====
        // TC10: a point at 90° (10, 0, 0), dir·l = 0, gets black
        assertColor(0, 0, 0, spot.getIntensity(new Point3D(10, 0, 0)), "TC10: at 90° must be black");
        // TC11: a point just in front of 90° (10, 0, -1e-6) gets a tiny positive intensity 200·1e-7
        Color c = spot.getIntensity(new Point3D(10, 0, -1e-6));
        assertEquals(200 * 1e-7, c.getR(), 1e-12, "TC11: wrong intensity just inside 90°");
        assertTrue(c.getR() > 0, "TC11: intensity just inside 90° must be positive");
        // TC12: at the light's own position there is no direction: rejected, naming the "position"
        e = assertThrows(IllegalArgumentException.class, () -> spot.getIntensity(Point3D.ZERO),
                "TC12: intensity at the light's position must be rejected");
        assertMessage(e, "position", "TC12");
    }

    /** Test method for {@link lighting.SpotLight#getL(primitives.Point3D)} and {@link lighting.SpotLight#getDistance(primitives.Point3D)}. */
    @Test
    void testGetLAndDistance() {
        SpotLight spot = light();
        // ===== Equivalence Partitions Tests =====
        // TC01: at 60°, l = (sqrt3/2, 0, -1/2) and the distance is 2
        Vector l = spot.getL(AT_60);
        assertEquals(new Vector(SQRT3 / 2, 0, -0.5), l, "TC01: wrong l");
        assertEquals(1, l.length(), DELTA, "TC01: l must be unit");
        assertEquals(0.5, l.dotProduct(spot.getDirection()), DELTA, "TC01: dir·l must be 0.5");
        assertEquals(2, spot.getDistance(AT_60), DELTA, "TC01: wrong distance");
        // TC02: behind the light, l is still defined: (0, 0, 1), distance 10
        assertEquals(new Vector(0, 0, 1), spot.getL(new Point3D(0, 0, 10)), "TC02: wrong l behind");
        assertEquals(10, spot.getDistance(new Point3D(0, 0, 10)), DELTA, "TC02: wrong distance behind");
    }

    /** Test method for {@link lighting.SpotLight#setNarrowBeam(double)}. */
    @Test
    void testSetNarrowBeam() {
        // ===== Equivalence Partitions Tests =====
        // TC01: setNarrowBeam(2) returns this; at 60° the factor is 0.5² = 0.25 -> (50, 25, 10)
        SpotLight spot = light();
        assertSame(spot, spot.setNarrowBeam(2), "TC01: setNarrowBeam must return this");
        assertEquals(2, spot.getNarrowBeam(), 0, "TC01: wrong narrow beam");
        assertColor(50, 25, 10, spot.getIntensity(AT_60), "TC01: wrong intensity at 60° with beam 2");
        // TC02: beam 3 at 60°: 0.5³ = 0.125 -> (25, 12.5, 5)
        assertColor(25, 12.5, 5, light().setNarrowBeam(3).getIntensity(AT_60), "TC02: wrong intensity with beam 3");
        // TC03: beam 0.5 widens: 0.5^0.5 at 60° -> I·sqrt(0.5)
        double f = Math.sqrt(0.5);
        assertColor(200 * f, 100 * f, 40 * f, light().setNarrowBeam(0.5).getIntensity(AT_60),
                "TC03: wrong intensity with beam 0.5");
        // TC04: on the axis the factor stays 1 whatever the beam: (200, 100, 40) with beam 50
        assertColor(200, 100, 40, light().setNarrowBeam(50).getIntensity(ON_AXIS),
                "TC04: on the axis the beam must not matter");
        // TC05: behind the light stays black with beam 0.5
        assertColor(0, 0, 0, light().setNarrowBeam(0.5).getIntensity(new Point3D(0, 0, 10)),
                "TC05: behind the light must be black");
        // TC06: a negative, NaN or infinite beam is rejected, the message names the "narrow beam"
        for (double bad : new double[] { -2, Double.NaN, Double.POSITIVE_INFINITY }) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> light().setNarrowBeam(bad), "TC06: beam " + bad + " must be rejected");
            assertMessage(e, "narrow beam", "TC06");
        }

        // ===== Boundary Values Tests =====
        // TC10: beam 0 is rejected, the message names the "narrow beam"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light().setNarrowBeam(0),
                "TC10: beam 0 must be rejected");
        assertMessage(e, "narrow beam", "TC10");
        // TC11: beam 1 is the plain spot: (100, 50, 20) at 60°
        assertColor(100, 50, 20, light().setNarrowBeam(1).getIntensity(AT_60), "TC11: beam 1 must be the plain spot");
        // TC12: for k = 1..8 the factor at 60° is exactly 0.5^k
        for (int k = 1; k <= 8; ++k)
            assertEquals(200 * Math.pow(0.5, k), light().setNarrowBeam(k).getIntensity(AT_60).getR(), DELTA,
                    "TC12: wrong factor at 60° for beam " + k);
    }

    /** Test method for the chainable {@link lighting.SpotLight#setKc(double)}, {@link lighting.SpotLight#setKl(double)} and {@link lighting.SpotLight#setKq(double)}. */
    @Test
    void testAttenuationSetters() {
        // ===== Equivalence Partitions Tests =====
        // TC01: each setter returns the SpotLight itself, chainable with setNarrowBeam
        SpotLight spot = light();
        SpotLight chained = spot.setKc(0.5).setKl(4E-4).setNarrowBeam(2).setKq(2E-5);
        assertSame(spot, chained, "TC01: the setters must return this");
        assertSame(spot, spot.setKc(0.5), "TC01: setKc must return this");
        assertSame(spot, spot.setKl(4E-4), "TC01: setKl must return this");
        assertSame(spot, spot.setKq(2E-5), "TC01: setKq must return this");
        assertEquals(0.5, spot.getKc(), 0, "TC01: wrong kC");
        assertEquals(4E-4, spot.getKl(), 0, "TC01: wrong kL");
        assertEquals(2E-5, spot.getKq(), 0, "TC01: wrong kQ");
        assertEquals(2, spot.getNarrowBeam(), 0, "TC01: wrong narrow beam");
        // TC02: negative and NaN factors are rejected, the message names the factor
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light().setKc(-1),
                "TC02: negative kC must be rejected");
        assertMessage(e, "kC", "TC02");
        e = assertThrows(IllegalArgumentException.class, () -> light().setKl(Double.NaN),
                "TC02: NaN kL must be rejected");
        assertMessage(e, "kL", "TC02");
        e = assertThrows(IllegalArgumentException.class, () -> light().setKq(-1e-3),
                "TC02: negative kQ must be rejected");
        assertMessage(e, "kQ", "TC02");

        // ===== Boundary Values Tests =====
        // TC10: factors 0 are accepted (kC 0 with kL 1: on the axis at d 10 -> I / 10 = (20, 10, 4))
        assertColor(20, 10, 4, light().setKc(0).setKl(1).setKq(0).getIntensity(ON_AXIS),
                "TC10: wrong intensity with kC 0, kL 1");
    }
}
