package primitives;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import geometries.Sphere;

/**
 * Unit tests for {@link primitives.Ray}.
 */
class RayTest {
    /** Tolerance for comparing doubles. */
    private static final double DELTA = 1e-10;

    /** Test method for {@link primitives.Ray#Ray(primitives.Point3D, primitives.Vector)}. */
    @Test
    void testConstructor() {
        Point3D p0 = new Point3D(1, 2, 3);
        // ===== Equivalence Partitions Tests =====
        // TC01: direction (0,3,4) is kept as the unit copy (0,0.6,0.8); p0 is (1,2,3)
        Vector dir = new Vector(0, 3, 4);
        Ray ray = new Ray(p0, dir);
        assertEquals(new Point3D(1, 2, 3), ray.getP0(), "TC01: wrong p0");
        assertEquals(new Vector(0, 0.6, 0.8), ray.getDir(), "TC01: wrong direction");
        assertEquals(1, ray.getDir().length(), DELTA, "TC01: direction is not unit");
        // TC02: the caller's vector is unchanged (0,3,4) and is not the ray's own direction object
        assertEquals(0, dir.getX(), 0, "TC02: the ray changed the caller's vector");
        assertEquals(3, dir.getY(), 0, "TC02: the ray changed the caller's vector");
        assertEquals(4, dir.getZ(), 0, "TC02: the ray changed the caller's vector");
        assertNotSame(dir, ray.getDir(), "TC02: the ray must keep its own copy of the direction");
        // TC03: null start point or direction is rejected with a message naming the argument
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Ray(null, new Vector(1, 0, 0)), "TC03: null p0 must be rejected");
        assertMessage(e, "null", "TC03");
        assertMessage(e, "start point", "TC03");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Ray(p0, null), "TC03: null direction must be rejected");
        assertMessage(e, "null", "TC03");
        assertMessage(e, "direction", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: a unit direction (0,0,-1) is still copied: equal, not the same object, caller's vector unchanged
        Vector unit = new Vector(0, 0, -1);
        Ray r2 = new Ray(Point3D.ZERO, unit);
        assertEquals(new Vector(0, 0, -1), r2.getDir(), "TC10: wrong direction");
        assertNotSame(unit, r2.getDir(), "TC10: the ray must keep its own copy of the direction");
        // TC11: normalising the caller's vector later does not change the ray
        Vector later = new Vector(0, 0, 2);
        Ray r3 = new Ray(Point3D.ZERO, later);
        later.normalize();
        later.normalize();
        assertEquals(new Vector(0, 0, 1), r3.getDir(), "TC11: the ray's direction must not depend on the caller's vector");
    }

    /** Test method for {@link primitives.Ray#Ray(primitives.Point3D, primitives.Vector, primitives.Vector)}. */
    @Test
    void testConstructorWithNormal() {
        Point3D head = new Point3D(1, 1, 1);
        Vector normal = new Vector(0, 0, 1);
        // ===== Equivalence Partitions Tests =====
        // TC01: direction on the normal's side (dir·n > 0): head moves +0.1 along the normal to (1,1,1.1)
        Vector up = new Vector(1, 0, 1);
        Ray r1 = new Ray(head, up, normal);
        assertEquals(new Point3D(1, 1, 1.1), r1.getP0(), "TC01: head must move +DELTA along the normal");
        assertEquals(new Vector(1 / Math.sqrt(2), 0, 1 / Math.sqrt(2)), r1.getDir(), "TC01: wrong unit direction");
        // TC02: direction on the other side (dir·n < 0): head moves -0.1 along the normal to (1,1,0.9)
        Ray r2 = new Ray(head, new Vector(1, 0, -1), normal);
        assertEquals(new Point3D(1, 1, 0.9), r2.getP0(), "TC02: head must move -DELTA along the normal");
        assertEquals(new Vector(1 / Math.sqrt(2), 0, -1 / Math.sqrt(2)), r2.getDir(), "TC02: wrong unit direction");
        // TC03: a normal that is not unit (0,0,5) still moves the head by exactly DELTA: (1,1,1.1)
        Ray r3 = new Ray(head, up, new Vector(0, 0, 5));
        assertEquals(new Point3D(1, 1, 1.1), r3.getP0(), "TC03: head must move exactly DELTA");
        assertEquals(Ray.DELTA, r3.getP0().distance(head), DELTA, "TC03: head must move exactly DELTA");
        // TC04: a slanted normal (1,1,1)/sqrt(3) with direction (1,1,0): head moves 0.1 along it
        Vector slanted = new Vector(1, 1, 1).normalized();
        Ray r4 = new Ray(Point3D.ZERO, new Vector(1, 1, 0), slanted);
        double d = 0.1 / Math.sqrt(3);
        assertEquals(new Point3D(d, d, d), r4.getP0(), "TC04: head must move DELTA along the slanted normal");
        // TC05: the arguments are unchanged
        assertEquals(new Point3D(1, 1, 1), head, "TC05: the head point changed");
        assertEquals(1, up.getX(), 0, "TC05: the direction changed");
        assertEquals(1, up.getZ(), 0, "TC05: the direction changed");
        assertEquals(1, normal.getZ(), 0, "TC05: the normal changed");
        assertNotSame(up, r1.getDir(), "TC05: the ray must keep its own copy of the direction");
        // TC06: null arguments are rejected with messages naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Ray(null, up, normal), "TC06: null head must be rejected");
        assertMessage(e, "null", "TC06");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Ray(head, null, normal), "TC06: null direction must be rejected");
        assertMessage(e, "null", "TC06");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Ray(head, up, null), "TC06: null normal must be rejected");
        assertMessage(e, "normal", "TC06");

        // ===== Boundary Values Tests =====
        // TC10: direction orthogonal to the normal (dir·n = 0): head stays (1,1,1)
        Ray r10 = new Ray(head, new Vector(1, 0, 0), normal);
        assertEquals(new Point3D(1, 1, 1), r10.getP0(), "TC10: head must not move when dir·n = 0");
        assertEquals(new Vector(1, 0, 0), r10.getDir(), "TC10: wrong direction");
        // TC11: dir·n within the tolerance of 0 (1e-12): head stays (1,1,1)
        Ray r11 = new Ray(head, new Vector(1, 0, 1e-12), normal);
        assertEquals(new Point3D(1, 1, 1), r11.getP0(), "TC11: head must not move when dir·n is about 0");
        // TC12: direction along the normal: head moves to (1,1,1.1), direction (0,0,1)
        Ray r12 = new Ray(head, new Vector(0, 0, 3), normal);
        assertEquals(new Point3D(1, 1, 1.1), r12.getP0(), "TC12: head must move +DELTA");
        assertEquals(new Vector(0, 0, 1), r12.getDir(), "TC12: wrong direction");
        // TC13: direction against the normal: head moves to (1,1,0.9), direction (0,0,-1)
        Ray r13 = new Ray(head, new Vector(0, 0, -3), normal);
        assertEquals(new Point3D(1, 1, 0.9), r13.getP0(), "TC13: head must move -DELTA");
        assertEquals(new Vector(0, 0, -1), r13.getDir(), "TC13: wrong direction");
        // TC14: DELTA is 0.1
        assertEquals(0.1, Ray.DELTA, 0, "TC14: DELTA must be 0.1");
    }

    /** Test method for {@link primitives.Ray#getPoint(double)}. */
    @Test
    void testGetPoint() {
        Ray ray = new Ray(new Point3D(1, 0, 0), new Vector(0, 3, 4));
        // ===== Equivalence Partitions Tests =====
        // TC01: t = 5 gives (1,3,4)
        assertEquals(new Point3D(1, 3, 4), ray.getPoint(5), "TC01: wrong point at t=5");
        // TC02: t = 0.5 gives (1,0.3,0.4)
        assertEquals(new Point3D(1, 0.3, 0.4), ray.getPoint(0.5), "TC02: wrong point at t=0.5");
        // TC03: the distance from p0 to getPoint(t) is t (7.25)
        assertEquals(7.25, ray.getPoint(7.25).distance(ray.getP0()), DELTA, "TC03: wrong distance");

        // ===== Boundary Values Tests =====
        // TC10: t = 0 gives p0 (1,0,0)
        assertEquals(new Point3D(1, 0, 0), ray.getPoint(0), "TC10: t=0 must give p0");
        // TC11: NaN is rejected (not finite)
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ray.getPoint(Double.NaN), "TC11: NaN t must be rejected");
        assertMessage(e, "finite", "TC11");
    }

    /** Test method for {@link primitives.Ray#findClosestPoint(java.util.List)}. */
    @Test
    void testFindClosestPoint() {
        Ray ray = new Ray(Point3D.ZERO, new Vector(1, 0, 0));
        Point3D p1 = new Point3D(1, 0, 0);
        Point3D p2 = new Point3D(2, 1, 0);
        Point3D p3 = new Point3D(3, 0, 5);
        // ===== Equivalence Partitions Tests =====
        // TC01: the closest point is in the middle of the list: (1,0,0)
        assertSame(p1, ray.findClosestPoint(List.of(p2, p1, p3)), "TC01: wrong closest point (middle)");
        // TC02: a point off the ray's line but nearest is still chosen: (0,-0.5,0) before (1,0,0)
        Point3D side = new Point3D(0, -0.5, 0);
        assertSame(side, ray.findClosestPoint(List.of(p1, side, p2)), "TC02: wrong closest point (off the line)");

        // ===== Boundary Values Tests =====
        // TC10: null list: null
        assertNull(ray.findClosestPoint(null), "TC10: null list must give null");
        // TC11: empty list: null
        assertNull(ray.findClosestPoint(new ArrayList<>()), "TC11: empty list must give null");
        // TC12: closest is first: (1,0,0)
        assertSame(p1, ray.findClosestPoint(List.of(p1, p2, p3)), "TC12: wrong closest point (first)");
        // TC13: closest is last: (1,0,0)
        assertSame(p1, ray.findClosestPoint(List.of(p3, p2, p1)), "TC13: wrong closest point (last)");
        // TC14: single point: that point (3,0,5)
        assertSame(p3, ray.findClosestPoint(List.of(p3)), "TC14: wrong closest point (single)");
        // TC15: p0 itself in the list: p0 (distance 0)
        assertSame(Point3D.ZERO, ray.findClosestPoint(List.of(p2, Point3D.ZERO, p1)),
                "TC15: p0 itself must be the closest");
    }

    /** Test method for {@link primitives.Ray#findClosestGeoPoint(java.util.List)}. */
    @Test
    void testFindClosestGeoPoint() {
        Ray ray = new Ray(Point3D.ZERO, new Vector(1, 0, 0));
        Sphere s1 = new Sphere(new Point3D(1, 0, 0), 0.5);
        Sphere s2 = new Sphere(new Point3D(5, 0, 0), 0.5);
        GeoPoint g1 = new GeoPoint(s1, new Point3D(0.5, 0, 0));
        GeoPoint g2 = new GeoPoint(s2, new Point3D(4.5, 0, 0));
        GeoPoint g3 = new GeoPoint(s2, new Point3D(5.5, 0, 0));
        // ===== Equivalence Partitions Tests =====
        // TC01: the closest is in the middle: g1 at (0.5,0,0) on s1
        GeoPoint closest = ray.findClosestGeoPoint(List.of(g2, g1, g3));
        assertSame(g1, closest, "TC01: wrong closest geo point (middle)");
        assertSame(s1, closest.geometry, "TC01: wrong geometry of the closest geo point");
        assertEquals(new Point3D(0.5, 0, 0), closest.point, "TC01: wrong point of the closest geo point");

        // ===== Boundary Values Tests =====
        // TC10: null list: null
        assertNull(ray.findClosestGeoPoint(null), "TC10: null list must give null");
        // TC11: empty list: null
        assertNull(ray.findClosestGeoPoint(new ArrayList<>()), "TC11: empty list must give null");
        // TC12: closest is first: g1
        assertSame(g1, ray.findClosestGeoPoint(List.of(g1, g2, g3)), "TC12: wrong closest geo point (first)");
        // TC13: closest is last: g1
        assertSame(g1, ray.findClosestGeoPoint(List.of(g3, g2, g1)), "TC13: wrong closest geo point (last)");
        // TC14: single geo point: g3
        assertSame(g3, ray.findClosestGeoPoint(List.of(g3)), "TC14: wrong closest geo point (single)");
    }

    /** Test method for {@link primitives.Ray#equals(Object)} and {@link primitives.Ray#hashCode()}. */
    @Test
    void testEquals() {
        Ray ray = new Ray(new Point3D(1, 2, 3), new Vector(0, 0, 1));
        // ===== Equivalence Partitions Tests =====
        // TC01: same p0 and direction: equal, same hash code
        Ray same = new Ray(new Point3D(1, 2, 3), new Vector(0, 0, 1));
        assertEquals(ray, same, "TC01: rays with the same p0 and direction must be equal");
        assertEquals(ray.hashCode(), same.hashCode(), "TC01: equal rays must have the same hash code");
        // TC02: same p0, direction of another length (0,0,7): equal (directions are unit)
        Ray longer = new Ray(new Point3D(1, 2, 3), new Vector(0, 0, 7));
        assertEquals(ray, longer, "TC02: direction length must not matter");
        assertEquals(ray.hashCode(), longer.hashCode(), "TC02: equal rays must have the same hash code");
        // TC03: different p0: not equal
        assertNotEquals(ray, new Ray(new Point3D(1, 2, 4), new Vector(0, 0, 1)), "TC03: different p0 must differ");
        // TC04: different direction: not equal
        assertNotEquals(ray, new Ray(new Point3D(1, 2, 3), new Vector(0, 1, 1)), "TC04: different direction must differ");
        // TC05: another type or null: not equal
        assertNotEquals(ray, new Point3D(1, 2, 3), "TC05: a ray is not equal to a point");
        assertFalse(ray.equals(null), "TC05: a ray is not equal to null");

        // ===== Boundary Values Tests =====
        // TC10: reflexive
        assertEquals(ray, ray, "TC10: a ray must equal itself");
        // TC11: opposite direction (0,0,-1): not equal
        assertNotEquals(ray, new Ray(new Point3D(1, 2, 3), new Vector(0, 0, -1)), "TC11: opposite direction must differ");
        // TC12: p0 within the tolerance (5e-11): equal
        assertEquals(ray, new Ray(new Point3D(1 + 5e-11, 2, 3), new Vector(0, 0, 1)), "TC12: p0 within the tolerance");
    }
}
