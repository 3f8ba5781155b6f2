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
        // TC09: all attenuation factors 0 is rejected by the setter, the message names the "attenuation"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> light().setKc(0),
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
        // TC03: at its own position the spot light sits (isAt), and l is refused
        Point3D position = spot.getPosition();
        assertTrue(spot.isAt(position), "TC03: the spot light sits at its position");
        assertThrows(IllegalArgumentException.class, () -> spot.getL(position), "TC03: l must be refused there");
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
        assertColor(20, 10, 4, light().setKl(1).setKc(0).setKq(0).getIntensity(ON_AXIS),
                "TC10: wrong intensity with kC 0, kL 1");
    }

    /**
     * Test method for the chainable {@link lighting.SpotLight#setkC(double)}, {@link lighting.SpotLight#setkL(double)}
     * and {@link lighting.SpotLight#setkQ(double)}, the course's names of the report's setters.
     */
    @Test
    void testCourseSetterNames() {
        // ===== Equivalence Partitions Tests =====
        // TC01: each returns the SpotLight itself, chainable with setNarrowBeam: kC 0.5, kL 4E-4, kQ 2E-5
        SpotLight spot = light();
        SpotLight chained = spot.setkC(0.5).setkL(4E-4).setNarrowBeam(2).setkQ(2E-5);
        assertSame(spot, chained, "TC01: the setters must return this");
        assertArrayEquals(new double[] { 0.5, 4E-4, 2E-5 }, new double[] { spot.getKc(), spot.getKl(), spot.getKq() },
                0, "TC01: wrong kC, kL or kQ");
        // TC02: kC 0.5, kL 0.1, kQ 0.01, beam 2, 60° at d 10: 0.25 / 2.5 -> (20, 10, 4)
        assertColor(20, 10, 4, light().setkC(0.5).setkL(0.1).setkQ(0.01).setNarrowBeam(2)
                .getIntensity(new Point3D(0, 5 * SQRT3, -5)), "TC02: wrong combined intensity");
        // TC03: negative and NaN factors get the messages of the report's setters
        assertSameRejection(() -> light().setKc(-1), () -> light().setkC(-1), "TC03");
        assertSameRejection(() -> light().setKl(Double.NaN), () -> light().setkL(Double.NaN), "TC03");
        assertSameRejection(() -> light().setKq(-1e-3), () -> light().setkQ(-1e-3), "TC03");

        // ===== Boundary Values Tests =====
        // TC10: kC 0 with kL 1: on the axis at d 10 -> I / 10 = (20, 10, 4)
        assertColor(20, 10, 4, light().setkL(1).setkC(0).setkQ(0).getIntensity(ON_AXIS),
                "TC10: wrong intensity with kC 0, kL 1");
        // TC11: all three factors 0 gets the message of setKc
        assertSameRejection(() -> light().setKc(0), () -> light().setkC(0), "TC11");
    }

    /**
     * Asserts the default square of a spot light: getU(), getV() non-null, unit, orthogonal to each
     * other and to the spot direction (so |(U × V)·dir| = 1).
     */
    private static void assertPerpendicularSquare(SpotLight spot, String tc) {
        assertSquareAxes(spot.getU(), spot.getV(), spot.getDirection(), tc);
    }

    /** Test method for {@link lighting.SpotLight} as an {@link lighting.AreaLightSource}. */
    @Test
    void testAreaLightSource() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a spot light is an AreaLightSource (and a PointLight)
        SpotLight spot = new SpotLight(I, new Point3D(1, -2, 3), new Vector(0, 0, -1));
        assertInstanceOf(AreaLightSource.class, spot, "TC01: a spot light must be an AreaLightSource");
        assertInstanceOf(PointLight.class, spot, "TC01: a spot light must be a PointLight");
        // TC02: through the interface: centre (1, -2, 3), edge 0 by default, then 3 after setEdgesSize(3)
        AreaLightSource area = spot;
        assertEquals(new Point3D(1, -2, 3), area.getCenter(), "TC02: the centre must be the position");
        assertEquals(0, area.getEdges(), 0, "TC02: default edge must be 0");
        spot.setEdgesSize(3);
        assertEquals(3, area.getEdges(), 0, "TC02: wrong edge through the interface");

        // ===== Boundary Values Tests =====
        // TC10: a negative edge (-0.5) is rejected, naming the "edge"; the edge stays 3
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> spot.setEdgesSize(-0.5),
                "TC10: negative edge must be rejected");
        assertMessage(e, "edge", "TC10");
        assertEquals(3, spot.getEdges(), 0, "TC10: a rejected edge must leave the edge 3");
    }

    /** Test method for the chainable {@link lighting.SpotLight#setEdgesSize(double)} and {@link lighting.SpotLight#setUV(primitives.Vector, primitives.Vector)}. */
    @Test
    void testAreaSettersChaining() {
        // ===== Equivalence Partitions Tests =====
        // TC01: setEdgesSize and setUV return the SpotLight itself, so setNarrowBeam can follow
        SpotLight spot = light();
        SpotLight chained = spot.setEdgesSize(2).setUV(new Vector(3, 0, 0), new Vector(0, 4, 0)).setNarrowBeam(3);
        assertSame(spot, chained, "TC01: the setters must return this");
        assertEquals(2, spot.getEdges(), 0, "TC01: wrong edge");
        assertEquals(new Vector(1, 0, 0), spot.getU(), "TC01: wrong U");
        assertEquals(new Vector(0, 1, 0), spot.getV(), "TC01: wrong V");
        assertEquals(3, spot.getNarrowBeam(), 0, "TC01: wrong narrow beam");
        // TC02: in the other order, setUV then setEdgesSize then setKl, also the same SpotLight
        SpotLight other = light();
        assertSame(other, other.setUV(new Vector(0, 1, 0), new Vector(1, 0, 0)).setEdgesSize(5).setKl(0.1),
                "TC02: the setters must return this");
        assertEquals(5, other.getEdges(), 0, "TC02: wrong edge");
        // TC03: the area does not change the spot's intensity: (200, 100, 40) on the axis, (100, 50, 20) at 60°
        assertColor(200, 100, 40, light().setEdgesSize(4).getIntensity(ON_AXIS), "TC03: wrong intensity on the axis");
        assertColor(100, 50, 20, light().setEdgesSize(4).getIntensity(AT_60), "TC03: wrong intensity at 60°");
        // TC04: U, V not orthogonal are rejected, the message names "orthogonal"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> light().setUV(new Vector(1, 0, 0), new Vector(1, 0, 1)), "TC04: non-orthogonal U, V accepted");
        assertMessage(e, "orthogonal", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: edge 0 is accepted, the spot stays a true point light
        assertEquals(0, light().setEdgesSize(0).getEdges(), 0, "TC10: edge 0 must be accepted");
    }

    /** Test method for {@link lighting.SpotLight#getU()} and {@link lighting.SpotLight#getV()} when U, V were not set. */
    @Test
    void testDefaultUV() {
        // ===== Equivalence Partitions Tests =====
        // TC01: spot toward -z: U, V non-null, unit, orthogonal to each other and to (0, 0, -1)
        SpotLight spot = light();
        assertPerpendicularSquare(spot, "TC01");
        // TC02: general directions (1, 2, 3), (0, 3, -4), (-5, 1, -2): the square is perpendicular to them
        assertPerpendicularSquare(new SpotLight(I, Point3D.ZERO, new Vector(1, 2, 3)), "TC02");
        assertPerpendicularSquare(new SpotLight(I, new Point3D(1, 1, 1), new Vector(0, 3, -4)), "TC02");
        assertPerpendicularSquare(new SpotLight(I, new Point3D(-4, 0, 9), new Vector(-5, 1, -2)), "TC02");
        // TC03: U(p), V(p) equal U, V for points in front, to the side and behind the light
        Point3D[] points = { ON_AXIS, AT_60, new Point3D(10, 0, 0), new Point3D(0, 0, 10), new Point3D(3, 4, 1),
                new Point3D(-7, 2, -3) };
        for (Point3D p : points) {
            assertEquals(spot.getU(), spot.getU(p), "TC03: U(p) must be the spot's U at " + p);
            assertEquals(spot.getV(), spot.getV(p), "TC03: V(p) must be the spot's V at " + p);
        }
        // TC04: deterministic: twice U, V give equal vectors; two equal spots give equal U, V
        assertEquals(spot.getU(), spot.getU(), "TC04: U must be deterministic");
        assertEquals(spot.getV(), spot.getV(), "TC04: V must be deterministic");
        assertEquals(spot.getU(), light().getU(), "TC04: equal spots must have equal U");
        assertEquals(spot.getV(), light().getV(), "TC04: equal spots must have equal V");
        // TC05: setting the edge does not change the default square
        Vector u = spot.getU();
        Vector v = spot.getV();
        spot.setEdgesSize(2);
        assertEquals(u, spot.getU(), "TC05: the edge must not change U");
        assertEquals(v, spot.getV(), "TC05: the edge must not change V");

        // ===== Boundary Values Tests =====
        // TC10: directions along each coordinate axis, both senses: the square is perpendicular to them
        Vector[] axes = { new Vector(1, 0, 0), new Vector(-1, 0, 0), new Vector(0, 1, 0), new Vector(0, -1, 0),
                new Vector(0, 0, 1), new Vector(0, 0, -1) };
        for (Vector axis : axes)
            assertPerpendicularSquare(new SpotLight(I, Point3D.ZERO, axis), "TC10 direction " + axis);
        // TC11: a very long direction (0, 0, -1e9) and a very short one (1e-6, 1e-6, 0): perpendicular squares
        assertPerpendicularSquare(new SpotLight(I, Point3D.ZERO, new Vector(0, 0, -1e9)), "TC11 long");
        assertPerpendicularSquare(new SpotLight(I, Point3D.ZERO, new Vector(1e-6, 1e-6, 0)), "TC11 short");
        // TC12: a point on the axis through the light, (0, 0, -1e-6), also sees the spot's U, V
        assertEquals(spot.getU(), spot.getU(new Point3D(0, 0, -1e-6)), "TC12: U(p) must be the spot's U");
        assertEquals(spot.getV(), spot.getV(new Point3D(0, 0, -1e-6)), "TC12: V(p) must be the spot's V");
    }

    /** Test method for {@link lighting.SpotLight#setUV(primitives.Vector, primitives.Vector)} overriding the default square. */
    @Test
    void testSetUVOverridesDefault() {
        // ===== Equivalence Partitions Tests =====
        // TC01: setUV((0, 2, 0), (5, 0, 0)) on a spot toward -z: U = (0, 1, 0), V = (1, 0, 0), also for U(p), V(p)
        SpotLight spot = light().setUV(new Vector(0, 2, 0), new Vector(5, 0, 0));
        assertEquals(new Vector(0, 1, 0), spot.getU(), "TC01: set U must override the default");
        assertEquals(new Vector(1, 0, 0), spot.getV(), "TC01: set V must override the default");
        for (Point3D p : new Point3D[] { ON_AXIS, AT_60, new Point3D(0, 0, 10) }) {
            assertEquals(new Vector(0, 1, 0), spot.getU(p), "TC01: U(p) must be the set U at " + p);
            assertEquals(new Vector(1, 0, 0), spot.getV(p), "TC01: V(p) must be the set V at " + p);
        }
        // TC02: a tilted square ((1, 0, 1), (0, 3, 0)), not perpendicular to the direction, is kept as given:
        // U = (1, 0, 1)/sqrt2, V = (0, 1, 0)
        double h = Math.sqrt(0.5);
        SpotLight tilted = light().setUV(new Vector(1, 0, 1), new Vector(0, 3, 0));
        assertEquals(new Vector(h, 0, h), tilted.getU(), "TC02: wrong tilted U");
        assertEquals(new Vector(0, 1, 0), tilted.getV(), "TC02: wrong tilted V");
        assertEquals(new Vector(h, 0, h), tilted.getU(ON_AXIS), "TC02: wrong tilted U(p)");
        assertEquals(new Vector(0, 1, 0), tilted.getV(ON_AXIS), "TC02: wrong tilted V(p)");
        // TC03: a rejected setUV (not orthogonal) leaves the default square unchanged
        SpotLight plain = light();
        Vector u = plain.getU();
        Vector v = plain.getV();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> plain.setUV(new Vector(1, 1, 0), new Vector(1, 0, 0)), "TC03: non-orthogonal U, V accepted");
        assertMessage(e, "orthogonal", "TC03");
        assertEquals(u, plain.getU(), "TC03: a rejected setUV must leave U");
        assertEquals(v, plain.getV(), "TC03: a rejected setUV must leave V");

        // ===== Boundary Values Tests =====
        // TC10: U set along the spot's direction ((0, 0, -1), (1, 0, 0)) is accepted as given
        SpotLight edgeOn = light().setUV(new Vector(0, 0, -1), new Vector(1, 0, 0));
        assertEquals(new Vector(0, 0, -1), edgeOn.getU(), "TC10: wrong U along the direction");
        assertEquals(new Vector(1, 0, 0), edgeOn.getV(), "TC10: wrong V");
        // TC11: null U is rejected with IllegalArgumentException (not NullPointerException), naming "null"
        e = assertThrows(IllegalArgumentException.class, () -> light().setUV(null, new Vector(1, 0, 0)),
                "TC11: null U must be rejected");
        assertMessage(e, "null", "TC11");
    }
}
