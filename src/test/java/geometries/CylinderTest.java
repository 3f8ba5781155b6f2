package geometries;

import static org.junit.jupiter.api.Assertions.*;
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
 * Unit tests for {@link geometries.Cylinder}.
 */
class CylinderTest {
    /**
     * The cylinder used by most tests: axis ray from (0,0,1) along +z, radius 1, height 2, so the
     * bottom cap is the unit disc at z = 1, the top cap the unit disc at z = 3, and the side
     * x² + y² = 1 for 1 &lt; z &lt; 3.
     */
    private final Cylinder cylinder = new Cylinder(new Ray(new Point3D(0, 0, 1), new Vector(0, 0, 1)), 1, 2);

    /**
     * Test method for {@link geometries.Cylinder#Cylinder(primitives.Ray, double, double)}.
     */
    @Test
    void testConstructor() {
        Ray axis = new Ray(new Point3D(0, 0, 1), new Vector(0, 0, 5));
        // ===== Equivalence Partitions Tests =====
        // TC01: a correct cylinder keeps its axis, radius 1 and height 2
        Cylinder c = new Cylinder(axis, 1, 2);
        assertEquals(axis, c.getAxisRay(), "TC01: wrong axis ray");
        assertEquals(1, c.getRadius(), 1e-10, "TC01: wrong radius");
        assertEquals(2, c.getHeight(), 1e-10, "TC01: wrong height");
        // TC02: negative radius is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Cylinder(axis, -1, 2),
                "TC02: negative radius accepted");
        assertMessage(e, "radius", "TC02");
        // TC03: negative height is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Cylinder(axis, 1, -2),
                "TC03: negative height accepted");
        assertMessage(e, "height", "TC03");
        // TC04: NaN / infinite height is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Cylinder(axis, 1, Double.NaN),
                "TC04: NaN height accepted");
        assertMessage(e, "height", "TC04");
        e = assertThrows(IllegalArgumentException.class, () -> new Cylinder(axis, 1, Double.POSITIVE_INFINITY),
                "TC04: infinite height accepted");
        assertMessage(e, "height", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: zero radius is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Cylinder(axis, 0, 2), "TC10: zero radius accepted");
        assertMessage(e, "radius", "TC10");
        // TC11: zero height is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Cylinder(axis, 1, 0), "TC11: zero height accepted");
        assertMessage(e, "height", "TC11");
    }

    /**
     * Test method for {@link geometries.Cylinder#Cylinder(double, primitives.Ray, double)}, the course's
     * radius-first order.
     */
    @Test
    void testConstructorRadiusFirst() {
        Ray axis = new Ray(new Point3D(0, 0, 1), new Vector(0, 0, 5));
        // ===== Equivalence Partitions Tests =====
        // TC01: the same axis, radius 1 and height 2 as the axis-first constructor
        Cylinder c = new Cylinder(1, axis, 2);
        assertEquals(axis, c.getAxisRay(), "TC01: wrong axis ray");
        assertEquals(1, c.getRadius(), 1e-10, "TC01: wrong radius");
        assertEquals(2, c.getHeight(), 1e-10, "TC01: wrong height");
        // TC02: the same intersections as axis first, for a ray down the axis: the caps (0,0,3) and (0,0,1)
        Ray ray = new Ray(new Point3D(0, 0, 5), new Vector(0, 0, -1));
        assertEquals(new Cylinder(axis, 1, 2).findIntersections(ray), c.findIntersections(ray),
                "TC02: different intersections");
        // TC03: negative radius or height: the same messages as axis first
        assertSameRejection(() -> new Cylinder(axis, -1, 2), () -> new Cylinder(-1, axis, 2), "TC03");
        assertSameRejection(() -> new Cylinder(axis, 1, -2), () -> new Cylinder(1, axis, -2), "TC03");

        // ===== Boundary Values Tests =====
        // TC10: zero radius or height: the same messages as axis first
        assertSameRejection(() -> new Cylinder(axis, 0, 2), () -> new Cylinder(0, axis, 2), "TC10");
        assertSameRejection(() -> new Cylinder(axis, 1, 0), () -> new Cylinder(1, axis, 0), "TC10");
    }

    /**
     * Test method for {@link geometries.Cylinder#getNormal(primitives.Point3D)}.
     */
    @Test
    void testGetNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a point on the side (0.6, 0.8, 2.5) → (0.6, 0.8, 0)
        Vector n = cylinder.getNormal(new Point3D(0.6, 0.8, 2.5));
        assertEquals(1, n.length(), 1e-10, "TC01: normal is not a unit vector");
        assertEquals(new Vector(0.6, 0.8, 0), n, "TC01: wrong normal");
        // TC02: a point on the bottom cap (0.5, 0, 1) → −axis (0, 0, −1)
        n = cylinder.getNormal(new Point3D(0.5, 0, 1));
        assertEquals(1, n.length(), 1e-10, "TC02: normal is not a unit vector");
        assertEquals(new Vector(0, 0, -1), n, "TC02: wrong normal");
        // TC03: a point on the top cap (0, -0.5, 3) → +axis (0, 0, 1)
        n = cylinder.getNormal(new Point3D(0, -0.5, 3));
        assertEquals(1, n.length(), 1e-10, "TC03: normal is not a unit vector");
        assertEquals(new Vector(0, 0, 1), n, "TC03: wrong normal");
        // TC04: a cylinder along x: side point (1, 0, -1) → (0, 0, -1); bottom cap (0, 0.5, 0) → (-1, 0, 0);
        // top cap (2, 0, 0.5) → (1, 0, 0)
        Cylinder alongX = new Cylinder(new Ray(Point3D.ZERO, new Vector(3, 0, 0)), 1, 2);
        assertEquals(new Vector(0, 0, -1), alongX.getNormal(new Point3D(1, 0, -1)), "TC04: wrong side normal");
        assertEquals(new Vector(-1, 0, 0), alongX.getNormal(new Point3D(0, 0.5, 0)), "TC04: wrong bottom normal");
        assertEquals(new Vector(1, 0, 0), alongX.getNormal(new Point3D(2, 0, 0.5)), "TC04: wrong top normal");
        // TC05: a null point is refused, naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> cylinder.getNormal(null),
                "TC05: a null point must be refused"), "point must not be null", "TC05");

        // ===== Boundary Values Tests =====
        // TC10: the centre of the bottom cap (the axis ray's start) → (0, 0, −1)
        n = cylinder.getNormal(new Point3D(0, 0, 1));
        assertEquals(1, n.length(), 1e-10, "TC10: normal is not a unit vector");
        assertEquals(new Vector(0, 0, -1), n, "TC10: wrong normal");
        // TC11: the centre of the top cap → (0, 0, 1)
        assertEquals(new Vector(0, 0, 1), cylinder.getNormal(new Point3D(0, 0, 3)), "TC11: wrong normal");
        // TC12: a side point just above the bottom cap's level (1, 0, 1.001) → (1, 0, 0)
        assertEquals(new Vector(1, 0, 0), cylinder.getNormal(new Point3D(1, 0, 1.001)), "TC12: wrong normal");
        // TC13: the rims belong to the caps (as the intersection code says): (1,0,1) → (0,0,−1), (0,1,3) → (0,0,1)
        assertEquals(new Vector(0, 0, -1), cylinder.getNormal(new Point3D(1, 0, 1)), "TC13: wrong bottom rim normal");
        assertEquals(new Vector(0, 0, 1), cylinder.getNormal(new Point3D(0, 1, 3)), "TC13: wrong top rim normal");
    }

    /**
     * Test method for {@link geometries.Cylinder#findIntersections(primitives.Ray)}.
     */
    @Test
    void testFindIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: through both side walls (2 points)
        assertEquals(List.of(new Point3D(-1, 0, 2), new Point3D(1, 0, 2)),
                cylinder.findIntersections(new Ray(new Point3D(-2, 0, 2), new Vector(1, 0, 0))),
                "TC01: wrong intersection points");
        // TC02: in through the side, out through the top cap (2 points)
        assertEquals(List.of(new Point3D(-1, 0, 2.5), new Point3D(-0.5, 0, 3)),
                cylinder.findIntersections(new Ray(new Point3D(-2, 0, 1.5), new Vector(1, 0, 1))),
                "TC02: wrong intersection points");
        // TC03: in through the top cap, out through the side (2 points, cap first)
        assertEquals(List.of(new Point3D(0.5, 0, 3), new Point3D(1, 0, 2.5)),
                cylinder.findIntersections(new Ray(new Point3D(0, 0, 3.5), new Vector(1, 0, -1))),
                "TC03: wrong intersection points");
        // TC04: in through the side, out through the bottom cap (2 points, side first)
        assertEquals(List.of(new Point3D(-1, 0, 2), new Point3D(0, 0, 1)),
                cylinder.findIntersections(new Ray(new Point3D(-2, 0, 3), new Vector(1, 0, -1))),
                "TC04: wrong intersection points");
        // TC05: through both caps, slanted (2 points)
        assertEquals(List.of(new Point3D(0.2, 0, 1), new Point3D(0.6, 0, 3)),
                cylinder.findIntersections(new Ray(Point3D.ZERO, new Vector(0.2, 0, 1))),
                "TC05: wrong intersection points");
        // TC06: through both caps, slanted, downwards (2 points, top first)
        assertEquals(List.of(new Point3D(0.6, 0, 3), new Point3D(0.2, 0, 1)),
                cylinder.findIntersections(new Ray(new Point3D(0.8, 0, 4), new Vector(-0.2, 0, -1))),
                "TC06: wrong intersection points");
        // TC07: starts inside, leaves through the side (1 point)
        assertEquals(List.of(new Point3D(1, 0, 2)),
                cylinder.findIntersections(new Ray(new Point3D(0, 0, 2), new Vector(1, 0, 0))),
                "TC07: wrong intersection points");
        // TC08: starts inside, leaves through the top cap (1 point)
        assertEquals(List.of(new Point3D(0.25, 0, 3)),
                cylinder.findIntersections(new Ray(new Point3D(0, 0, 2), new Vector(0.25, 0, 1))),
                "TC08: wrong intersection points");
        // TC09: misses beside the cylinder (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(3, 3, 0), new Vector(0, 0, 1))),
                "TC09: wrong intersection points");
        // TC10: crosses the infinite tube above the top cap (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(-2, 0, 4), new Vector(1, 0, 0))),
                "TC10: wrong intersection points");
        // TC11: crosses the infinite tube below the bottom cap (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(-2, 0, 0), new Vector(1, 0, 0))),
                "TC11: wrong intersection points");
        // TC12: crosses the cap planes outside the discs (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(3, 0, 0), new Vector(0, 0.2, 1))),
                "TC12: wrong intersection points");
        // TC13: starts after the cylinder (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(2, 0, 2), new Vector(1, 0, 0))),
                "TC13: wrong intersection points");
        // TC14: a cylinder along x, crossed by a ray along y (2 points)
        Cylinder alongX = new Cylinder(new Ray(Point3D.ZERO, new Vector(1, 0, 0)), 1, 2);
        assertEquals(List.of(new Point3D(1, -1, 0), new Point3D(1, 1, 0)),
                alongX.findIntersections(new Ray(new Point3D(1, -2, 0), new Vector(0, 1, 0))),
                "TC14: wrong intersection points");

        // ===== Boundary Values Tests =====
        // **** Group: the ray is parallel to the axis
        // TC20: along the axis from below, through both caps (2 points)
        assertEquals(List.of(new Point3D(0, 0, 1), new Point3D(0, 0, 3)),
                cylinder.findIntersections(new Ray(Point3D.ZERO, new Vector(0, 0, 1))),
                "TC20: wrong intersection points");
        // TC21: along the axis from above, downwards (2 points, top first)
        assertEquals(List.of(new Point3D(0, 0, 3), new Point3D(0, 0, 1)),
                cylinder.findIntersections(new Ray(new Point3D(0, 0, 5), new Vector(0, 0, -1))),
                "TC21: wrong intersection points");
        // TC22: in the axis direction from inside, on the axis (1 point)
        assertEquals(List.of(new Point3D(0, 0, 3)),
                cylinder.findIntersections(new Ray(new Point3D(0, 0, 2), new Vector(0, 0, 1))),
                "TC22: wrong intersection points");
        // TC23: in the axis direction from inside, off the axis (1 point)
        assertEquals(List.of(new Point3D(0.5, 0, 3)),
                cylinder.findIntersections(new Ray(new Point3D(0.5, 0, 2), new Vector(0, 0, 1))),
                "TC23: wrong intersection points");
        // TC24: against the axis direction from inside, off the axis (1 point)
        assertEquals(List.of(new Point3D(0.5, 0, 1)),
                cylinder.findIntersections(new Ray(new Point3D(0.5, 0, 2), new Vector(0, 0, -1))),
                "TC24: wrong intersection points");
        // TC25: parallel to the axis, outside the radius (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(2, 0, 0), new Vector(0, 0, 1))),
                "TC25: wrong intersection points");
        // TC26: starting at the bottom cap centre, along the axis (1 point)
        assertEquals(List.of(new Point3D(0, 0, 3)),
                cylinder.findIntersections(new Ray(new Point3D(0, 0, 1), new Vector(0, 0, 1))),
                "TC26: wrong intersection points");
        // TC27: starting on the top cap, going out along the axis (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(0, 0, 3), new Vector(0, 0, 1))),
                "TC27: wrong intersection points");
        // TC28: parallel to the axis along the side surface: it meets the two rims, which belong to
        // the caps (closed body, like closed polygons) (2 points)
        assertEquals(List.of(new Point3D(1, 0, 1), new Point3D(1, 0, 3)),
                cylinder.findIntersections(new Ray(new Point3D(1, 0, 0), new Vector(0, 0, 1))),
                "TC28: wrong intersection points");

        // **** Group: the ray starts on the surface
        // TC30: on the side, going inside (1 point)
        assertEquals(List.of(new Point3D(-1, 0, 2)),
                cylinder.findIntersections(new Ray(new Point3D(1, 0, 2), new Vector(-1, 0, 0))),
                "TC30: wrong intersection points");
        // TC31: on the side, going outside (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(1, 0, 2), new Vector(1, 0, 0))),
                "TC31: wrong intersection points");
        // TC32: on the bottom cap, going inside slanted, out through the side (1 point)
        assertEquals(List.of(new Point3D(1, 0, 2)),
                cylinder.findIntersections(new Ray(new Point3D(0, 0, 1), new Vector(1, 0, 1))),
                "TC32: wrong intersection points");
        // TC33: on the bottom cap, going outside (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(0.5, 0, 1), new Vector(0, 1, -1))),
                "TC33: wrong intersection points");

        // **** Group: tangent, rims and cap planes
        // TC40: tangent to the side (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(1, -2, 2), new Vector(0, 1, 0))),
                "TC40: wrong intersection points");
        // TC41: in the plane of the bottom cap, across the disc: the ray lies in the face, which counts
        // as no hit, as for a polygon (null)
        assertNull(cylinder.findIntersections(new Ray(new Point3D(-2, 0, 1), new Vector(1, 0, 0))),
                "TC41: wrong intersection points");
        // TC42: diagonally through the top rim and the opposite bottom rim (2 points)
        assertEquals(List.of(new Point3D(1, 0, 3), new Point3D(-1, 0, 1)),
                cylinder.findIntersections(new Ray(new Point3D(2, 0, 4), new Vector(-1, 0, -1))),
                "TC42: wrong intersection points");
        // TC43: grazing the top rim only from outside: the rim is part of the closed body (1 point)
        assertEquals(List.of(new Point3D(1, 0, 3)),
                cylinder.findIntersections(new Ray(new Point3D(2, 0, 2), new Vector(-1, 0, 1))),
                "TC43: wrong intersection points");
        // TC44: orthogonal to the axis through the axis, exactly at the middle height (2 points)
        assertEquals(List.of(new Point3D(0, -1, 2), new Point3D(0, 1, 2)),
                cylinder.findIntersections(new Ray(new Point3D(0, -3, 2), new Vector(0, 1, 0))),
                "TC44: wrong intersection points");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray, double)} on a cylinder.
     */
    @Test
    void testFindGeoIntersectionsMaxDistance() {
        // along the axis from the origin: bottom cap at t = 1, top cap at t = 3
        Ray ray = new Ray(Point3D.ZERO, new Vector(0, 0, 1));
        // ===== Equivalence Partitions Tests =====
        // TC01: both within the distance (2 points, each naming the cylinder)
        List<GeoPoint> result = cylinder.findGeoIntersections(ray, 10);
        assertEquals(List.of(new GeoPoint(cylinder, new Point3D(0, 0, 1)), new GeoPoint(cylinder, new Point3D(0, 0, 3))),
                result, "TC01: wrong intersection points");
        assertSame(cylinder, result.get(1).geometry, "TC01: wrong geometry");
        // TC02: only the bottom cap within the distance (1 point)
        assertEquals(List.of(new GeoPoint(cylinder, new Point3D(0, 0, 1))), cylinder.findGeoIntersections(ray, 2),
                "TC02: wrong intersection points");
        // TC03: both beyond the distance (null)
        assertNull(cylinder.findGeoIntersections(ray, 0.5), "TC03: wrong intersection points");
        // TC04: side then cap (TC02 of findIntersections, t = √2 and 1.5·√2): only the side within 2
        Ray slanted = new Ray(new Point3D(-2, 0, 1.5), new Vector(1, 0, 1));
        assertEquals(List.of(new GeoPoint(cylinder, new Point3D(-1, 0, 2.5))), cylinder.findGeoIntersections(slanted, 2),
                "TC04: wrong intersection points");
        // TC05: cap then side (TC03 of findIntersections, t = 0.5·√2 and √2): only the cap within 1
        Ray capFirst = new Ray(new Point3D(0, 0, 3.5), new Vector(1, 0, -1));
        assertEquals(List.of(new GeoPoint(cylinder, new Point3D(0.5, 0, 3))), cylinder.findGeoIntersections(capFirst, 1),
                "TC05: wrong intersection points");

        // ===== Boundary Values Tests =====
        // TC10: the distance is exactly the first point's (inclusive: 1 point)
        assertEquals(List.of(new GeoPoint(cylinder, new Point3D(0, 0, 1))), cylinder.findGeoIntersections(ray, 1),
                "TC10: wrong intersection points");
        // TC11: the distance is exactly the second point's (inclusive: 2 points)
        assertEquals(2, cylinder.findGeoIntersections(ray, 3).size(), "TC11: wrong number of intersection points");
        // TC12: the side points at exactly t = 1 and t = 3 (orthogonal ray through the axis)
        Ray across = new Ray(new Point3D(-2, 0, 2), new Vector(1, 0, 0));
        assertEquals(List.of(new GeoPoint(cylinder, new Point3D(-1, 0, 2))), cylinder.findGeoIntersections(across, 1),
                "TC12: wrong intersection points");
        assertEquals(2, cylinder.findGeoIntersections(across, 3).size(), "TC12: wrong number of intersection points");
    }

    /**
     * Test method for {@link geometries.Cylinder#findIntersections(primitives.Ray)} and
     * {@link geometries.Intersectable#findGeoIntersections(primitives.Ray)}: the two points come by distance
     * along the ray, nearest first, whichever of the side and the caps the ray meets first.
     */
    @Test
    void testIntersectionsNearestFirst() {
        // ===== Equivalence Partitions Tests =====
        // TC01: in through the top cap, out through the side: (0.5, 0, 3) then (1, 0, 2.5); back, side first
        assertNearestFirst(cylinder, new Ray(new Point3D(0, 0, 3.5), new Vector(1, 0, -1)),
                List.of(new Point3D(0.5, 0, 3), new Point3D(1, 0, 2.5)), "TC01");
        // TC02: in through the side, out through the bottom cap: (-1, 0, 2) then (0, 0, 1); back, cap first
        assertNearestFirst(cylinder, new Ray(new Point3D(-2, 0, 3), new Vector(1, 0, -1)),
                List.of(new Point3D(-1, 0, 2), new Point3D(0, 0, 1)), "TC02");
        // TC03: through both side walls: (-1, 0, 2) then (1, 0, 2), and back
        assertNearestFirst(cylinder, new Ray(new Point3D(-2, 0, 2), new Vector(1, 0, 0)),
                List.of(new Point3D(-1, 0, 2), new Point3D(1, 0, 2)), "TC03");
        // TC04: through both caps, slanted: (0.2, 0, 1) then (0.6, 0, 3), and back
        assertNearestFirst(cylinder, new Ray(Point3D.ZERO, new Vector(0.2, 0, 1)),
                List.of(new Point3D(0.2, 0, 1), new Point3D(0.6, 0, 3)), "TC04");
        // TC05: 200 seeded random rays from 10 away through a point of the axis: 2 points each, nearest first
        assertNearestFirstThrough(cylinder, rnd -> rayThrough(rnd, pointIn(rnd, cylinder), 10), "TC05");

        // ===== Boundary Values Tests =====
        // TC10: along the axis: the bottom cap (0, 0, 1) then the top cap (0, 0, 3), and back
        assertNearestFirst(cylinder, new Ray(Point3D.ZERO, new Vector(0, 0, 1)),
                List.of(new Point3D(0, 0, 1), new Point3D(0, 0, 3)), "TC10");
        // TC11: through the top rim and the opposite bottom rim: (1, 0, 3) then (-1, 0, 1), and back
        assertNearestFirst(cylinder, new Ray(new Point3D(2, 0, 4), new Vector(-1, 0, -1)),
                List.of(new Point3D(1, 0, 3), new Point3D(-1, 0, 1)), "TC11");
        // TC12: across the corner next to the top rim, the cap 0.01 before the side: (0.99, 0, 3) then (1, 0, 2.99)
        assertNearestFirst(cylinder, new Ray(new Point3D(0.49, 0, 3.5), new Vector(1, 0, -1)),
                List.of(new Point3D(0.99, 0, 3), new Point3D(1, 0, 2.99)), "TC12");
    }
}
