package lighting;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertSameRejection;
import static testutil.TestAssertions.assertSquareAxes;

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
        assertColor(60, 30, 12, new PointLight(I, POSITION).setKl(1).setKc(0).getIntensity(new Point3D(4, 6, 3)),
                "TC05: wrong linear attenuation");
        // TC06: quadratic only (kC 0, kQ 1) at d 10: I / 100 = (3, 1.5, 0.6)
        assertColor(3, 1.5, 0.6, new PointLight(I, POSITION).setKq(1).setKc(0).getIntensity(new Point3D(1, 12, 3)),
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
        // TC09: all attenuation factors 0 is rejected by the setter, the message names the "attenuation"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new PointLight(I, POSITION).setKc(0), "TC09: all-zero attenuation must be rejected");
        assertMessage(e, "attenuation", "TC09");
        // TC10: a null point is rejected, the message names the "point"
        e = assertThrows(IllegalArgumentException.class, () -> light.getIntensity(null),
                "TC10: null point must be rejected");
        assertMessage(e, "point", "TC10");

        // ===== Boundary Values Tests =====
        // TC11: at the light's own position (d 0) only kC counts: I / 1 = (300, 150, 60)
        assertColor(300, 150, 60, light.getIntensity(POSITION), "TC11: wrong intensity at d 0");
        // TC12: kC 0 at the light's own position makes the attenuation 0: rejected, naming the "attenuation"
        PointLight noConstant = new PointLight(I, POSITION).setKl(1).setKc(0);
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

    /** Test method for {@link lighting.PointLight#isAt(primitives.Point3D)}. */
    @Test
    void testIsAt() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: the light's position (1, 2, 3): true, and getL refuses it
        assertTrue(light.isAt(new Point3D(1, 2, 3)), "TC01: the light sits at its position");
        // TC02: another point (4, 6, 3): false, and getL gives its direction
        assertFalse(light.isAt(new Point3D(4, 6, 3)), "TC02: the light does not sit elsewhere");
        // TC03: a null point is refused, naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> light.isAt(null),
                "TC03: a null point must be refused"), "lit point must not be null", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: 1e-11 off the position, within the points' tolerance: true, as getL refuses it
        Point3D within = new Point3D(1, 2, 3 + 1e-11);
        assertTrue(light.isAt(within), "TC11: a point within the tolerance is the position");
        assertThrows(IllegalArgumentException.class, () -> light.getL(within), "TC11: getL must refuse it too");
        // TC12: 1e-6 off the position: false, as getL gives (0, 0, 1) there
        assertFalse(light.isAt(new Point3D(1, 2, 3 + 1e-6)), "TC12: a point 1e-6 away is not the position");
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
        // TC10: kC 0 is accepted when kL is not 0
        assertEquals(0, light.setKl(1).setKc(0).getKc(), 0, "TC10: kC 0 must be accepted");
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

    /**
     * Test method for {@link lighting.PointLight#setkC(double)}, {@link lighting.PointLight#setkL(double)} and
     * {@link lighting.PointLight#setkQ(double)}, the course's names of the report's setters.
     */
    @Test
    void testCourseSetterNames() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: each returns the light itself and sets its factor: kC 2, kL 4E-4, kQ 2E-5
        assertSame(light, light.setkC(2).setkL(4E-4).setkQ(2E-5), "TC01: the setters must return this");
        assertArrayEquals(new double[] { 2, 4E-4, 2E-5 }, new double[] { light.getKc(), light.getKl(), light.getKq() },
                0, "TC01: wrong kC, kL or kQ");
        // TC02: kC 1, kL 0.5, kQ 0.25 through the course's names at d 2: 1 + 1 + 1 = 3 -> (100, 50, 20)
        assertColor(100, 50, 20, new PointLight(I, POSITION).setkC(1).setkL(0.5).setkQ(0.25)
                .getIntensity(new Point3D(1, 2, 5)), "TC02: wrong intensity at d 2");
        // TC03: negative and NaN factors get the messages of the report's setters
        assertSameRejection(() -> new PointLight(I, POSITION).setKc(-1), () -> new PointLight(I, POSITION).setkC(-1),
                "TC03");
        assertSameRejection(() -> new PointLight(I, POSITION).setKl(Double.NaN),
                () -> new PointLight(I, POSITION).setkL(Double.NaN), "TC03");
        assertSameRejection(() -> new PointLight(I, POSITION).setKq(-2), () -> new PointLight(I, POSITION).setkQ(-2),
                "TC03");

        // ===== Boundary Values Tests =====
        // TC10: kC 0 is accepted once kL is 1 (0), and kL, kQ 0 are accepted (0)
        PointLight linear = new PointLight(I, POSITION).setkL(1).setkC(0);
        assertEquals(0, linear.getKc(), 0, "TC10: kC 0 must be accepted");
        assertEquals(0, new PointLight(I, POSITION).setkL(0).setkQ(0).getKq(), 0, "TC10: kQ 0 must be accepted");
        // TC11: all three factors 0 gets the message of setKc (infinitely bright light)
        assertSameRejection(() -> new PointLight(I, POSITION).setKc(0), () -> new PointLight(I, POSITION).setkC(0),
                "TC11");
    }

    /** Asserts that a vector is not null and of unit length. */
    private static void assertUnit(Vector u, String message) {
        assertNotNull(u, message + " (null)");
        assertEquals(1, u.length(), DELTA, message + " (length must be 1)");
    }

    /**
     * Asserts that the light's square seen from p faces p: U(p) and V(p) are unit, orthogonal to each
     * other and to l = getL(p), so |(U × V) · l| = 1.
     */
    private static void assertFacing(PointLight light, Point3D p, String tc) {
        assertSquareAxes(light.getU(p), light.getV(p), light.getL(p), tc);
    }

    /** Test method for {@link lighting.PointLight#setEdgesSize(double)} and {@link lighting.PointLight#getEdges()}. */
    @Test
    void testSetEdgesSize() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: the default edge is 0 (a true point light)
        assertEquals(0, light.getEdges(), 0, "TC01: default edge must be 0");
        // TC02: setEdgesSize(2.5) returns the light itself and getEdges gives 2.5
        assertSame(light, light.setEdgesSize(2.5), "TC02: setEdgesSize must return this");
        assertEquals(2.5, light.getEdges(), 0, "TC02: wrong edge");
        // TC03: a negative edge (-1) is rejected, the message names the "edge"; the edge stays 2.5
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light.setEdgesSize(-1),
                "TC03: negative edge must be rejected");
        assertMessage(e, "edge", "TC03");
        assertEquals(2.5, light.getEdges(), 0, "TC03: a rejected edge must leave the edge 2.5");
        // TC04: NaN and ±infinite edges are rejected, the message names the "edge"; the edge stays 2.5
        for (double bad : new double[] { Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY }) {
            e = assertThrows(IllegalArgumentException.class, () -> light.setEdgesSize(bad),
                    "TC04: edge " + bad + " must be rejected");
            assertMessage(e, "edge", "TC04");
        }
        assertEquals(2.5, light.getEdges(), 0, "TC04: a rejected edge must leave the edge 2.5");
        // TC05: the edge does not change the light's position (1, 2, 3) or intensity (300, 150, 60) at d 5
        assertEquals(new Point3D(1, 2, 3), light.getPosition(), "TC05: the edge must not move the light");
        assertColor(300, 150, 60, light.getIntensity(new Point3D(4, 6, 3)), "TC05: the edge must not change intensity");

        // ===== Boundary Values Tests =====
        // TC10: edge 0 is accepted (back to a point light) and returned
        assertSame(light, light.setEdgesSize(0), "TC10: setEdgesSize must return this");
        assertEquals(0, light.getEdges(), 0, "TC10: edge 0 must be accepted");
        // TC11: a tiny positive edge 1e-9 is accepted and returned
        assertEquals(1e-9, light.setEdgesSize(1e-9).getEdges(), 0, "TC11: edge 1e-9 must be accepted");
        // TC12: negative zero is not negative: accepted, the edge is 0
        assertEquals(0, light.setEdgesSize(-0.0).getEdges(), 0, "TC12: edge -0.0 must be accepted as 0");
    }

    /** Test method for {@link lighting.PointLight#getCenter()}. */
    @Test
    void testGetCenter() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the centre of the square is the light's position (1, 2, 3)
        PointLight light = new PointLight(I, POSITION);
        assertEquals(new Point3D(1, 2, 3), light.getCenter(), "TC01: the centre must be the position");
        assertEquals(light.getPosition(), light.getCenter(), "TC01: the centre must be getPosition()");
        // TC02: with an edge 4 and U, V set the centre is still (1, 2, 3)
        light.setEdgesSize(4).setUV(new Vector(1, 0, 0), new Vector(0, 1, 0));
        assertEquals(new Point3D(1, 2, 3), light.getCenter(), "TC02: the square must stay centred at the position");

        // ===== Boundary Values Tests =====
        // TC10: a light at the origin has its centre at the origin (0, 0, 0)
        assertEquals(Point3D.ZERO, new PointLight(I, Point3D.ZERO).getCenter(), "TC10: wrong centre at the origin");
    }

    /** Test method for {@link PointLight#isUVSet()}: true only after setUV. */
    @Test
    void testIsUVSet() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a point light without setUV: false
        assertFalse(new PointLight(I, POSITION).isUVSet(), "TC01: no U and V were set");
        // TC02: after setUV: true
        assertTrue(new PointLight(I, POSITION).setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)).isUVSet(),
                "TC02: U and V were set");
        // ===== Boundary Values Tests =====
        // TC11: a spot light without setUV has a square of its own (getU() not null) but none set: false
        SpotLight spot = new SpotLight(I, POSITION, new Vector(0, 0, -1));
        assertNotNull(spot.getU(), "TC11: a spot light chooses its U");
        assertFalse(spot.isUVSet(), "TC11: a chosen square is not a set one");
        // TC12: the spot light after setUV with the very square it chose: true
        assertTrue(spot.setUV(spot.getU(), spot.getV()).isUVSet(), "TC12: U and V were set");
    }

    /** Test method for {@link lighting.PointLight#setUV(primitives.Vector, primitives.Vector)}, {@link lighting.PointLight#getU()} and {@link lighting.PointLight#getV()}. */
    @Test
    void testSetUV() {
        PointLight light = new PointLight(I, POSITION);
        // ===== Equivalence Partitions Tests =====
        // TC01: before setUV, getU() and getV() are null
        assertNull(light.getU(), "TC01: U must be null before setUV");
        assertNull(light.getV(), "TC01: V must be null before setUV");
        // TC02: setUV((2, 0, 0), (0, 0, 3)) returns the light, stores the units (1, 0, 0) and (0, 0, 1),
        // and leaves the caller's vectors unchanged
        Vector u = new Vector(2, 0, 0);
        Vector v = new Vector(0, 0, 3);
        assertSame(light, light.setUV(u, v), "TC02: setUV must return this");
        assertEquals(new Vector(1, 0, 0), light.getU(), "TC02: wrong U");
        assertEquals(new Vector(0, 0, 1), light.getV(), "TC02: wrong V");
        assertUnit(light.getU(), "TC02: U must be unit");
        assertUnit(light.getV(), "TC02: V must be unit");
        assertEquals(new Vector(2, 0, 0), u, "TC02: the caller's U changed");
        assertEquals(2, u.length(), DELTA, "TC02: the caller's U changed length");
        assertEquals(new Vector(0, 0, 3), v, "TC02: the caller's V changed");
        assertEquals(3, v.length(), DELTA, "TC02: the caller's V changed length");
        // TC03: general orthogonal (1, 2, 3) and (0, 3, -2) become (1, 2, 3)/sqrt14 and (0, 3, -2)/sqrt13
        double s14 = Math.sqrt(14);
        double s13 = Math.sqrt(13);
        light.setUV(new Vector(1, 2, 3), new Vector(0, 3, -2));
        assertEquals(new Vector(1 / s14, 2 / s14, 3 / s14), light.getU(), "TC03: wrong U");
        assertEquals(new Vector(0, 3 / s13, -2 / s13), light.getV(), "TC03: wrong V");
        assertEquals(0, light.getU().dotProduct(light.getV()), DELTA, "TC03: U·V must be 0");
        // TC04: U, V not orthogonal ((1, 0, 0), (1, 1, 0)) are rejected, the message names "orthogonal";
        // U and V stay as in TC03
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> light.setUV(new Vector(1, 0, 0), new Vector(1, 1, 0)), "TC04: non-orthogonal U, V accepted");
        assertMessage(e, "orthogonal", "TC04");
        assertEquals(new Vector(1 / s14, 2 / s14, 3 / s14), light.getU(), "TC04: a rejected U must leave U");
        assertEquals(new Vector(0, 3 / s13, -2 / s13), light.getV(), "TC04: a rejected V must leave V");
        // TC05: a null U or V is rejected with IllegalArgumentException (not NullPointerException), naming "null"
        e = assertThrows(IllegalArgumentException.class, () -> light.setUV(null, new Vector(0, 1, 0)),
                "TC05: null U must be rejected");
        assertMessage(e, "null", "TC05");
        e = assertThrows(IllegalArgumentException.class, () -> light.setUV(new Vector(1, 0, 0), null),
                "TC05: null V must be rejected");
        assertMessage(e, "null", "TC05");
        e = assertThrows(IllegalArgumentException.class, () -> light.setUV(null, null),
                "TC05: null U and V must be rejected");
        assertMessage(e, "null", "TC05");

        // ===== Boundary Values Tests =====
        // TC10: parallel U, V ((1, 0, 0), (3, 0, 0)) are rejected, the message names "orthogonal"
        e = assertThrows(IllegalArgumentException.class,
                () -> light.setUV(new Vector(1, 0, 0), new Vector(3, 0, 0)), "TC10: parallel U, V accepted");
        assertMessage(e, "orthogonal", "TC10");
        // TC11: opposite U, V ((0, 1, 0), (0, -1, 0)) are rejected, the message names "orthogonal"
        e = assertThrows(IllegalArgumentException.class,
                () -> light.setUV(new Vector(0, 1, 0), new Vector(0, -1, 0)), "TC11: opposite U, V accepted");
        assertMessage(e, "orthogonal", "TC11");
        // TC12: nearly orthogonal U, V (unit dot product about 1e-3) are rejected, naming "orthogonal"
        e = assertThrows(IllegalArgumentException.class,
                () -> light.setUV(new Vector(1, 0, 0), new Vector(1e-3, 1, 0)), "TC12: nearly orthogonal U, V accepted");
        assertMessage(e, "orthogonal", "TC12");
        // TC13: orthogonal U, V of very different lengths (1e-6, 0, 0), (0, 1e6, 0): units (1, 0, 0), (0, 1, 0)
        light.setUV(new Vector(1e-6, 0, 0), new Vector(0, 1e6, 0));
        assertEquals(new Vector(1, 0, 0), light.getU(), "TC13: wrong U");
        assertEquals(new Vector(0, 1, 0), light.getV(), "TC13: wrong V");
        // TC14: a second setUV replaces the first: (0, 0, -1), (1, 0, 0)
        light.setUV(new Vector(0, 0, -5), new Vector(7, 0, 0));
        assertEquals(new Vector(0, 0, -1), light.getU(), "TC14: setUV must replace U");
        assertEquals(new Vector(1, 0, 0), light.getV(), "TC14: setUV must replace V");
    }

    /** Test method for {@link lighting.PointLight#getU(primitives.Point3D)} and {@link lighting.PointLight#getV(primitives.Point3D)} when U, V were set. */
    @Test
    void testGetUVAtPointWhenSet() {
        PointLight light = new PointLight(I, POSITION).setUV(new Vector(0, 3, 0), new Vector(0, 0, -2));
        Point3D[] points = { new Point3D(4, 6, 3), new Point3D(-1, 0, 2), new Point3D(1, 2, 13),
                new Point3D(11, 2, 3), new Point3D(-100, 50, 7) };
        // ===== Equivalence Partitions Tests =====
        // TC01: for points in any direction, U(p) = (0, 1, 0) and V(p) = (0, 0, -1), the set vectors
        for (Point3D p : points) {
            assertEquals(new Vector(0, 1, 0), light.getU(p), "TC01: U(p) must be the set U at " + p);
            assertEquals(new Vector(0, 0, -1), light.getV(p), "TC01: V(p) must be the set V at " + p);
        }

        // ===== Boundary Values Tests =====
        // TC10: a point along the set U from the light, (1, 12, 3): still U(p) = (0, 1, 0), V(p) = (0, 0, -1)
        Point3D alongU = new Point3D(1, 12, 3);
        assertEquals(new Vector(0, 1, 0), light.getU(alongU), "TC10: U(p) must be the set U");
        assertEquals(new Vector(0, 0, -1), light.getV(alongU), "TC10: V(p) must be the set V");
    }

    /** Test method for {@link lighting.PointLight#getU(primitives.Point3D)} and {@link lighting.PointLight#getV(primitives.Point3D)} when U, V were not set (the square faces the point). */
    @Test
    void testGetUVAtPointWhenUnset() {
        PointLight light = new PointLight(I, POSITION).setEdgesSize(2);
        // ===== Equivalence Partitions Tests =====
        // TC01: point (4, 6, 3), l = (0.6, 0.8, 0): U(p), V(p) unit, orthogonal to each other and to l
        assertFacing(light, new Point3D(4, 6, 3), "TC01");
        // TC02: point (-1, 0, 2), l = (-2/3, -2/3, -1/3): U(p), V(p) unit, orthogonal to each other and to l
        assertFacing(light, new Point3D(-1, 0, 2), "TC02");
        // TC03: 500 points drawn from Random(7) in [-50, 50)³: the square faces each of them
        java.util.Random random = new java.util.Random(7);
        for (int i = 0; i < 500; ++i)
            assertFacing(light, new Point3D(random.nextDouble() * 100 - 50, random.nextDouble() * 100 - 50,
                    random.nextDouble() * 100 - 50), "TC03 (point " + i + ")");
        // TC04: deterministic: the same point, and an equal point, give equal U(p) and V(p)
        Point3D p = new Point3D(4, 6, 3);
        assertEquals(light.getU(p), light.getU(p), "TC04: U(p) must be deterministic");
        assertEquals(light.getV(p), light.getV(p), "TC04: V(p) must be deterministic");
        assertEquals(light.getU(p), light.getU(new Point3D(4, 6, 3)), "TC04: equal points must give equal U(p)");
        assertEquals(light.getV(p), light.getV(new Point3D(4, 6, 3)), "TC04: equal points must give equal V(p)");
        // TC05: points on the same ray from the light, (4, 6, 3) and (7, 10, 3), see the same square
        assertEquals(light.getU(p), light.getU(new Point3D(7, 10, 3)), "TC05: same direction must give the same U");
        assertEquals(light.getV(p), light.getV(new Point3D(7, 10, 3)), "TC05: same direction must give the same V");
        // TC06: asking U(p), V(p) does not set U, V: getU() and getV() stay null
        assertNull(light.getU(), "TC06: getU(p) must not set U");
        assertNull(light.getV(), "TC06: getV(p) must not set V");
        // TC07: a null point is rejected with IllegalArgumentException, the message names the "point"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light.getU(null),
                "TC07: null point must be rejected by getU");
        assertMessage(e, "point", "TC07");
        e = assertThrows(IllegalArgumentException.class, () -> light.getV(null),
                "TC07: null point must be rejected by getV");
        assertMessage(e, "point", "TC07");

        // ===== Boundary Values Tests =====
        // TC10: points along each coordinate axis from the light, both senses (l = ±x, ±y, ±z): facing squares
        Point3D[] onAxes = { new Point3D(11, 2, 3), new Point3D(-9, 2, 3), new Point3D(1, 12, 3),
                new Point3D(1, -8, 3), new Point3D(1, 2, 13), new Point3D(1, 2, -7) };
        for (Point3D a : onAxes)
            assertFacing(light, a, "TC10 at " + a);
        // TC11: a point very near the light, (1, 2, 3 + 1e-6): facing square, l = (0, 0, 1)
        assertFacing(light, new Point3D(1, 2, 3 + 1e-6), "TC11");
        // TC12: a point very far, (1e6, -2e6, 3e6): facing square
        assertFacing(light, new Point3D(1e6, -2e6, 3e6), "TC12");
        // TC13: the light's own position has no direction: rejected, the message names the "position"
        e = assertThrows(IllegalArgumentException.class, () -> light.getU(new Point3D(1, 2, 3)),
                "TC13: U at the light's position must be rejected");
        assertMessage(e, "position", "TC13");
        e = assertThrows(IllegalArgumentException.class, () -> light.getV(new Point3D(1, 2, 3)),
                "TC13: V at the light's position must be rejected");
        assertMessage(e, "position", "TC13");
    }
}
