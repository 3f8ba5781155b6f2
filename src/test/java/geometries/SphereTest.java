package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertNearestFirst;
import static testutil.TestAssertions.assertNearestFirstThrough;
import static testutil.TestAssertions.assertSameRejection;
import static testutil.TestRandom.rayThrough;
import static testutil.TestScenes.pointIn;

import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.Sphere}.
 */
class SphereTest {
    /** The course's sphere: centre (1,0,0), radius 1. */
    private final Sphere sphere = new Sphere(new Point3D(1, 0, 0), 1);

    /**
     * Asserts that a list of intersection points is exactly the expected points, in that order.
     *
     * @param message  the case label
     * @param expected the expected points, nearest first
     * @param actual   the points found
     */
    private static void assertPoints(String message, List<Point3D> expected, List<Point3D> actual) {
        assertTrue(actual != null, message + ": expected intersections but got null");
        assertEquals(expected.size(), actual.size(), message + ": wrong number of points");
        for (int i = 0; i < expected.size(); ++i)
            assertEquals(expected.get(i), actual.get(i), message + ": wrong point " + i);
    }

    /**
     * Test method for {@link geometries.Sphere#Sphere(primitives.Point3D, double)}.
     */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a correct sphere keeps its centre and radius
        Sphere s = new Sphere(new Point3D(1, 2, 3), 4.5);
        assertEquals(new Point3D(1, 2, 3), s.getCenter(), "TC01: wrong centre");
        assertEquals(4.5, s.getRadius(), 1e-10, "TC01: wrong radius");

        // TC02: negative radius is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Sphere(new Point3D(1, 2, 3), -1), "TC02: negative radius must throw");
        assertMessage(e, "radius", "TC02");

        // TC03: NaN radius is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Sphere(new Point3D(1, 2, 3), Double.NaN), "TC03: NaN radius must throw");
        assertMessage(e, "radius", "TC03");

        // TC04: infinite radius is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Sphere(new Point3D(1, 2, 3), Double.POSITIVE_INFINITY), "TC04: infinite radius must throw");
        assertMessage(e, "radius", "TC04");

        // TC05: null centre is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Sphere(null, 1), "TC05: null centre must throw");
        assertMessage(e, "center", "TC05");

        // ===== Boundary Values Tests =====
        // TC11: zero radius is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Sphere(new Point3D(1, 2, 3), 0), "TC11: zero radius must throw");
        assertMessage(e, "radius", "TC11");
    }

    /**
     * Test method for {@link geometries.Sphere#Sphere(double, primitives.Point3D)}, the course's radius-first order.
     */
    @Test
    void testConstructorRadiusFirst() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the same centre (1,2,3) and radius 4.5 as the centre-first constructor
        Sphere s = new Sphere(4.5, new Point3D(1, 2, 3));
        assertEquals(new Point3D(1, 2, 3), s.getCenter(), "TC01: wrong centre");
        assertEquals(4.5, s.getRadius(), 1e-10, "TC01: wrong radius");
        // TC02: the same intersections as the course's sphere built centre first: (0,0,0) and (2,0,0)
        Ray ray = new Ray(new Point3D(-1, 0, 0), new Vector(1, 0, 0));
        assertEquals(sphere.findIntersections(ray), new Sphere(1, new Point3D(1, 0, 0)).findIntersections(ray),
                "TC02: different intersections");
        // TC03: bad radius (negative, NaN) or a null centre: the same messages as centre first
        assertSameRejection(() -> new Sphere(new Point3D(1, 2, 3), -1), () -> new Sphere(-1, new Point3D(1, 2, 3)), "TC03");
        assertSameRejection(() -> new Sphere(new Point3D(1, 2, 3), Double.NaN),
                () -> new Sphere(Double.NaN, new Point3D(1, 2, 3)), "TC03");
        assertSameRejection(() -> new Sphere(null, 1), () -> new Sphere(1, null), "TC03");

        // ===== Boundary Values Tests =====
        // TC11: zero radius: the same message as centre first
        assertSameRejection(() -> new Sphere(new Point3D(1, 2, 3), 0), () -> new Sphere(0, new Point3D(1, 2, 3)), "TC11");
    }

    /**
     * Test method for {@link geometries.Sphere#getNormal(primitives.Point3D)}.
     */
    @Test
    void testGetNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a general point on the sphere: normal (2,3,6)/7, unit and outward
        Sphere s = new Sphere(new Point3D(1, 2, 3), 7);
        Point3D p = new Point3D(3, 5, 9);
        Vector n = s.getNormal(p);
        assertEquals(1, n.length(), 1e-10, "TC01: normal is not a unit vector");
        assertTrue(n.dotProduct(p.subtract(s.getCenter())) > 0, "TC01: normal does not point outward");
        assertEquals(new Vector(2d / 7, 3d / 7, 6d / 7), n, "TC01: wrong normal value");
        assertEquals(new Point3D(3, 5, 9), p, "TC01: getNormal changed its argument");

        // TC02: the course's case: point (2,0,0) on the sphere (1,0,0) r=1 has normal (1,0,0)
        Vector n2 = sphere.getNormal(new Point3D(2, 0, 0));
        assertEquals(1, n2.length(), 1e-10, "TC02: normal is not a unit vector");
        assertEquals(new Vector(1, 0, 0), n2, "TC02: wrong normal value");

        // TC03: the normal at the bottom of the sphere points down (outward)
        assertEquals(new Vector(0, -1, 0), sphere.getNormal(new Point3D(1, -1, 0)),
                "TC03: normal at the bottom must point down");
        // TC04: a null point is refused, naming it (not a NullPointerException)
        assertMessage(assertThrows(IllegalArgumentException.class, () -> sphere.getNormal(null),
                "TC04: a null point must be refused"), "point must not be null", "TC04");

        // ===== Boundary Values Tests =====
        // TC11 (own): the centre (1,0,0) has no normal: refused as a zero vector
        assertMessage(assertThrows(IllegalArgumentException.class, () -> sphere.getNormal(new Point3D(1, 0, 0)),
                "TC11: the centre must be refused"), "zero vector", "TC11");
    }

    /**
     * Test method for {@link geometries.Sphere#getUV(primitives.Point3D)}: longitude and latitude as
     * fractions, u = 0.5 + atan2(x, z)/2π and v = 0.5 + asin(y/r)/π, seen from the centre.
     */
    @Test
    void testGetUV() {
        Sphere s = new Sphere(new Point3D(1, 2, 3), 2);
        // ===== Equivalence Partitions Tests =====
        // TC01: on the equator, facing +z: (0.5, 0.5); facing +x: (0.75, 0.5); facing −x: (0.25, 0.5)
        assertArrayEquals(new double[] { 0.5, 0.5 }, s.getUV(new Point3D(1, 2, 5)), 1e-12, "TC01: facing +z");
        assertArrayEquals(new double[] { 0.75, 0.5 }, s.getUV(new Point3D(3, 2, 3)), 1e-12, "TC01: facing +x");
        assertArrayEquals(new double[] { 0.25, 0.5 }, s.getUV(new Point3D(-1, 2, 3)), 1e-12, "TC01: facing -x");
        // TC02: 45° north, facing +z: latitude π/4, v = 0.75
        double h = Math.sqrt(2);
        assertArrayEquals(new double[] { 0.5, 0.75 }, s.getUV(new Point3D(1, 2 + h, 3 + h)), 1e-12, "TC02: 45° north");
        // ===== Boundary Values Tests =====
        // TC11: the poles: v = 1 at the top, 0 at the bottom
        assertEquals(1, s.getUV(new Point3D(1, 4, 3))[1], 1e-12, "TC11: the top pole");
        assertEquals(0, s.getUV(new Point3D(1, 0, 3))[1], 1e-12, "TC11: the bottom pole");
        // TC12: facing −z, where u wraps around: 0 or 1
        double u = s.getUV(new Point3D(1, 2, 1))[0];
        assertTrue(u == 0 || u == 1, "TC12: facing -z, u must be 0 or 1, got " + u);
    }

    /**
     * Test method for {@link geometries.Sphere#findIntersections(primitives.Ray)}.
     */
    @Test
    void testFindIntersections() {
        double sqrt6 = Math.sqrt(6);

        // ===== Equivalence Partitions Tests =====
        // TC01: ray's line is outside the sphere (0 points)
        assertNull(sphere.findIntersections(new Ray(new Point3D(-1, 0, 0), new Vector(1, 1, 0))),
                "TC01: ray's line out of sphere must give null");

        // TC02: ray starts before and crosses the sphere (2 points, nearest first)
        // line (-1,0,0)+s(3,1,0): 10s^2 - 12s + 3 = 0, s = (6 -+ sqrt6)/10
        double s1 = (6 - sqrt6) / 10;
        double s2 = (6 + sqrt6) / 10;
        Point3D p1 = new Point3D(-1 + 3 * s1, s1, 0);
        Point3D p2 = new Point3D(-1 + 3 * s2, s2, 0);
        assertPoints("TC02: wrong intersection points", List.of(p1, p2),
                sphere.findIntersections(new Ray(new Point3D(-1, 0, 0), new Vector(3, 1, 0))));

        // TC03: ray starts inside the sphere (1 point)
        // line (0.5,0.5,0)+s(3,1,0): 10s^2 - 2s - 0.5 = 0, s = (1 + sqrt6)/10
        double s3 = (1 + sqrt6) / 10;
        assertPoints("TC03: wrong intersection point", List.of(new Point3D(0.5 + 3 * s3, 0.5 + s3, 0)),
                sphere.findIntersections(new Ray(new Point3D(0.5, 0.5, 0), new Vector(3, 1, 0))));

        // TC04: ray starts after the sphere (0 points)
        assertNull(sphere.findIntersections(new Ray(new Point3D(2, 1, 0), new Vector(3, 1, 0))),
                "TC04: ray starting after the sphere must give null");

        // ===== Boundary Values Tests =====
        // **** Group: ray's line crosses the sphere (but not the centre)
        // TC11: ray starts at the sphere and goes inside (1 point, (2,0,0))
        assertPoints("TC11: wrong intersection point", List.of(new Point3D(2, 0, 0)),
                sphere.findIntersections(new Ray(new Point3D(1, 1, 0), new Vector(1, -1, 0))));

        // TC12: ray starts at the sphere and goes outside (0 points)
        assertNull(sphere.findIntersections(new Ray(new Point3D(2, 0, 0), new Vector(1, 1, 0))),
                "TC12: ray leaving the sphere from its surface must give null");

        // **** Group: ray's line goes through the centre
        // TC13: ray starts before the sphere (2 points, (1,-1,0) then (1,1,0))
        assertPoints("TC13: wrong intersection points", List.of(new Point3D(1, -1, 0), new Point3D(1, 1, 0)),
                sphere.findIntersections(new Ray(new Point3D(1, -2, 0), new Vector(0, 1, 0))));

        // TC14: ray starts at the sphere and goes inside (1 point, (1,1,0))
        assertPoints("TC14: wrong intersection point", List.of(new Point3D(1, 1, 0)),
                sphere.findIntersections(new Ray(new Point3D(1, -1, 0), new Vector(0, 1, 0))));

        // TC15: ray starts inside (1 point, (1,1,0))
        assertPoints("TC15: wrong intersection point", List.of(new Point3D(1, 1, 0)),
                sphere.findIntersections(new Ray(new Point3D(1, -0.5, 0), new Vector(0, 1, 0))));

        // TC16: ray starts at the centre (1 point, (1,1,0))
        assertPoints("TC16: wrong intersection point", List.of(new Point3D(1, 1, 0)),
                sphere.findIntersections(new Ray(new Point3D(1, 0, 0), new Vector(0, 1, 0))));

        // TC17: ray starts at the sphere and goes outside (0 points)
        assertNull(sphere.findIntersections(new Ray(new Point3D(1, 1, 0), new Vector(0, 1, 0))),
                "TC17: ray leaving through the centre line from the surface must give null");

        // TC18: ray starts after the sphere (0 points)
        assertNull(sphere.findIntersections(new Ray(new Point3D(1, 2, 0), new Vector(0, 1, 0))),
                "TC18: ray starting after the sphere on the centre line must give null");

        // **** Group: ray's line is tangent to the sphere (all tests 0 points)
        // TC19: ray starts before the tangent point
        assertNull(sphere.findIntersections(new Ray(new Point3D(0, 1, 0), new Vector(1, 0, 0))),
                "TC19: tangent ray before the tangent point must give null");

        // TC20: ray starts at the tangent point
        assertNull(sphere.findIntersections(new Ray(new Point3D(1, 1, 0), new Vector(1, 0, 0))),
                "TC20: tangent ray at the tangent point must give null");

        // TC21: ray starts after the tangent point
        assertNull(sphere.findIntersections(new Ray(new Point3D(2, 1, 0), new Vector(1, 0, 0))),
                "TC21: tangent ray after the tangent point must give null");

        // **** Group: special cases
        // TC22: ray's line is outside, ray is orthogonal to the line from its start to the centre (0 points)
        assertNull(sphere.findIntersections(new Ray(new Point3D(-1, 0, 0), new Vector(0, 0, 1))),
                "TC22: ray orthogonal to the centre line from outside must give null");

        // TC23: ray starts inside, orthogonal to the line from its start to the centre (1 point (0.5,0,sqrt(0.75)))
        assertPoints("TC23: wrong intersection point", List.of(new Point3D(0.5, 0, Math.sqrt(0.75))),
                sphere.findIntersections(new Ray(new Point3D(0.5, 0, 0), new Vector(0, 0, 1))));
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray, double)} on a sphere.
     */
    @Test
    void testFindGeoIntersectionsMaxDistance() {
        // the ray crosses the sphere at distance 1 ((1,-1,0)) and 3 ((1,1,0))
        Ray ray = new Ray(new Point3D(1, -2, 0), new Vector(0, 1, 0));

        // ===== Equivalence Partitions Tests =====
        // TC01: max distance beyond both points (2 points, the sphere named in each)
        List<GeoPoint> result = sphere.findGeoIntersections(ray, 10);
        assertEquals(List.of(new GeoPoint(sphere, new Point3D(1, -1, 0)), new GeoPoint(sphere, new Point3D(1, 1, 0))),
                result, "TC01: wrong intersections within a long distance");
        assertSame(sphere, result.get(0).geometry, "TC01: wrong geometry in the GeoPoint");

        // TC02: max distance between the points excludes the farther one (1 point (1,-1,0))
        assertEquals(List.of(new GeoPoint(sphere, new Point3D(1, -1, 0))), sphere.findGeoIntersections(ray, 2),
                "TC02: the farther point must be excluded");

        // TC03: max distance before both points excludes both (null)
        assertNull(sphere.findGeoIntersections(ray, 0.5), "TC03: both points must be excluded");

        // TC04: ray starts inside, max distance before the exit point (null)
        assertNull(sphere.findGeoIntersections(new Ray(new Point3D(1, 0, 0), new Vector(0, 1, 0)), 0.5),
                "TC04: the exit point beyond the distance must be excluded");

        // TC05: no limit gives both points
        assertEquals(2, sphere.findGeoIntersections(ray).size(), "TC05: wrong number of points without limit");

        // ===== Boundary Values Tests =====
        // TC11: max distance exactly at the nearer point includes it (1 point (1,-1,0))
        assertEquals(List.of(new GeoPoint(sphere, new Point3D(1, -1, 0))), sphere.findGeoIntersections(ray, 1),
                "TC11: a point exactly at the max distance must be included");

        // TC12: max distance exactly at the farther point includes both (2 points)
        assertEquals(2, sphere.findGeoIntersections(ray, 3).size(),
                "TC12: a point exactly at the max distance must be included");
    }

    /**
     * Test method for {@link geometries.Sphere#findIntersections(primitives.Ray)} and
     * {@link geometries.Intersectable#findGeoIntersections(primitives.Ray)}: the two points come by distance
     * along the ray, nearest first, whichever way the ray crosses.
     */
    @Test
    void testIntersectionsNearestFirst() {
        // ===== Equivalence Partitions Tests =====
        // TC01: along −x off the centre from (3, 0.5, 0): (1 + √0.75, 0.5, 0) then (1 − √0.75, 0.5, 0), and back
        double half = Math.sqrt(0.75);
        assertNearestFirst(sphere, new Ray(new Point3D(3, 0.5, 0), new Vector(-1, 0, 0)),
                List.of(new Point3D(1 + half, 0.5, 0), new Point3D(1 - half, 0.5, 0)), "TC01");
        // TC02: 200 seeded random rays from 10 away through a point inside: 2 points each, nearest first
        assertNearestFirstThrough(sphere, rnd -> rayThrough(rnd, pointIn(rnd, sphere), 10), "TC02");

        // ===== Boundary Values Tests =====
        // TC10: through the centre along +z from (1, 0, −2): (1, 0, −1) then (1, 0, 1), and back
        assertNearestFirst(sphere, new Ray(new Point3D(1, 0, -2), new Vector(0, 0, 1)),
                List.of(new Point3D(1, 0, -1), new Point3D(1, 0, 1)), "TC10");
        // TC11: a chord just inside the tangent: (1 ± √(1 − 0.9999²), 0.9999, 0), about 0.028 apart, and back
        double graze = Math.sqrt(1 - 0.9999 * 0.9999);
        assertNearestFirst(sphere, new Ray(new Point3D(3, 0.9999, 0), new Vector(-1, 0, 0)),
                List.of(new Point3D(1 + graze, 0.9999, 0), new Point3D(1 - graze, 0.9999, 0)), "TC11");
    }
}
