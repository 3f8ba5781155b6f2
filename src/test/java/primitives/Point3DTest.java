package primitives;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link primitives.Point3D}.
 */
class Point3DTest {
    /** Tolerance for comparing doubles. */
    private static final double DELTA = 1e-10;

    /** Test method for {@link primitives.Point3D#Point3D(double, double, double)} and the getters. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: ordinary coordinates are kept (1, -2.5, 3)
        Point3D p = new Point3D(1, -2.5, 3);
        assertEquals(1, p.getX(), 0, "TC01: wrong x");
        assertEquals(-2.5, p.getY(), 0, "TC01: wrong y");
        assertEquals(3, p.getZ(), 0, "TC01: wrong z");
        // TC02: NaN coordinate is rejected, the message names the coordinate and "finite"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Point3D(Double.NaN, 0, 0), "TC02: NaN x must be rejected");
        assertMessage(e, "coordinate", "TC02");
        assertMessage(e, "finite", "TC02");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Point3D(0, Double.NaN, 0), "TC02: NaN y must be rejected");
        assertMessage(e, "finite", "TC02");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Point3D(0, 0, Double.NaN), "TC02: NaN z must be rejected");
        assertMessage(e, "finite", "TC02");
        // TC03: infinite coordinates are rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Point3D(Double.POSITIVE_INFINITY, 0, 0), "TC03: +inf x must be rejected");
        assertMessage(e, "finite", "TC03");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Point3D(0, Double.NEGATIVE_INFINITY, 0), "TC03: -inf y must be rejected");
        assertMessage(e, "finite", "TC03");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Point3D(0, 0, Double.POSITIVE_INFINITY), "TC03: +inf z must be rejected");
        assertMessage(e, "finite", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: ZERO is the origin (0, 0, 0)
        assertEquals(0, Point3D.ZERO.getX(), 0, "TC10: ZERO x is not 0");
        assertEquals(0, Point3D.ZERO.getY(), 0, "TC10: ZERO y is not 0");
        assertEquals(0, Point3D.ZERO.getZ(), 0, "TC10: ZERO z is not 0");
        assertEquals(new Point3D(0, 0, 0), Point3D.ZERO, "TC10: ZERO is not the origin");
        // TC11: the largest finite coordinates are accepted (MAX_VALUE, -MAX_VALUE, 0)
        Point3D big = new Point3D(Double.MAX_VALUE, -Double.MAX_VALUE, 0);
        assertEquals(Double.MAX_VALUE, big.getX(), 0, "TC11: wrong x");
        assertEquals(-Double.MAX_VALUE, big.getY(), 0, "TC11: wrong y");
    }

    /** Test method for {@link primitives.Point3D#add(primitives.Vector)}. */
    @Test
    void testAdd() {
        Point3D p = new Point3D(1, 2, 3);
        // ===== Equivalence Partitions Tests =====
        // TC01: (1,2,3) + (1,-4,2.5) = (2,-2,5.5)
        assertEquals(new Point3D(2, -2, 5.5), p.add(new Vector(1, -4, 2.5)), "TC01: wrong point after add");
        // TC02: the operand point is unchanged (1,2,3)
        assertEquals(1, p.getX(), 0, "TC02: add changed the point");
        assertEquals(2, p.getY(), 0, "TC02: add changed the point");
        assertEquals(3, p.getZ(), 0, "TC02: add changed the point");
        // TC03: null vector is rejected with an IllegalArgumentException naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> p.add(null),
                "TC03: null vector must be rejected");
        assertMessage(e, "null", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: adding the opposite vector gives the origin ZERO
        assertEquals(Point3D.ZERO, p.add(new Vector(-1, -2, -3)), "TC10: (1,2,3) + (-1,-2,-3) must be ZERO");
        // TC11: an overflowing sum is rejected as not finite
        Point3D far = new Point3D(Double.MAX_VALUE, 0, 0);
        IllegalArgumentException e2 = assertThrows(IllegalArgumentException.class,
                () -> far.add(new Vector(Double.MAX_VALUE, 0, 0)), "TC11: overflow must be rejected");
        assertMessage(e2, "finite", "TC11");
    }

    /** Test method for {@link primitives.Point3D#subtract(primitives.Point3D)}. */
    @Test
    void testSubtract() {
        Point3D p1 = new Point3D(1, 2, 3);
        Point3D p2 = new Point3D(2, 3, 4);
        // ===== Equivalence Partitions Tests =====
        // TC01: (2,3,4) - (1,2,3) = vector (1,1,1)
        assertEquals(new Vector(1, 1, 1), p2.subtract(p1), "TC01: wrong vector after subtract");
        // TC02: (1,2,3) - (2,3,4) = vector (-1,-1,-1)
        assertEquals(new Vector(-1, -1, -1), p1.subtract(p2), "TC02: wrong vector after subtract");
        // TC03: operands unchanged
        assertEquals(new Point3D(1, 2, 3), p1, "TC03: subtract changed its point");
        assertEquals(new Point3D(2, 3, 4), p2, "TC03: subtract changed its argument");
        // TC04: null point is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> p1.subtract(null),
                "TC04: null point must be rejected");
        assertMessage(e, "null", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: p.subtract(p) is the zero vector and is rejected
        e = assertThrows(IllegalArgumentException.class, () -> p1.subtract(p1),
                "TC10: p - p must be rejected");
        assertMessage(e, "zero vector", "TC10");
        // TC11: subtracting an equal (distinct) point is rejected
        e = assertThrows(IllegalArgumentException.class, () -> p1.subtract(new Point3D(1, 2, 3)),
                "TC11: p - equal point must be rejected");
        assertMessage(e, "zero vector", "TC11");
        // TC12: subtracting a point only 5e-11 away gives a short vector, not zero: only exactly zero is refused
        assertEquals(-5e-11, p1.subtract(new Point3D(1 + 5e-11, 2, 3)).getX(), 1e-15,
                "TC12: p - nearly equal point must be a short vector");
        // TC13: the origin minus a point gives the opposite vector (-1,-2,-3)
        assertEquals(new Vector(-1, -2, -3), Point3D.ZERO.subtract(p1), "TC13: wrong vector");
    }

    /** Test method for {@link primitives.Point3D#distanceSquared(primitives.Point3D)}. */
    @Test
    void testDistanceSquared() {
        Point3D p1 = new Point3D(1, 2, 3);
        // ===== Equivalence Partitions Tests =====
        // TC01: (1,2,3) to (4,6,3): 25
        assertEquals(25, p1.distanceSquared(new Point3D(4, 6, 3)), DELTA, "TC01: wrong squared distance");
        // TC02: symmetric: (4,6,3) to (1,2,3): 25
        assertEquals(25, new Point3D(4, 6, 3).distanceSquared(p1), DELTA, "TC02: wrong squared distance");
        // TC03: (1,2,3) to (0,0,0): 14
        assertEquals(14, p1.distanceSquared(Point3D.ZERO), DELTA, "TC03: wrong squared distance");
        // TC04: null point is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> p1.distanceSquared(null), "TC04: null point must be rejected");
        assertMessage(e, "null", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: distance to itself: 0
        assertEquals(0, p1.distanceSquared(p1), 0, "TC10: squared distance to itself must be 0");
    }

    /** Test method for {@link primitives.Point3D#distance(primitives.Point3D)}. */
    @Test
    void testDistance() {
        Point3D p1 = new Point3D(1, 2, 3);
        // ===== Equivalence Partitions Tests =====
        // TC01: (1,2,3) to (4,6,3): 5
        assertEquals(5, p1.distance(new Point3D(4, 6, 3)), DELTA, "TC01: wrong distance");
        // TC02: (1,2,3) to (-1,0,2): 3
        assertEquals(3, p1.distance(new Point3D(-1, 0, 2)), DELTA, "TC02: wrong distance");
        // TC03: (1,2,3) to the origin: sqrt(14)
        assertEquals(Math.sqrt(14), p1.distance(Point3D.ZERO), DELTA, "TC03: wrong distance");
        // TC04: null point is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> p1.distance(null), "TC04: null point must be rejected");
        assertMessage(e, "null", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: distance to itself: 0
        assertEquals(0, p1.distance(p1), 0, "TC10: distance to itself must be 0");
        // TC11: distance to an equal point: 0
        assertEquals(0, p1.distance(new Point3D(1, 2, 3)), 0, "TC11: distance to an equal point must be 0");
    }

    /** Test method for {@link primitives.Point3D#equals(Object)} and {@link primitives.Point3D#hashCode()}. */
    @Test
    void testEqualsAndHashCode() {
        Point3D p = new Point3D(1, 2, 3);
        // ===== Equivalence Partitions Tests =====
        // TC01: same coordinates: equal, same hash code
        Point3D q = new Point3D(1, 2, 3);
        assertEquals(p, q, "TC01: points with the same coordinates must be equal");
        assertEquals(q, p, "TC01: equality must be symmetric");
        assertEquals(p.hashCode(), q.hashCode(), "TC01: equal points must have the same hash code");
        // TC02: different point: not equal
        assertNotEquals(p, new Point3D(1, 2, 4), "TC02: different points must not be equal");
        assertNotEquals(p, new Point3D(0, 2, 3), "TC02: different points must not be equal");
        assertNotEquals(p, new Point3D(1, 3, 3), "TC02: different points must not be equal");
        // TC03: another type (a vector with the same components) is not equal
        assertNotEquals(p, new Vector(1, 2, 3), "TC03: a point is not equal to a vector");
        // TC04: null is not equal
        assertFalse(p.equals(null), "TC04: a point is not equal to null");

        // ===== Boundary Values Tests =====
        // TC10: reflexive
        assertEquals(p, p, "TC10: a point must equal itself");
        // TC11: difference of 5e-11 in each coordinate (within tolerance): equal, same hash code
        Point3D near = new Point3D(1 + 5e-11, 2 - 5e-11, 3 + 5e-11);
        assertEquals(p, near, "TC11: points within the tolerance must be equal");
        assertEquals(p.hashCode(), near.hashCode(), "TC11: equal points must have the same hash code");
        // TC12: difference of 2e-10 in one coordinate (beyond tolerance): not equal
        assertNotEquals(p, new Point3D(1 + 2e-10, 2, 3), "TC12: x beyond the tolerance must differ");
        assertNotEquals(p, new Point3D(1, 2 - 2e-10, 3), "TC12: y beyond the tolerance must differ");
        assertNotEquals(p, new Point3D(1, 2, 3 + 2e-10), "TC12: z beyond the tolerance must differ");
        // TC13: the origin and a point within the tolerance of it: equal
        Point3D tiny = new Point3D(1e-11, -1e-11, 0);
        assertEquals(Point3D.ZERO, tiny, "TC13: a point within the tolerance of the origin must equal ZERO");
        assertEquals(Point3D.ZERO.hashCode(), tiny.hashCode(), "TC13: equal points must have the same hash code");
    }

    /** Test method for {@link primitives.Point3D#toString()}. */
    @Test
    void testToString() {
        // ===== Equivalence Partitions Tests =====
        // TC01: (1, -2.5, 3) prints as "(1.0, -2.5, 3.0)"
        assertEquals("(1.0, -2.5, 3.0)", new Point3D(1, -2.5, 3).toString(), "TC01: wrong toString");

        // ===== Boundary Values Tests =====
        // TC10: ZERO prints as "(0.0, 0.0, 0.0)"
        assertEquals("(0.0, 0.0, 0.0)", Point3D.ZERO.toString(), "TC10: wrong toString");
    }
}
