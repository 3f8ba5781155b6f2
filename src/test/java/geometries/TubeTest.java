package geometries;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertNearestFirst;
import static testutil.TestAssertions.assertNearestFirstThrough;
import static testutil.TestAssertions.assertSameRejection;
import static testutil.TestScenes.perpendicular;

import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.Tube}.
 */
class TubeTest {
    /** √2, for ray distances. */
    private static final double SQRT2 = Math.sqrt(2);

    /** The tube used by the intersection tests: axis through (1,0,0) along z, radius 1, i.e. (x−1)² + y² = 1. */
    private final Tube tube = new Tube(new Ray(new Point3D(1, 0, 0), new Vector(0, 0, 1)), 1);

    /**
     * Test method for {@link geometries.Tube#Tube(primitives.Ray, double)}.
     */
    @Test
    void testConstructor() {
        Ray axis = new Ray(new Point3D(1, 0, 0), new Vector(0, 0, 3));
        // ===== Equivalence Partitions Tests =====
        // TC01: a correct tube keeps its axis and radius (2)
        Tube t = new Tube(axis, 2);
        assertEquals(axis, t.getAxisRay(), "TC01: wrong axis ray");
        assertEquals(new Vector(0, 0, 1), t.getAxisRay().getDir(), "TC01: axis direction is not unit");
        assertEquals(2, t.getRadius(), 1e-10, "TC01: wrong radius");
        // TC02: negative radius is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Tube(axis, -1),
                "TC02: negative radius accepted");
        assertMessage(e, "radius", "TC02");
        // TC03: NaN / infinite radius is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Tube(axis, Double.NaN), "TC03: NaN radius accepted");
        assertMessage(e, "radius", "TC03");
        e = assertThrows(IllegalArgumentException.class, () -> new Tube(axis, Double.POSITIVE_INFINITY),
                "TC03: infinite radius accepted");
        assertMessage(e, "radius", "TC03");
        // TC04: a null axis is rejected with a message naming it (no bare NullPointerException)
        e = assertThrows(IllegalArgumentException.class, () -> new Tube(null, 1), "TC04: null axis accepted");
        assertMessage(e, "axis", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: zero radius is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Tube(axis, 0), "TC10: zero radius accepted");
        assertMessage(e, "radius", "TC10");
    }

    /**
     * Test method for {@link geometries.Tube#Tube(double, primitives.Ray)}, the course's radius-first order.
     */
    @Test
    void testConstructorRadiusFirst() {
        Ray axis = new Ray(new Point3D(1, 0, 0), new Vector(0, 0, 3));
        // ===== Equivalence Partitions Tests =====
        // TC01: the same axis and radius (2) as the axis-first constructor
        Tube t = new Tube(2, axis);
        assertEquals(axis, t.getAxisRay(), "TC01: wrong axis ray");
        assertEquals(2, t.getRadius(), 1e-10, "TC01: wrong radius");
        // TC02: the same intersections as the test tube built axis first: (0,0,0.5) and (2,0,0.5)
        Ray ray = new Ray(new Point3D(-1, 0, 0.5), new Vector(1, 0, 0));
        assertEquals(tube.findIntersections(ray), new Tube(1, new Ray(new Point3D(1, 0, 0), new Vector(0, 0, 1)))
                .findIntersections(ray), "TC02: different intersections");
        // TC03: negative radius or a null axis: the same messages as axis first
        assertSameRejection(() -> new Tube(axis, -1), () -> new Tube(-1, axis), "TC03");
        assertSameRejection(() -> new Tube(null, 1), () -> new Tube(1, null), "TC03");

        // ===== Boundary Values Tests =====
        // TC10: zero radius: the same message as axis first
        assertSameRejection(() -> new Tube(axis, 0), () -> new Tube(0, axis), "TC10");
    }

    /**
     * Test method for {@link geometries.Tube#getNormal(primitives.Point3D)}.
     */
    @Test
    void testGetNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a point on the side, off the axis start's level: (1.6, 0.8, -4) → (0.6, 0.8, 0)
        Vector n = tube.getNormal(new Point3D(1.6, 0.8, -4));
        assertEquals(1, n.length(), 1e-10, "TC01: normal is not a unit vector");
        assertEquals(new Vector(0.6, 0.8, 0), n, "TC01: wrong normal");
        assertEquals(0, n.dotProduct(tube.getAxisRay().getDir()), 1e-10, "TC01: normal is not orthogonal to the axis");
        // TC02: a point far ahead along the axis: (2, 0, 100) → (1, 0, 0)
        assertEquals(new Vector(1, 0, 0), tube.getNormal(new Point3D(2, 0, 100)), "TC02: wrong normal");
        // TC03: a slanted tube, axis from the origin along (1,1,0), radius √2: point (2,0,0) → (1,-1,0)/√2
        Tube slanted = new Tube(new Ray(Point3D.ZERO, new Vector(1, 1, 0)), SQRT2);
        n = slanted.getNormal(new Point3D(2, 0, 0));
        assertEquals(1, n.length(), 1e-10, "TC03: normal is not a unit vector");
        assertEquals(new Vector(1 / SQRT2, -1 / SQRT2, 0), n, "TC03: wrong normal");
        // TC04: a slanted tube, point behind the axis start: (-3,-1,1) projects to (-2,-2,0) → (-1,1,1)/√3
        Tube slanted3 = new Tube(new Ray(Point3D.ZERO, new Vector(1, 1, 0)), Math.sqrt(3));
        double s3 = 1 / Math.sqrt(3);
        assertEquals(new Vector(-s3, s3, s3), slanted3.getNormal(new Point3D(-3, -1, 1)), "TC04: wrong normal");
        // TC05: a null point is refused, naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> tube.getNormal(null),
                "TC05: a null point must be refused"), "point must not be null", "TC05");

        // ===== Boundary Values Tests =====
        // TC10: the point's projection on the axis is the axis start p0 itself: (1,-1,0) → (0,-1,0)
        n = tube.getNormal(new Point3D(1, -1, 0));
        assertEquals(1, n.length(), 1e-10, "TC10: normal is not a unit vector");
        assertEquals(new Vector(0, -1, 0), n, "TC10: wrong normal");
        // TC11: the same on the slanted tube: (1,-1,0) − p0 is orthogonal to (1,1,0) → (1,-1,0)/√2
        assertEquals(new Vector(1 / SQRT2, -1 / SQRT2, 0), slanted.getNormal(new Point3D(1, -1, 0)),
                "TC11: wrong normal");
        // TC12 (own): a point on the axis has no normal: refused as a zero vector
        assertMessage(assertThrows(IllegalArgumentException.class, () -> tube.getNormal(new Point3D(1, 0, 7)),
                "TC12: a point on the axis must be refused"), "zero vector", "TC12");
    }

    /**
     * Test method for {@link geometries.Tube#findIntersections(primitives.Ray)}.
     */
    @Test
    void testFindIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the ray misses the tube (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(-1, 2, 0), new Vector(1, 0, 0.5))),
                "TC01: wrong intersection points");
        // TC02: the ray starts outside and crosses the tube (2 points, nearest first)
        assertEquals(List.of(new Point3D(0.2, 0.6, 1.2), new Point3D(1.8, 0.6, 2.8)),
                tube.findIntersections(new Ray(new Point3D(-1, 0.6, 0), new Vector(1, 0, 1))),
                "TC02: wrong intersection points");
        // TC03: the ray starts inside the tube (1 point)
        assertEquals(List.of(new Point3D(1.8, 0.6, 0.8)),
                tube.findIntersections(new Ray(new Point3D(1, 0.6, 0), new Vector(1, 0, 1))),
                "TC03: wrong intersection points");
        // TC04: the ray starts after the tube (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(3, 0.6, 0), new Vector(1, 0, 1))),
                "TC04: wrong intersection points");
        // TC05: the tube is infinite both ways: a ray behind the axis start still hits it (2,0,-4) only
        assertEquals(List.of(new Point3D(2, 0, -4)),
                tube.findIntersections(new Ray(new Point3D(1, 0, -5), new Vector(1, 0, 1))),
                "TC05: wrong intersection points");
        // TC06: crossing from the other side: points come nearest first (1.8,0.6,1.2) then (0.2,0.6,2.8)
        assertEquals(List.of(new Point3D(1.8, 0.6, 1.2), new Point3D(0.2, 0.6, 2.8)),
                tube.findIntersections(new Ray(new Point3D(3, 0.6, 0), new Vector(-1, 0, 1))),
                "TC06: wrong intersection points");

        // ===== Boundary Values Tests =====
        // **** Group: the ray is parallel to the axis
        // TC10: inside the tube (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(1.5, 0, 0), new Vector(0, 0, 1))),
                "TC10: wrong intersection points");
        // TC11: outside the tube (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(3, 0, 0), new Vector(0, 0, -1))),
                "TC11: wrong intersection points");
        // TC12: on the surface (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(2, 0, 0), new Vector(0, 0, 1))),
                "TC12: wrong intersection points");
        // TC13: on the axis itself (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(1, 0, 5), new Vector(0, 0, -1))),
                "TC13: wrong intersection points");

        // **** Group: the ray is orthogonal to the axis
        // TC14: starts outside and goes through the axis (2 points)
        assertEquals(List.of(new Point3D(0, 0, 2), new Point3D(2, 0, 2)),
                tube.findIntersections(new Ray(new Point3D(-1, 0, 2), new Vector(1, 0, 0))),
                "TC14: wrong intersection points");
        // TC15: starts on the axis (1 point)
        assertEquals(List.of(new Point3D(1, 1, 2)),
                tube.findIntersections(new Ray(new Point3D(1, 0, 2), new Vector(0, 1, 0))),
                "TC15: wrong intersection points");
        // TC16: starts at the axis start p0 itself (1 point)
        assertEquals(List.of(new Point3D(0, 0, 0)),
                tube.findIntersections(new Ray(new Point3D(1, 0, 0), new Vector(-1, 0, 0))),
                "TC16: wrong intersection points");
        // TC17: starts inside, off the axis, and does not cross it (1 point)
        assertEquals(List.of(new Point3D(1.5, Math.sqrt(0.75), 2)),
                tube.findIntersections(new Ray(new Point3D(1.5, 0, 2), new Vector(0, 1, 0))),
                "TC17: wrong intersection points");
        // TC18: starts after the tube, moving away (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(3, 0, 2), new Vector(1, 0, 0))),
                "TC18: wrong intersection points");

        // **** Group: the ray's line crosses the axis, slanted
        // TC19: starts outside (2 points)
        assertEquals(List.of(new Point3D(0, 0, 1), new Point3D(2, 0, 3)),
                tube.findIntersections(new Ray(new Point3D(-1, 0, 0), new Vector(1, 0, 1))),
                "TC19: wrong intersection points");

        // **** Group: the ray's line is tangent to the tube
        // TC20: starts before the tangent point (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(2, -1, 0), new Vector(0, 1, 1))),
                "TC20: wrong intersection points");
        // TC21: starts at the tangent point (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(2, 0, 0), new Vector(0, 1, 0))),
                "TC21: wrong intersection points");
        // TC22: starts after the tangent point (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(2, 1, 0), new Vector(0, 1, 0))),
                "TC22: wrong intersection points");

        // **** Group: the ray starts on the surface
        // TC23: slanted, going inside (1 point, the far side)
        assertEquals(List.of(new Point3D(0, 0, 2)),
                tube.findIntersections(new Ray(new Point3D(2, 0, 0), new Vector(-1, 0, 1))),
                "TC23: wrong intersection points");
        // TC24: slanted, going outside (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(2, 0, 0), new Vector(1, 0, 1))),
                "TC24: wrong intersection points");
        // TC25: orthogonal to the axis, going inside through the axis (1 point)
        assertEquals(List.of(new Point3D(2, 0, 0)),
                tube.findIntersections(new Ray(new Point3D(0, 0, 0), new Vector(1, 0, 0))),
                "TC25: wrong intersection points");
        // TC26: orthogonal to the axis, going outside along the normal (null)
        assertNull(tube.findIntersections(new Ray(new Point3D(2, 0, 0), new Vector(1, 0, 0))),
                "TC26: wrong intersection points");
        // TC27: orthogonal to the axis, going inside off the axis from (1.6,0.8,3) along −x:
        // (x−1)² = 1 − 0.64 → x = 0.4 (1 point)
        assertEquals(List.of(new Point3D(0.4, 0.8, 3)),
                tube.findIntersections(new Ray(new Point3D(1.6, 0.8, 3), new Vector(-1, 0, 0))),
                "TC27: wrong intersection points");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray, double)} on a tube.
     */
    @Test
    void testFindGeoIntersectionsMaxDistance() {
        // the ray crosses the tube at t = 1 (0,0,0) and t = 3 (2,0,0)
        Ray ray = new Ray(new Point3D(-1, 0, 0), new Vector(1, 0, 0));
        // ===== Equivalence Partitions Tests =====
        // TC01: both points within the distance (2 points, each naming the tube)
        List<GeoPoint> result = tube.findGeoIntersections(ray, 5);
        assertEquals(List.of(new GeoPoint(tube, new Point3D(0, 0, 0)), new GeoPoint(tube, new Point3D(2, 0, 0))),
                result, "TC01: wrong intersection points");
        assertSame(tube, result.get(0).geometry, "TC01: wrong geometry");
        // TC02: only the first within the distance (1 point)
        assertEquals(List.of(new GeoPoint(tube, new Point3D(0, 0, 0))), tube.findGeoIntersections(ray, 2),
                "TC02: wrong intersection points");
        // TC03: both beyond the distance (null)
        assertNull(tube.findGeoIntersections(ray, 0.5), "TC03: wrong intersection points");
        // TC04: ray starting inside, the point beyond the distance (null); within it (1 point)
        Ray inside = new Ray(new Point3D(1, 0, 0), new Vector(1, 0, 0));
        assertNull(tube.findGeoIntersections(inside, 0.9), "TC04: wrong intersection points");
        assertEquals(List.of(new GeoPoint(tube, new Point3D(2, 0, 0))), tube.findGeoIntersections(inside, 1.1),
                "TC04: wrong intersection points");
        // TC05: no limit (2 points)
        assertEquals(2, tube.findGeoIntersections(ray).size(), "TC05: wrong number of intersection points");

        // ===== Boundary Values Tests =====
        // TC10: the distance is exactly the first point's (inclusive: 1 point)
        assertEquals(List.of(new GeoPoint(tube, new Point3D(0, 0, 0))), tube.findGeoIntersections(ray, 1),
                "TC10: wrong intersection points");
        // TC11: the distance is exactly the second point's (inclusive: 2 points)
        assertEquals(2, tube.findGeoIntersections(ray, 3).size(), "TC11: wrong number of intersection points");
        // TC12: a non-positive or NaN distance is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> tube.findGeoIntersections(ray, 0), "TC12: zero distance accepted");
        assertMessage(e, "distance", "TC12");
        assertThrows(IllegalArgumentException.class, () -> tube.findGeoIntersections(ray, Double.NaN),
                "TC12: NaN distance accepted");
    }

    /**
     * Test method for {@link geometries.Tube#findIntersections(primitives.Ray)} and
     * {@link geometries.Intersectable#findGeoIntersections(primitives.Ray)}: the two points come by distance
     * along the ray, nearest first, whichever way the ray crosses.
     */
    @Test
    void testIntersectionsNearestFirst() {
        // ===== Equivalence Partitions Tests =====
        // TC01: slanted across, off the axis: (1.8, 0.6, 1.2) then (0.2, 0.6, 2.8), and back
        assertNearestFirst(tube, new Ray(new Point3D(2, 0.6, 1), new Vector(-1, 0, 1)),
                List.of(new Point3D(1.8, 0.6, 1.2), new Point3D(0.2, 0.6, 2.8)), "TC01");
        // TC02: 200 seeded random rays from 10 off the axis through a point of it: 2 points each, nearest first
        Vector axis = tube.getAxisRay().getDir();
        assertNearestFirstThrough(tube, rnd -> {
            Point3D onAxis = tube.getAxisRay().getPoint(20 * rnd.nextDouble() - 10);
            Point3D start = onAxis.add(perpendicular(rnd, axis).scale(10)).add(axis.scale(20 * rnd.nextDouble() - 10));
            return new Ray(start, onAxis.subtract(start));
        }, "TC02");

        // ===== Boundary Values Tests =====
        // TC10: orthogonal to the axis, through it: (0, 0, 5) then (2, 0, 5), and back
        assertNearestFirst(tube, new Ray(new Point3D(-1, 0, 5), new Vector(1, 0, 0)),
                List.of(new Point3D(0, 0, 5), new Point3D(2, 0, 5)), "TC10");
        // TC11: nearly along the axis: the two points 1000 apart, (0, 0, 0) then (2, 0, 1000), and back
        assertNearestFirst(tube, new Ray(new Point3D(-0.002, 0, -1), new Vector(0.002, 0, 1)),
                List.of(new Point3D(0, 0, 0), new Point3D(2, 0, 1000)), "TC11");
    }
}
