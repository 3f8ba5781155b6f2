package lighting;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

/**
 * Unit tests for {@link lighting.PointLight}.
 */
class PointLightTest {
    /** Tolerance for comparing doubles. */
    private static final double DELTA = 1e-10;
    /** The light's position in most tests. */
    private static final Point3D POSITION = new Point3D(1, 2, 3);
    /** The light's intensity in most tests. */
    private static final Color I = new Color(300, 150, 60);

    /** Test method for {@link lighting.PointLight#PointLight(primitives.Color, primitives.Point3D)}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: position (1, 2, 3), intensity (300, 150, 60), defaults kC 1, kL 0, kQ 0
        PointLight light = new PointLight(I, POSITION);
        assertEquals(new Point3D(1, 2, 3), light.getPosition(), "TC01: wrong position");
        assertEquals(new Color(300, 150, 60), light.getIntensity(), "TC01: wrong intensity");
        assertEquals(1, light.getKc(), 0, "TC01: default kC must be 1");
        assertEquals(0, light.getKl(), 0, "TC01: default kL must be 0");
        assertEquals(0, light.getKq(), 0, "TC01: default kQ must be 0");
        // TC02: a null position is rejected, the message names the "position"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new PointLight(I, null),
                "TC02: null position must be rejected");
        assertMessage(e, "position", "TC02");
        // TC03: a null intensity is rejected, the message names the "intensity"
        e = assertThrows(IllegalArgumentException.class, () -> new PointLight(null, POSITION),
                "TC03: null intensity must be rejected");
        assertMessage(e, "intensity", "TC03");
    }

    /** Test method for {@link lighting.PointLight#getIntensity(primitives.Point3D)}. */
    @Test
    void testGetIntensity() {
        // ===== Equivalence Partitions Tests =====
        // TC01: defaults (kC 1, kL 0, kQ 0) mean no attenuation: (300, 150, 60) at distance 10 and 1000
        PointLight plain = new PointLight(I, POSITION);
        assertColor(300, 150, 60, plain.getIntensity(new Point3D(1, 2, 13)), "TC01: wrong intensity at d 10");
        assertColor(300, 150, 60, plain.getIntensity(new Point3D(1001, 2, 3)), "TC01: wrong intensity at d 1000");

        PointLight light = new PointLight(I, POSITION).setKc(1).setKl(0.5).setKq(0.25);
        // TC02: kC 1, kL 0.5, kQ 0.25 at d 2: 1 + 1 + 1 = 3 -> (100, 50, 20)
        assertColor(100, 50, 20, light.getIntensity(new Point3D(1, 2, 5)), "TC02: wrong intensity at d 2");
        // TC03: same light at d 4: 1 + 2 + 4 = 7 -> (300/7, 150/7, 60/7)
        assertColor(300d / 7, 150d / 7, 60d / 7, light.getIntensity(new Point3D(1, 2, -1)),
                "TC03: wrong intensity at d 4");
        // TC04: same light at d 5 off the axes (4, 6, 3): 1 + 2.5 + 6.25 = 9.75 -> I / 9.75
        assertColor(300 / 9.75, 150 / 9.75, 60 / 9.75, light.getIntensity(new Point3D(4, 6, 3)),
                "TC04: wrong intensity at d 5");
        // TC05: linear only (kC 0, kL 1) at d 5: I / 5 = (60, 30, 12)
        assertColor(60, 30, 12, new PointLight(I, POSITION).setKc(0).setKl(1).getIntensity(new Point3D(4, 6, 3)),
                "TC05: wrong linear attenuation");
        // TC06: quadratic only (kC 0, kQ 1) at d 10: I / 100 = (3, 1.5, 0.6)
        assertColor(3, 1.5, 0.6, new PointLight(I, POSITION).setKc(0).setKq(1).getIntensity(new Point3D(1, 12, 3)),
                "TC06: wrong quadratic attenuation");
        // TC07: constant only (kC 2) at any distance: I / 2 = (150, 75, 30)
        PointLight constant = new PointLight(I, POSITION).setKc(2);
        assertColor(150, 75, 30, constant.getIntensity(new Point3D(4, 6, 3)), "TC07: wrong constant attenuation");
        assertColor(150, 75, 30, constant.getIntensity(new Point3D(-500, 2, 3)), "TC07: wrong constant attenuation");
        // TC08: attenuation lowers the intensity with distance: red strictly decreasing over d = 0..20
        PointLight fading = new PointLight(I, POSITION).setKl(0.1).setKq(0.01);
        double previous = Double.POSITIVE_INFINITY;
        for (int d = 0; d <= 20; ++d) {
            double red = fading.getIntensity(new Point3D(1 + d, 2, 3)).getR();
            assertEquals(300 / (1 + 0.1 * d + 0.01 * d * d), red, DELTA, "TC08: wrong intensity at d " + d);
            assertTrue(red < previous, "TC08: intensity must fall with distance, at d " + d);
            previous = red;
        }
        // TC09: all attenuation factors 0 is rejected, the message names the "attenuation"
        PointLight dark = new PointLight(I, POSITION).setKc(0);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> dark.getIntensity(new Point3D(4, 6, 3)), "TC09: all-zero attenuation must be rejected");
        assertMessage(e, "attenuation", "TC09");
        // TC10: a null point is rejected, the message names the "point"
        e = assertThrows(IllegalArgumentException.class, () -> light.getIntensity(null),
                "TC10: null point must be rejected");
        assertMessage(e, "point", "TC10");

        // ===== Boundary Values Tests =====
        // TC11: at the light's own position (d 0) only kC counts: I / 1 = (300, 150, 60)
        assertColor(300, 150, 60, light.getIntensity(POSITION), "TC11: wrong intensity at d 0");
        // TC12: kC 0 at the light's own position makes the attenuation 0: rejected, naming the "attenuation"
        PointLight noConstant = new PointLight(I, POSITION).setKc(0).setKl(1);
        e = assertThrows(IllegalArgumentException.class, () -> noConstant.getIntensity(POSITION),
                "TC12: zero attenuation at d 0 must be rejected");
        assertMessage(e, "attenuation", "TC12");
        // TC13: a black light stays black (0, 0, 0) at d 5
        assertColor(0, 0, 0, new PointLight(Color.BLACK, POSITION).getIntensity(new Point3D(4, 6, 3)),
                "TC13: black light must stay black");
    }

    /** Test method for {@link lighting.PointLight#getL(primitives.Point3D)}. */
    @Test
    void testGetL() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: point (4, 6, 3): l = (0.6, 0.8, 0), from the light to the point
        Vector l = light.getL(new Point3D(4, 6, 3));
        assertEquals(new Vector(0.6, 0.8, 0), l, "TC01: wrong l");
        assertEquals(1, l.length(), DELTA, "TC01: l must be unit");
        // TC02: point (-1, 0, 2): l = (-2/3, -2/3, -1/3)
        l = light.getL(new Point3D(-1, 0, 2));
        assertEquals(new Vector(-2d / 3, -2d / 3, -1d / 3), l, "TC02: wrong l");
        assertEquals(1, l.length(), DELTA, "TC02: l must be unit");
        // TC03: point on an axis through the light, (1, 2, -7): l = (0, 0, -1)
        assertEquals(new Vector(0, 0, -1), light.getL(new Point3D(1, 2, -7)), "TC03: wrong l");
        // TC04: a null point is rejected, the message names the "point"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light.getL(null),
                "TC04: null point must be rejected");
        assertMessage(e, "point", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: the light's own position has no direction: rejected, the message names the "position"
        e = assertThrows(IllegalArgumentException.class, () -> light.getL(new Point3D(1, 2, 3)),
                "TC10: l at the light's position must be rejected");
        assertMessage(e, "position", "TC10");
        // TC11: a point very near the light, (1, 2, 3 + 1e-6): l = (0, 0, 1)
        l = light.getL(new Point3D(1, 2, 3 + 1e-6));
        assertEquals(new Vector(0, 0, 1), l, "TC11: wrong l near the light");
        assertEquals(1, l.length(), DELTA, "TC11: l must be unit");
    }

    /** Test method for {@link lighting.PointLight#getDistance(primitives.Point3D)}. */
    @Test
    void testGetDistance() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: point (4, 6, 3) is at distance 5
        assertEquals(5, light.getDistance(new Point3D(4, 6, 3)), DELTA, "TC01: wrong distance");
        // TC02: point (-1, 0, 2) is at distance 3
        assertEquals(3, light.getDistance(new Point3D(-1, 0, 2)), DELTA, "TC02: wrong distance");
        // TC03: a null point is rejected, the message names the "point"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light.getDistance(null),
                "TC03: null point must be rejected");
        assertMessage(e, "point", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: the light's own position is at distance 0
        assertEquals(0, light.getDistance(POSITION), DELTA, "TC10: wrong distance at the light");
    }

    /** Test method for {@link lighting.PointLight#setKc(double)}. */
    @Test
    void testSetKc() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: setKc(2) returns the light itself and sets kC 2
        assertSame(light, light.setKc(2), "TC01: setKc must return this");
        assertEquals(2, light.getKc(), 0, "TC01: wrong kC");
        // TC02: negative, NaN and infinite kC are rejected, the message names "kC"
        for (double bad : new double[] { -1, Double.NaN, Double.POSITIVE_INFINITY }) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light.setKc(bad),
                    "TC02: kC " + bad + " must be rejected");
            assertMessage(e, "kC", "TC02");
        }
        assertEquals(2, light.getKc(), 0, "TC02: a rejected kC must leave kC 2");

        // ===== Boundary Values Tests =====
        // TC10: kC 0 is accepted
        assertEquals(0, light.setKc(0).getKc(), 0, "TC10: kC 0 must be accepted");
        // TC11: kC -1e-12 is rejected, the message names "kC"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light.setKc(-1e-12),
                "TC11: kC -1e-12 must be rejected");
        assertMessage(e, "kC", "TC11");
    }

    /** Test method for {@link lighting.PointLight#setKl(double)}. */
    @Test
    void testSetKl() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: setKl(4E-4) returns the light itself and sets kL 4E-4
        assertSame(light, light.setKl(4E-4), "TC01: setKl must return this");
        assertEquals(4E-4, light.getKl(), 0, "TC01: wrong kL");
        // TC02: negative, NaN and infinite kL are rejected, the message names "kL"
        for (double bad : new double[] { -0.5, Double.NaN, Double.NEGATIVE_INFINITY }) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light.setKl(bad),
                    "TC02: kL " + bad + " must be rejected");
            assertMessage(e, "kL", "TC02");
        }
        assertEquals(4E-4, light.getKl(), 0, "TC02: a rejected kL must leave kL 4E-4");

        // ===== Boundary Values Tests =====
        // TC10: kL 0 is accepted
        assertEquals(0, light.setKl(0).getKl(), 0, "TC10: kL 0 must be accepted");
    }

    /** Test method for {@link lighting.PointLight#setKq(double)}. */
    @Test
    void testSetKq() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: setKq(2E-5) returns the light itself and sets kQ 2E-5
        assertSame(light, light.setKq(2E-5), "TC01: setKq must return this");
        assertEquals(2E-5, light.getKq(), 0, "TC01: wrong kQ");
        // TC02: negative, NaN and infinite kQ are rejected, the message names "kQ"
        for (double bad : new double[] { -2, Double.NaN, Double.POSITIVE_INFINITY }) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light.setKq(bad),
                    "TC02: kQ " + bad + " must be rejected");
            assertMessage(e, "kQ", "TC02");
        }
        assertEquals(2E-5, light.getKq(), 0, "TC02: a rejected kQ must leave kQ 2E-5");

        // ===== Boundary Values Tests =====
        // TC10: kQ 0 is accepted
        assertEquals(0, light.setKq(0).getKq(), 0, "TC10: kQ 0 must be accepted");
    }
}
