package geometries;

import accel.ShadowFrustum;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.Plane}.
 */
class PlaneTest {
    /** The course's plane through (1,0,0), (0,1,0), (0,0,1): x + y + z = 1. */
    private final Plane plane = new Plane(new Point3D(1, 0, 0), new Point3D(0, 1, 0), new Point3D(0, 0, 1));

    /**
     * Test method for {@link geometries.Plane#Plane(primitives.Point3D, primitives.Point3D, primitives.Point3D)}.
     */
    @Test
    void testConstructorThreePoints() {
        Point3D p1 = new Point3D(1, 0, 0);
        Point3D p2 = new Point3D(0, 1, 0);
        Point3D p3 = new Point3D(0, 0, 1);

        // ===== Equivalence Partitions Tests =====
        // TC01: three general points: unit normal ±(1,1,1)/sqrt3, orthogonal to both edges
        Vector n = plane.getNormal();
        assertEquals(1, n.length(), 1e-10, "TC01: normal is not a unit vector");
        assertEquals(0, n.dotProduct(p2.subtract(p1)), 1e-10, "TC01: normal not orthogonal to the first edge");
        assertEquals(0, n.dotProduct(p3.subtract(p1)), 1e-10, "TC01: normal not orthogonal to the second edge");
        double s = 1 / Math.sqrt(3);
        Vector expected = new Vector(s, s, s);
        assertTrue(n.equals(expected) || n.equals(expected.scale(-1)), "TC01: wrong normal value " + n);
        assertEquals(p1, plane.getQ0(), "TC01: the reference point must be the first point");

        // TC02: the points in the other order give the opposite (still unit) normal
        Vector reversed = new Plane(p1, p3, p2).getNormal();
        assertEquals(1, reversed.length(), 1e-10, "TC02: normal is not a unit vector");
        assertEquals(n.scale(-1), reversed, "TC02: swapping two points must flip the normal");

        // TC03: a null point is rejected
        assertThrows(IllegalArgumentException.class, () -> new Plane(p1, p2, null), "TC03: null point must throw");

        // ===== Boundary Values Tests =====
        // TC11: first and second points coincide
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Plane(p1, new Point3D(1, 0, 0), p3), "TC11: coincident points must throw"),
                "coincide", "TC11");

        // TC12: second and third points coincide
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Plane(p1, p2, new Point3D(0, 1, 0)), "TC12: coincident points must throw"),
                "coincide", "TC12");

        // TC13: first and third points coincide
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Plane(p1, p2, new Point3D(1, 0, 0)), "TC13: coincident points must throw"),
                "coincide", "TC13");

        // TC14: all three points coincide
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Plane(p1, p1, p1), "TC14: coincident points must throw"), "coincide", "TC14");

        // TC15: three distinct collinear points
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Plane(new Point3D(1, 2, 3), new Point3D(2, 4, 6), new Point3D(3, 6, 9)),
                "TC15: collinear points must throw"), "collinear", "TC15");

        // TC16: collinear points with the middle one given last
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Plane(new Point3D(0, 0, 0), new Point3D(4, 0, 0), new Point3D(1, 0, 0)),
                "TC16: collinear points must throw"), "collinear", "TC16");
    }

    /**
     * Test method for {@link geometries.Plane#Plane(primitives.Point3D, primitives.Vector)}.
     */
    @Test
    void testConstructorPointNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a long normal is kept as a unit copy (0,0,1); the caller's vector is unchanged
        Vector given = new Vector(0, 0, 5);
        Plane p = new Plane(new Point3D(1, 2, 3), given);
        assertEquals(new Vector(0, 0, 1), p.getNormal(), "TC01: the normal must be normalised");
        assertEquals(new Vector(0, 0, 5), given, "TC01: the caller's normal vector must not change");
        assertEquals(new Point3D(1, 2, 3), p.getQ0(), "TC01: wrong reference point");

        // TC02: null point or null normal is rejected
        assertThrows(IllegalArgumentException.class, () -> new Plane(null, given), "TC02: null point must throw");
        assertThrows(IllegalArgumentException.class, () -> new Plane(Point3D.ZERO, (Vector) null),
                "TC02: null normal must throw");
        // ===== Boundary Values Tests =====
        // TC11: a very short normal (0, 1e-200, 0) is not a zero vector: the unit normal is (0, 1, 0)
        assertEquals(new Vector(0, 1, 0), new Plane(Point3D.ZERO, new Vector(0, 1e-200, 0)).getNormal(),
                "TC11: a very short normal must be normalised");
        // TC12: a very long normal (3e200, 0, 4e200) gives (0.6, 0, 0.8)
        assertEquals(new Vector(0.6, 0, 0.8), new Plane(Point3D.ZERO, new Vector(3e200, 0, 4e200)).getNormal(),
                "TC12: a very long normal must be normalised");
    }

    /**
     * Test method for {@link geometries.Plane#getNormal(primitives.Point3D)}.
     */
    @Test
    void testGetNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the normal at a point of the plane is the plane's unit normal ±(1,1,1)/sqrt3
        Vector n = plane.getNormal(new Point3D(1d / 3, 1d / 3, 1d / 3));
        double s = 1 / Math.sqrt(3);
        assertEquals(1, n.length(), 1e-10, "TC01: normal is not a unit vector");
        assertTrue(n.equals(new Vector(s, s, s)) || n.equals(new Vector(-s, -s, -s)), "TC01: wrong normal " + n);
        assertEquals(plane.getNormal(), n, "TC01: the normal must be the same at every point");

        // TC02: a plane built from a point and a normal returns that normal, normalised
        Plane p = new Plane(new Point3D(0, 0, 1), new Vector(0, 3, 4));
        assertEquals(new Vector(0, 0.6, 0.8), p.getNormal(new Point3D(5, 0, 1)), "TC02: wrong normal");
        // TC03: a null point is refused, naming it, although the normal is the same everywhere
        assertMessage(assertThrows(IllegalArgumentException.class, () -> p.getNormal(null),
                "TC03: a null point must be refused"), "point must not be null", "TC03");
    }

    /**
     * Test method for {@link geometries.Plane#getUV(primitives.Point3D)}: the position in the plane from
     * q0, u along the coordinate axis most across the normal, v along normal × u.
     */
    @Test
    void testGetUV() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a floor facing +y through (1, 5, 2): u along +x, v along −z
        Plane floor = new Plane(new Point3D(1, 5, 2), new Vector(0, 1, 0));
        assertArrayEquals(new double[] { 3, -4 }, floor.getUV(new Point3D(4, 5, 6)), 1e-12, "TC01: a floor");
        // TC02: a wall facing +z: u along +x (the first of x and y), v along z × x = +y
        Plane wall = new Plane(Point3D.ZERO, new Vector(0, 0, 1));
        assertArrayEquals(new double[] { 2, 7 }, wall.getUV(new Point3D(2, 7, 0)), 1e-12, "TC02: a wall");
        // TC03: a tilted plane (x + y + z = 1): the coordinates are distances, |p − q0| = √(u² + v²)
        Point3D p = new Point3D(2, 1, -2);
        double[] uv = plane.getUV(p);
        assertEquals(p.distance(plane.getQ0()), Math.sqrt(uv[0] * uv[0] + uv[1] * uv[1]), 1e-12, "TC03: tilted");
        // ===== Boundary Values Tests =====
        // TC11: q0 itself is (0, 0)
        assertArrayEquals(new double[] { 0, 0 }, floor.getUV(new Point3D(1, 5, 2)), 0, "TC11: q0");
    }

    /**
     * Test method for {@link geometries.Plane#findIntersections(primitives.Ray)}.
     */
    @Test
    void testFindIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: ray crosses the plane (1 point (2/3,2/3,-1/3))
        List<Point3D> result = plane.findIntersections(new Ray(new Point3D(0, 0, -1), new Vector(1, 1, 1)));
        assertEquals(List.of(new Point3D(2d / 3, 2d / 3, -1d / 3)), result, "TC01: wrong intersection point");

        // TC02: ray goes away from the plane (0 points)
        assertNull(plane.findIntersections(new Ray(new Point3D(0, 0, 2), new Vector(0, 0, 1))),
                "TC02: ray going away from the plane must give null");

        // TC03: ray crosses the plane from the other side (1 point (0.5,0.5,0))
        assertEquals(List.of(new Point3D(0.5, 0.5, 0)),
                plane.findIntersections(new Ray(new Point3D(1, 1, 0), new Vector(-1, -1, 0))),
                "TC03: wrong intersection point from the other side");

        // ===== Boundary Values Tests =====
        // **** Group: ray parallel to the plane
        // TC11: ray included in the plane (0 points)
        assertNull(plane.findIntersections(new Ray(new Point3D(0, 1, 0), new Vector(1, -1, 0))),
                "TC11: ray inside the plane must give null");

        // TC12: ray not included in the plane (0 points)
        assertNull(plane.findIntersections(new Ray(new Point3D(0, 0, 2), new Vector(1, -1, 0))),
                "TC12: ray parallel to the plane must give null");

        // **** Group: ray orthogonal to the plane
        // TC13: ray starts before the plane (1 point (1,1,-1))
        assertEquals(List.of(new Point3D(1, 1, -1)),
                plane.findIntersections(new Ray(new Point3D(0, 0, -2), new Vector(1, 1, 1))),
                "TC13: wrong intersection point for an orthogonal ray");

        // TC14: ray starts in the plane (0 points)
        assertNull(plane.findIntersections(new Ray(new Point3D(0, 0, 1), new Vector(1, 1, 1))),
                "TC14: orthogonal ray starting in the plane must give null");

        // TC15: ray starts after the plane (0 points)
        assertNull(plane.findIntersections(new Ray(new Point3D(0, 0, 2), new Vector(1, 1, 1))),
                "TC15: orthogonal ray starting after the plane must give null");

        // **** Group: special cases
        // TC16: ray starts in the plane, neither parallel nor orthogonal (0 points)
        assertNull(plane.findIntersections(new Ray(new Point3D(0, 1, 0), new Vector(1, 0, 0))),
                "TC16: ray starting in the plane must give null");

        // TC17: ray starts at the plane's reference point q0 (0 points)
        assertNull(plane.findIntersections(new Ray(new Point3D(1, 0, 0), new Vector(1, 2, 3))),
                "TC17: ray starting at the plane's reference point must give null");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray, double)} on a plane.
     */
    @Test
    void testFindGeoIntersectionsMaxDistance() {
        // the plane z = 1, hit by a ray from the origin along z at distance 1
        Plane p = new Plane(new Point3D(0, 0, 1), new Vector(0, 0, 1));
        Ray ray = new Ray(Point3D.ZERO, new Vector(0, 0, 1));

        // ===== Equivalence Partitions Tests =====
        // TC01: max distance beyond the point (1 point (0,0,1), the plane named)
        List<GeoPoint> result = p.findGeoIntersections(ray, 5);
        assertEquals(List.of(new GeoPoint(p, new Point3D(0, 0, 1))), result, "TC01: wrong intersection");
        assertSame(p, result.get(0).geometry, "TC01: wrong geometry in the GeoPoint");

        // TC02: max distance before the point (null)
        assertNull(p.findGeoIntersections(ray, 0.5), "TC02: a point beyond the max distance must be excluded");

        // ===== Boundary Values Tests =====
        // TC11: max distance exactly at the point (1 point)
        assertEquals(List.of(new GeoPoint(p, new Point3D(0, 0, 1))), p.findGeoIntersections(ray, 1),
                "TC11: a point exactly at the max distance must be included");

        // TC12: max distance just short of the point (null)
        assertNull(p.findGeoIntersections(ray, 1 - 1e-6), "TC12: a point just beyond the max distance must be excluded");
    }

    /**
     * Test method for {@link geometries.Plane#mayMeet(ShadowFrustum)}: the plane is gathered for a
     * bundle of shadow rays only when the bundle's pyramid reaches it.
     */
    @Test
    void testMayMeet() {
        // the pyramid from the apex (0, 0, 5) to the square (±1, ±1, −1) below it
        ShadowFrustum frustum = new ShadowFrustum();
        assertTrue(frustum.set(new double[] { 0, 0, 5 }, new double[] { 0, 0, -1, 1, 0, 0, 0, 1, 0 }, 0),
                "the pyramid must be set");

        // ===== Equivalence Partitions Tests =====
        // TC01: the plane z = 0 crosses the pyramid: true
        assertTrue(new Plane(Point3D.ZERO, new Vector(0, 0, 1)).mayMeet(frustum), "TC01: a crossing plane may meet");
        // TC02: the slanted plane x + z = 2 crosses it: true
        assertTrue(new Plane(new Point3D(2, 0, 0), new Vector(1, 0, 1)).mayMeet(frustum),
                "TC02: a slanted crossing plane may meet");
        // TC03: the plane z = −2, below the whole pyramid: false
        assertFalse(new Plane(new Point3D(0, 0, -2), new Vector(0, 0, 1)).mayMeet(frustum),
                "TC03: a plane below the pyramid must not meet");
        // TC04: the plane z = 6, above the apex (its normal pointing down): false
        assertFalse(new Plane(new Point3D(3, 3, 6), new Vector(0, 0, -1)).mayMeet(frustum),
                "TC04: a plane above the apex must not meet");
        // TC05: the plane x = 5 beside the pyramid: false
        assertFalse(new Plane(new Point3D(5, 0, 0), new Vector(1, 0, 0)).mayMeet(frustum),
                "TC05: a plane beside the pyramid must not meet");

        // ===== Boundary Values Tests =====
        // TC11: the plane z = 5 through the apex only: true
        assertTrue(new Plane(new Point3D(0, 0, 5), new Vector(0, 0, 1)).mayMeet(frustum),
                "TC11: a plane through the apex may meet");
        // TC12: the base's plane z = −1: true
        assertTrue(new Plane(new Point3D(0, 0, -1), new Vector(0, 0, 1)).mayMeet(frustum),
                "TC12: the base's plane may meet");
        // TC13: the plane x = 1 touching the base's edge: true
        assertTrue(new Plane(new Point3D(1, 0, 0), new Vector(1, 0, 0)).mayMeet(frustum),
                "TC13: a plane touching the base's edge may meet");
    }
}
