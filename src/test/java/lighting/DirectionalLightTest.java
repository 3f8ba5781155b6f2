package lighting;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;

/**
 * Unit tests for {@link lighting.DirectionalLight}.
 */
class DirectionalLightTest {
    /** Tolerance for comparing doubles. */
    private static final double DELTA = 1e-10;

    /** Points spread over space, to show that the answers do not depend on the point. */
    private static final Point3D[] POINTS = {
            Point3D.ZERO, new Point3D(1000, -5, 7), new Point3D(-3, 2, 1), new Point3D(1e-6, 0, -1e6) };

    /** Test method for {@link lighting.DirectionalLight#DirectionalLight(primitives.Color, primitives.Vector)}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the direction is kept as a unit vector, (0, 3, 4) -> (0, 0.6, 0.8), the caller's vector unchanged
        Vector d = new Vector(0, 3, 4);
        DirectionalLight light = new DirectionalLight(new Color(1, 2, 3), d);
        assertEquals(new Vector(0, 0.6, 0.8), light.getDirection(), "TC01: wrong direction");
        assertEquals(1, light.getDirection().length(), DELTA, "TC01: direction must be unit");
        assertEquals(0, d.getX(), 0, "TC01: caller's vector changed");
        assertEquals(3, d.getY(), 0, "TC01: caller's vector changed");
        assertEquals(4, d.getZ(), 0, "TC01: caller's vector changed");
        assertNotSame(d, light.getDirection(), "TC01: light must keep its own copy of the direction");
        // TC02: a null direction is rejected, the message names the "direction"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new DirectionalLight(new Color(1, 2, 3), null), "TC02: null direction must be rejected");
        assertMessage(e, "direction", "TC02");
        // TC03: a null intensity is rejected, the message names the "intensity"
        e = assertThrows(IllegalArgumentException.class,
                () -> new DirectionalLight(null, new Vector(0, 0, -1)), "TC03: null intensity must be rejected");
        assertMessage(e, "intensity", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: an already-unit direction (0, 0, -1) is kept as (0, 0, -1)
        assertEquals(new Vector(0, 0, -1), new DirectionalLight(Color.BLACK, new Vector(0, 0, -1)).getDirection(),
                "TC10: wrong direction");
    }

    /** Test method for {@link lighting.DirectionalLight#getIntensity(primitives.Point3D)}. */
    @Test
    void testGetIntensity() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the intensity is (100, 200, 50) at every point, no attenuation
        DirectionalLight light = new DirectionalLight(new Color(100, 200, 50), new Vector(1, -1, 0));
        for (Point3D p : POINTS)
            assertEquals(new Color(100, 200, 50), light.getIntensity(p), "TC01: wrong intensity at " + p);
        assertEquals(new Color(100, 200, 50), light.getIntensity(), "TC01: wrong base intensity");
    }

    /** Test method for {@link lighting.DirectionalLight#getL(primitives.Point3D)}. */
    @Test
    void testGetL() {
        // ===== Equivalence Partitions Tests =====
        // TC01: l is the unit direction (1/3, 2/3, 2/3) of (1, 2, 2) at every point
        Vector d = new Vector(1, 2, 2);
        DirectionalLight light = new DirectionalLight(new Color(1, 1, 1), d);
        for (Point3D p : POINTS) {
            Vector l = light.getL(p);
            assertEquals(new Vector(1d / 3, 2d / 3, 2d / 3), l, "TC01: wrong l at " + p);
            assertEquals(1, l.length(), DELTA, "TC01: l must be unit at " + p);
        }
        // the caller's vector is still (1, 2, 2)
        assertEquals(1, d.getX(), 0, "TC01: caller's vector changed");
        assertEquals(2, d.getY(), 0, "TC01: caller's vector changed");
        assertEquals(2, d.getZ(), 0, "TC01: caller's vector changed");

        // ===== Boundary Values Tests =====
        // TC10: a very long direction (0, -1e6, 0) gives the unit (0, -1, 0)
        assertEquals(new Vector(0, -1, 0),
                new DirectionalLight(new Color(1, 1, 1), new Vector(0, -1e6, 0)).getL(new Point3D(5, 5, 5)),
                "TC10: wrong l");
    }

    /** Test method for {@link lighting.LightSource#isAt(primitives.Point3D)}, the default of a light at infinity. */
    @Test
    void testIsAt() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a light at infinity sits at no point: false at every point
        DirectionalLight light = new DirectionalLight(new Color(1, 1, 1), new Vector(0, 0, -1));
        for (Point3D p : POINTS)
            assertFalse(light.isAt(p), "TC01: a directional light sits nowhere, not at " + p);
    }

    /** Test method for {@link lighting.DirectionalLight#getDistance(primitives.Point3D)}. */
    @Test
    void testGetDistance() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the light is at infinity: +infinity at every point
        DirectionalLight light = new DirectionalLight(new Color(1, 1, 1), new Vector(0, 0, -1));
        for (Point3D p : POINTS)
            assertEquals(Double.POSITIVE_INFINITY, light.getDistance(p), "TC01: distance must be +infinity at " + p);
    }
}
