package primitives;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link primitives.Vector}.
 */
class VectorTest {
    /** Tolerance for comparing doubles. */
    private static final double DELTA = 1e-10;

    /** Asserts a vector's exact components, to prove that an operation left it untouched. */
    private static void assertComponents(double x, double y, double z, Vector v, String message) {
        assertEquals(x, v.getX(), 0, message);
        assertEquals(y, v.getY(), 0, message);
        assertEquals(z, v.getZ(), 0, message);
    }

    /** Test method for {@link primitives.Vector#Vector(double, double, double)}. */
    @Test
    void testConstructorComponents() {
        // ===== Equivalence Partitions Tests =====
        // TC01: ordinary components are kept (1, -2, 3.5)
        Vector v = new Vector(1, -2, 3.5);
        assertComponents(1, -2, 3.5, v, "TC01: wrong components");
        // TC02: NaN component is rejected, the message names "finite"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Vector(Double.NaN, 1, 1), "TC02: NaN x must be rejected");
        assertMessage(e, "finite", "TC02");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Vector(1, Double.NaN, 1), "TC02: NaN y must be rejected");
        assertMessage(e, "finite", "TC02");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Vector(1, 1, Double.NaN), "TC02: NaN z must be rejected");
        assertMessage(e, "finite", "TC02");
        // TC03: infinite component is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Vector(Double.POSITIVE_INFINITY, 0, 0), "TC03: +inf x must be rejected");
        assertMessage(e, "finite", "TC03");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Vector(0, 0, Double.NEGATIVE_INFINITY), "TC03: -inf z must be rejected");
        assertMessage(e, "finite", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: the zero vector is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Vector(0, 0, 0),
                "TC10: zero vector must be rejected");
        assertMessage(e, "zero vector", "TC10");
        // TC11: a tiny vector is not zero: only exactly zero is refused (5e-11, -5e-11, 0) and (0, 1e-200, 0)
        assertComponents(5e-11, -5e-11, 0, new Vector(5e-11, -5e-11, 0), "TC11: a tiny vector must be accepted");
        assertComponents(0, 1e-200, 0, new Vector(0, 1e-200, 0), "TC11: a tiny vector must be accepted");
        // TC12: a single non-zero component is enough (0, 0, 1e-9)
        assertComponents(0, 0, 1e-9, new Vector(0, 0, 1e-9), "TC12: wrong components");
    }

    /** Test method for {@link primitives.Vector#Vector(primitives.Point3D)}. */
    @Test
    void testConstructorPoint() {
        // ===== Equivalence Partitions Tests =====
        // TC01: head (1,2,3) gives vector (1,2,3)
        Vector v = new Vector(new Point3D(1, 2, 3));
        assertComponents(1, 2, 3, v, "TC01: wrong components");
        assertEquals(new Point3D(1, 2, 3), v.getHead(), "TC01: wrong head");
        // TC02: null head is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Vector((Point3D) null), "TC02: null head must be rejected");
        assertMessage(e, "null", "TC02");

        // ===== Boundary Values Tests =====
        // TC10: the origin as head is the zero vector and is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new Vector(Point3D.ZERO),
                "TC10: head at the origin must be rejected");
        assertMessage(e, "zero vector", "TC10");
    }

    /** Test method for {@link primitives.Vector#add(primitives.Vector)}. */
    @Test
    void testAdd() {
        Vector v1 = new Vector(1, 2, 3);
        Vector v2 = new Vector(-2, -4, -6);
        // ===== Equivalence Partitions Tests =====
        // TC01: (1,2,3) + (-2,-4,-6) = (-1,-2,-3)
        assertEquals(new Vector(-1, -2, -3), v1.add(v2), "TC01: wrong sum");
        // TC02: (1,2,3) + (0,3,-2) = (1,5,1)
        assertEquals(new Vector(1, 5, 1), v1.add(new Vector(0, 3, -2)), "TC02: wrong sum");
        // TC03: the operands are unchanged and the result is a new object
        Vector sum = v1.add(v2);
        assertNotSame(v1, sum, "TC03: add must return a new vector");
        assertNotSame(v2, sum, "TC03: add must return a new vector");
        assertComponents(1, 2, 3, v1, "TC03: add changed its vector");
        assertComponents(-2, -4, -6, v2, "TC03: add changed its argument");
        // TC04: null is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> v1.add(null),
                "TC04: null must be rejected");
        assertMessage(e, "null", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: v + (-v) is the zero vector and is rejected
        e = assertThrows(IllegalArgumentException.class, () -> v1.add(v1.scale(-1)),
                "TC10: v + (-v) must be rejected");
        assertMessage(e, "zero vector", "TC10");
        // TC11: v + v = 2v (2,4,6)
        assertEquals(new Vector(2, 4, 6), v1.add(v1), "TC11: wrong sum v + v");
    }

    /** Test method for {@link primitives.Vector#subtract(primitives.Vector)}. */
    @Test
    void testSubtract() {
        Vector v1 = new Vector(1, 2, 3);
        Vector v2 = new Vector(-2, -4, -6);
        // ===== Equivalence Partitions Tests =====
        // TC01: (1,2,3) - (-2,-4,-6) = (3,6,9)
        assertEquals(new Vector(3, 6, 9), v1.subtract(v2), "TC01: wrong difference");
        // TC02: (-2,-4,-6) - (1,2,3) = (-3,-6,-9)
        assertEquals(new Vector(-3, -6, -9), v2.subtract(v1), "TC02: wrong difference");
        // TC03: the operands are unchanged
        v1.subtract(v2);
        assertComponents(1, 2, 3, v1, "TC03: subtract changed its vector");
        assertComponents(-2, -4, -6, v2, "TC03: subtract changed its argument");
        // TC04: null is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> v1.subtract(null),
                "TC04: null must be rejected");
        assertMessage(e, "null", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: v - v is the zero vector and is rejected
        e = assertThrows(IllegalArgumentException.class, () -> v1.subtract(v1),
                "TC10: v - v must be rejected");
        assertMessage(e, "zero vector", "TC10");
        // TC11: v - (equal vector) is rejected too
        e = assertThrows(IllegalArgumentException.class, () -> v1.subtract(new Vector(1, 2, 3)),
                "TC11: v - equal vector must be rejected");
        assertMessage(e, "zero vector", "TC11");
    }

    /** Test method for {@link primitives.Vector#scale(double)}. */
    @Test
    void testScale() {
        Vector v = new Vector(1, -2, 3);
        // ===== Equivalence Partitions Tests =====
        // TC01: positive factor 2: (2,-4,6)
        assertEquals(new Vector(2, -4, 6), v.scale(2), "TC01: wrong scaled vector");
        // TC02: negative factor -0.5: (-0.5,1,-1.5)
        assertEquals(new Vector(-0.5, 1, -1.5), v.scale(-0.5), "TC02: wrong scaled vector");
        // TC03: the operand is unchanged and the result is a new object
        Vector s = v.scale(3);
        assertNotSame(v, s, "TC03: scale must return a new vector");
        assertComponents(1, -2, 3, v, "TC03: scale changed its vector");
        // TC04: NaN factor is rejected
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> v.scale(Double.NaN),
                "TC04: NaN factor must be rejected");
        assertMessage(e, "finite", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: factor 0 gives the zero vector and is rejected
        e = assertThrows(IllegalArgumentException.class, () -> v.scale(0), "TC10: scale(0) must be rejected");
        assertMessage(e, "zero vector", "TC10");
        // TC11: factor 1 gives an equal vector (1,-2,3) that is still a new object
        Vector one = v.scale(1);
        assertEquals(new Vector(1, -2, 3), one, "TC11: scale(1) must give an equal vector");
        assertNotSame(v, one, "TC11: scale(1) must return a new vector");
        // TC12: factor -1 gives the opposite vector (-1,2,-3)
        assertEquals(new Vector(-1, 2, -3), v.scale(-1), "TC12: scale(-1) must give the opposite vector");
    }

    /** Test method for {@link primitives.Vector#dotProduct(primitives.Vector)}. */
    @Test
    void testDotProduct() {
        Vector v1 = new Vector(1, 2, 3);
        Vector v2 = new Vector(-2, -4, -6);
        Vector v3 = new Vector(0, 3, -2);
        // ===== Equivalence Partitions Tests =====
        // TC01: acute angle: (1,2,3)·(1,1,1) = 6
        assertEquals(6, v1.dotProduct(new Vector(1, 1, 1)), DELTA, "TC01: wrong dot product");
        // TC02: obtuse angle (opposite): (1,2,3)·(-2,-4,-6) = -28
        assertEquals(-28, v1.dotProduct(v2), DELTA, "TC02: wrong dot product");
        // TC03: symmetric: (-2,-4,-6)·(1,2,3) = -28
        assertEquals(-28, v2.dotProduct(v1), DELTA, "TC03: wrong dot product");
        // TC04: null is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> v1.dotProduct(null),
                "TC04: null must be rejected");
        assertMessage(e, "null", "TC04");

        // ===== Boundary Values Tests =====
        // TC10: orthogonal vectors: (1,2,3)·(0,3,-2) = 0
        assertEquals(0, v1.dotProduct(v3), DELTA, "TC10: orthogonal vectors must give 0");
        // TC11: the unit axes are orthogonal: 0
        assertEquals(0, new Vector(1, 0, 0).dotProduct(new Vector(0, 0, 1)), DELTA, "TC11: axes must give 0");
        // TC12: a vector with itself: its squared length 14
        assertEquals(14, v1.dotProduct(v1), DELTA, "TC12: v·v must be |v|^2");
        // TC13: operands unchanged
        assertComponents(1, 2, 3, v1, "TC13: dotProduct changed its vector");
        assertComponents(0, 3, -2, v3, "TC13: dotProduct changed its argument");
    }

    /** Test method for {@link primitives.Vector#crossProduct(primitives.Vector)}. */
    @Test
    void testCrossProduct() {
        Vector v1 = new Vector(1, 2, 3);
        Vector v3 = new Vector(0, 3, -2);
        // ===== Equivalence Partitions Tests =====
        // TC01: orthogonal vectors (1,2,3)×(0,3,-2) = (-13,2,3), length |v1||v3| = sqrt(182)
        Vector vr = v1.crossProduct(v3);
        assertEquals(new Vector(-13, 2, 3), vr, "TC01: wrong cross product");
        assertEquals(v1.length() * v3.length(), vr.length(), DELTA, "TC01: wrong cross product length");
        assertEquals(Math.sqrt(182), vr.length(), DELTA, "TC01: wrong cross product length");
        assertEquals(0, vr.dotProduct(v1), DELTA, "TC01: cross product is not orthogonal to the 1st operand");
        assertEquals(0, vr.dotProduct(v3), DELTA, "TC01: cross product is not orthogonal to the 2nd operand");
        // TC02: 45° angle: (1,0,0)×(1,1,0) = (0,0,1), length 1·sqrt(2)·sin45° = 1
        Vector a = new Vector(1, 0, 0);
        Vector b = new Vector(1, 1, 0);
        Vector ab = a.crossProduct(b);
        assertEquals(new Vector(0, 0, 1), ab, "TC02: wrong cross product");
        assertEquals(a.length() * b.length() * Math.sin(Math.PI / 4), ab.length(), DELTA,
                "TC02: wrong cross product length");
        // TC03: obtuse angle 135°: (1,0,0)×(-1,2,0) = (0,0,2); |a||b|sinθ = 1·sqrt(5)·(2/sqrt(5)) = 2;
        // orthogonal to both
        Vector c = new Vector(-1, 2, 0);
        Vector ac = a.crossProduct(c);
        assertEquals(new Vector(0, 0, 2), ac, "TC03: wrong cross product");
        double cos = a.dotProduct(c) / (a.length() * c.length());
        double sin = Math.sqrt(1 - cos * cos);
        assertEquals(a.length() * c.length() * sin, ac.length(), DELTA, "TC03: wrong cross product length");
        assertEquals(0, ac.dotProduct(a), DELTA, "TC03: cross product is not orthogonal to the 1st operand");
        assertEquals(0, ac.dotProduct(c), DELTA, "TC03: cross product is not orthogonal to the 2nd operand");
        // TC04: anti-commutative: (0,3,-2)×(1,2,3) = (13,-2,-3)
        assertEquals(new Vector(13, -2, -3), v3.crossProduct(v1), "TC04: wrong reversed cross product");
        // TC05: right-handed axes: x × y = z
        assertEquals(new Vector(0, 0, 1), new Vector(1, 0, 0).crossProduct(new Vector(0, 1, 0)),
                "TC05: x × y must be z");
        // TC06: the operands are unchanged
        assertComponents(1, 2, 3, v1, "TC06: crossProduct changed its vector");
        assertComponents(0, 3, -2, v3, "TC06: crossProduct changed its argument");
        // TC07: null is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> v1.crossProduct(null),
                "TC07: null must be rejected");
        assertMessage(e, "null", "TC07");

        // ===== Boundary Values Tests =====
        // TC10: parallel vectors (same direction) are rejected
        e = assertThrows(IllegalArgumentException.class, () -> v1.crossProduct(new Vector(2, 4, 6)),
                "TC10: cross product of parallel vectors must be rejected");
        assertMessage(e, "parallel", "TC10");
        // TC11: anti-parallel vectors are rejected
        e = assertThrows(IllegalArgumentException.class, () -> v1.crossProduct(new Vector(-2, -4, -6)),
                "TC11: cross product of anti-parallel vectors must be rejected");
        assertMessage(e, "parallel", "TC11");
        // TC12: a vector with itself is rejected
        e = assertThrows(IllegalArgumentException.class, () -> v1.crossProduct(v1),
                "TC12: cross product of a vector with itself must be rejected");
        assertMessage(e, "parallel", "TC12");
        // TC13: parallel unit vectors along an axis are rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> new Vector(0, 0, 1).crossProduct(new Vector(0, 0, -3)),
                "TC13: cross product of anti-parallel axis vectors must be rejected");
        assertMessage(e, "parallel", "TC13");
        // TC14: short vectors at a right angle are not parallel, whatever their length: (1e-9,0,0)×(0,1e-9,0)
        assertComponents(0, 0, 1e-18, new Vector(1e-9, 0, 0).crossProduct(new Vector(0, 1e-9, 0)),
                "TC14: wrong cross product of short vectors");
        assertEquals(1e-18, new Vector(1e-9, 0, 0).crossProduct(new Vector(0, 1e-9, 0)).getZ(), 1e-30,
                "TC14: wrong cross product of short vectors");
        // TC15: long parallel vectors (1e200·(1,2,3) and 2e200·(1,2,3)) are rejected as parallel
        e = assertThrows(IllegalArgumentException.class,
                () -> new Vector(1e200, 2e200, 3e200).crossProduct(new Vector(2e200, 4e200, 6e200)),
                "TC15: cross product of long parallel vectors must be rejected");
        assertMessage(e, "parallel", "TC15");
    }

    /** Test method for {@link primitives.Vector#lengthSquared()}. */
    @Test
    void testLengthSquared() {
        // ===== Equivalence Partitions Tests =====
        // TC01: (1,2,3): 14
        assertEquals(14, new Vector(1, 2, 3).lengthSquared(), DELTA, "TC01: wrong squared length");
        // TC02: negative components (-1,-2,-3): 14
        assertEquals(14, new Vector(-1, -2, -3).lengthSquared(), DELTA, "TC02: wrong squared length");

        // ===== Boundary Values Tests =====
        // TC10: unit axis vector: 1
        assertEquals(1, new Vector(0, -1, 0).lengthSquared(), DELTA, "TC10: wrong squared length");
    }

    /** Test method for {@link primitives.Vector#length()}. */
    @Test
    void testLength() {
        // ===== Equivalence Partitions Tests =====
        // TC01: (0,3,4): 5
        assertEquals(5, new Vector(0, 3, 4).length(), DELTA, "TC01: wrong length");
        // TC02: (1,2,3): sqrt(14)
        assertEquals(Math.sqrt(14), new Vector(1, 2, 3).length(), DELTA, "TC02: wrong length");
        // TC03: (-2,-3,6): 7
        assertEquals(7, new Vector(-2, -3, 6).length(), DELTA, "TC03: wrong length");

        // ===== Boundary Values Tests =====
        // TC10: unit axis vector: 1
        assertEquals(1, new Vector(0, 0, -1).length(), DELTA, "TC10: wrong length");
    }

    /** Test method for {@link primitives.Vector#normalize()}. */
    @Test
    void testNormalize() {
        // ===== Equivalence Partitions Tests =====
        // TC01: (0,3,4) becomes (0,0.6,0.8) in place and the same object is returned
        Vector v = new Vector(0, 3, 4);
        Vector u = v.normalize();
        assertSame(v, u, "TC01: normalize must return the vector itself");
        assertEquals(1, v.length(), DELTA, "TC01: normalize did not make the vector unit");
        assertEquals(new Vector(0, 0.6, 0.8), v, "TC01: normalize changed the direction");
        // TC02: (1,2,3) becomes (1,2,3)/sqrt(14), same direction
        Vector w = new Vector(1, 2, 3);
        w.normalize();
        double s = Math.sqrt(14);
        assertEquals(new Vector(1 / s, 2 / s, 3 / s), w, "TC02: wrong normalised vector");
        assertEquals(1, w.length(), DELTA, "TC02: normalised vector is not unit");

        // ===== Boundary Values Tests =====
        // TC10: an already unit vector stays (0,-1,0)
        Vector unit = new Vector(0, -1, 0);
        assertSame(unit, unit.normalize(), "TC10: normalize must return the vector itself");
        assertComponents(0, -1, 0, unit, "TC10: a unit vector must not change");
        // TC11: a very long vector (1e200, 1e200, 0), whose square overflows, becomes (√½, √½, 0), not zero
        double half = Math.sqrt(0.5);
        assertEquals(new Vector(half, half, 0), new Vector(1e200, 1e200, 0).normalize(), "TC11: wrong long unit vector");
        // TC12: a very short vector (0, 1e-200, 0), whose square vanishes, becomes (0, 1, 0)
        assertComponents(0, 1, 0, new Vector(0, 1e-200, 0).normalize(), "TC12: wrong short unit vector");
        // TC13: the smallest double (Double.MIN_VALUE, 0, -Double.MIN_VALUE) becomes (√½, 0, -√½)
        assertEquals(new Vector(half, 0, -half), new Vector(Double.MIN_VALUE, 0, -Double.MIN_VALUE).normalize(),
                "TC13: wrong unit vector of the smallest components");
    }

    /** Test method for {@link primitives.Vector#normalized()}. */
    @Test
    void testNormalized() {
        // ===== Equivalence Partitions Tests =====
        // TC01: (0,3,4).normalized() is a new vector (0,0.6,0.8); the original stays (0,3,4)
        Vector v = new Vector(0, 3, 4);
        Vector u = v.normalized();
        assertNotSame(v, u, "TC01: normalized must return a new vector");
        assertEquals(new Vector(0, 0.6, 0.8), u, "TC01: wrong normalised vector");
        assertEquals(1, u.length(), DELTA, "TC01: normalised vector is not unit");
        assertComponents(0, 3, 4, v, "TC01: normalized changed the original vector");
        // TC02: same direction as the original: the cross product is rejected as parallel, the dot
        // product is positive (5)
        assertThrows(IllegalArgumentException.class, () -> v.crossProduct(u),
                "TC02: normalised vector is not parallel to the original");
        assertEquals(5, v.dotProduct(u), DELTA, "TC02: normalised vector is not in the same direction");

        // ===== Boundary Values Tests =====
        // TC10: a unit vector gives an equal, new unit vector (1,0,0)
        Vector unit = new Vector(1, 0, 0);
        Vector n = unit.normalized();
        assertNotSame(unit, n, "TC10: normalized must return a new vector");
        assertEquals(new Vector(1, 0, 0), n, "TC10: wrong normalised vector");
        // TC11: a very long vector (3e100,0,4e100) gives (0.6,0,0.8)
        assertEquals(new Vector(0.6, 0, 0.8), new Vector(3e100, 0, 4e100).normalized(),
                "TC11: wrong normalised long vector");
    }

    /** Test method for {@link primitives.Vector#equals(Object)} and {@link primitives.Vector#hashCode()}. */
    @Test
    void testEqualsAndHashCode() {
        Vector v = new Vector(1, 2, 3);
        // ===== Equivalence Partitions Tests =====
        // TC01: same components: equal, same hash code
        assertEquals(new Vector(1, 2, 3), v, "TC01: vectors with the same components must be equal");
        assertEquals(new Vector(1, 2, 3).hashCode(), v.hashCode(), "TC01: equal vectors must have the same hash");
        // TC02: different components: not equal
        assertNotEquals(new Vector(1, 2, 4), v, "TC02: different vectors must not be equal");
        // TC03: a point with the same coordinates is not equal; nor is null
        assertNotEquals(new Point3D(1, 2, 3), v, "TC03: a vector is not equal to a point");
        assertFalse(v.equals(null), "TC03: a vector is not equal to null");

        // ===== Boundary Values Tests =====
        // TC10: within the tolerance (5e-11): equal, same hash code
        Vector near = new Vector(1 + 5e-11, 2, 3 - 5e-11);
        assertEquals(v, near, "TC10: vectors within the tolerance must be equal");
        assertEquals(v.hashCode(), near.hashCode(), "TC10: equal vectors must have the same hash");
        // TC11: beyond the tolerance (2e-10): not equal
        assertNotEquals(v, new Vector(1, 2 + 2e-10, 3), "TC11: vectors beyond the tolerance must differ");
    }

    /**
     * Asserts that u is a unit vector orthogonal to v; the dot product is taken with v scaled by its
     * largest component, so the check does not depend on v's length (and cannot overflow).
     */
    private static void assertUnitOrthogonal(Vector v, Vector u, String tc) {
        assertNotNull(u, tc + ": orthogonal() must not return null");
        assertEquals(1, u.length(), DELTA, tc + ": orthogonal vector must be unit (length 1)");
        double m = Math.max(Math.abs(v.getX()), Math.max(Math.abs(v.getY()), Math.abs(v.getZ())));
        double dot = u.getX() * (v.getX() / m) + u.getY() * (v.getY() / m) + u.getZ() * (v.getZ() / m);
        assertEquals(0, dot, DELTA, tc + ": orthogonal vector must be orthogonal (dot product 0) to " + v);
    }

    /** Test method for {@link primitives.Vector#orthogonal()} on vectors along the coordinate axes. */
    @Test
    void testOrthogonalAxes() {
        // ===== Boundary Values Tests =====
        // TC10: along +x, +y, +z (1 on one axis, 0 on the others): a unit vector with dot product 0
        Vector[] axes = { new Vector(1, 0, 0), new Vector(0, 1, 0), new Vector(0, 0, 1) };
        for (Vector axis : axes)
            assertUnitOrthogonal(axis, axis.orthogonal(), "TC10");
        // TC11: along -x, -y, -z: a unit vector with dot product 0
        Vector[] negativeAxes = { new Vector(-1, 0, 0), new Vector(0, -1, 0), new Vector(0, 0, -1) };
        for (Vector axis : negativeAxes)
            assertUnitOrthogonal(axis, axis.orthogonal(), "TC11");
        // TC12: long along an axis (0, 0, 250): a unit vector with dot product 0
        assertUnitOrthogonal(new Vector(0, 0, 250), new Vector(0, 0, 250).orthogonal(), "TC12");
        // TC13: in a coordinate plane, on the diagonal (1, 1, 0) and (0, -2, 2): unit, dot product 0
        assertUnitOrthogonal(new Vector(1, 1, 0), new Vector(1, 1, 0).orthogonal(), "TC13");
        assertUnitOrthogonal(new Vector(0, -2, 2), new Vector(0, -2, 2).orthogonal(), "TC13");
    }

    /** Test method for {@link primitives.Vector#orthogonal()} on general vectors. */
    @Test
    void testOrthogonalGeneral() {
        // ===== Equivalence Partitions Tests =====
        // TC01: (1, 2, 3): a unit vector with dot product 0
        assertUnitOrthogonal(new Vector(1, 2, 3), new Vector(1, 2, 3).orthogonal(), "TC01");
        // TC02: negative components (-3, -4, 5) and (2, -7, -1): unit, dot product 0
        assertUnitOrthogonal(new Vector(-3, -4, 5), new Vector(-3, -4, 5).orthogonal(), "TC02");
        assertUnitOrthogonal(new Vector(2, -7, -1), new Vector(2, -7, -1).orthogonal(), "TC02");
        // TC03: 1000 vectors drawn from Random(42), components in [-10, 10): unit, dot product 0
        java.util.Random random = new java.util.Random(42);
        for (int i = 0; i < 1000; ++i) {
            Vector v = new Vector(random.nextDouble() * 20 - 10, random.nextDouble() * 20 - 10,
                    random.nextDouble() * 20 - 10);
            assertUnitOrthogonal(v, v.orthogonal(), "TC03 (vector " + i + ")");
        }

        // ===== Boundary Values Tests =====
        // TC10: all components equal in magnitude, (1, 1, 1) and (-1, 1, -1) (ties): unit, dot product 0
        assertUnitOrthogonal(new Vector(1, 1, 1), new Vector(1, 1, 1).orthogonal(), "TC10");
        assertUnitOrthogonal(new Vector(-1, 1, -1), new Vector(-1, 1, -1).orthogonal(), "TC10");
        // TC11: almost along an axis, (1, 1e-9, -1e-9): unit, dot product 0
        assertUnitOrthogonal(new Vector(1, 1e-9, -1e-9), new Vector(1, 1e-9, -1e-9).orthogonal(), "TC11");
    }

    /** Test method for {@link primitives.Vector#orthogonal()} on very long and very short vectors. */
    @Test
    void testOrthogonalExtremeLengths() {
        // ===== Boundary Values Tests =====
        // TC10: very long (1e12, -2e12, 3e12): unit, dot product 0
        assertUnitOrthogonal(new Vector(1e12, -2e12, 3e12), new Vector(1e12, -2e12, 3e12).orthogonal(), "TC10");
        // TC11: huge (1e200, 2e200, -3e200), whose squared length overflows a double: still unit, dot product 0
        assertUnitOrthogonal(new Vector(1e200, 2e200, -3e200), new Vector(1e200, 2e200, -3e200).orthogonal(),
                "TC11");
        // TC12: length 1e-6 along an axis, (1e-6, 0, 0): unit, dot product 0
        assertUnitOrthogonal(new Vector(1e-6, 0, 0), new Vector(1e-6, 0, 0).orthogonal(), "TC12");
        // TC13: length 1e-6 off the axes, (0, 6e-7, -8e-7) and (2e-7, -3e-7, 6e-7)·(1/0.7): unit, dot product 0
        assertUnitOrthogonal(new Vector(0, 6e-7, -8e-7), new Vector(0, 6e-7, -8e-7).orthogonal(), "TC13");
        Vector tiny = new Vector(2e-7 / 0.7, -3e-7 / 0.7, 6e-7 / 0.7);
        assertEquals(1e-6, tiny.length(), 1e-16, "TC13: the test vector must have length 1e-6");
        assertUnitOrthogonal(tiny, tiny.orthogonal(), "TC13");
        // TC14: the smallest non-zero components, (1e-10, 1e-10, 1e-10): unit, dot product 0
        assertUnitOrthogonal(new Vector(1e-10, 1e-10, 1e-10), new Vector(1e-10, 1e-10, 1e-10).orthogonal(), "TC14");
    }

    /** Test method for {@link primitives.Vector#orthogonal()}: a new object, the original unchanged, deterministic. */
    @Test
    void testOrthogonalNewAndDeterministic() {
        // ===== Equivalence Partitions Tests =====
        // TC01: (1, 2, 3).orthogonal() is a new object; the original stays (1, 2, 3)
        Vector v = new Vector(1, 2, 3);
        Vector u = v.orthogonal();
        assertNotSame(v, u, "TC01: orthogonal must return a new vector");
        assertComponents(1, 2, 3, v, "TC01: orthogonal changed the original vector");
        // TC02: calling it again on the same vector gives an equal vector, again a new object
        Vector again = v.orthogonal();
        assertEquals(u, again, "TC02: the same vector must give the same orthogonal vector");
        assertNotSame(u, again, "TC02: each call must return a new vector");
        // TC03: an equal vector (another object (1, 2, 3)) gives an equal orthogonal vector
        assertEquals(u, new Vector(1, 2, 3).orthogonal(), "TC03: equal vectors must give equal orthogonal vectors");

        // ===== Boundary Values Tests =====
        // TC10: a unit axis vector (0, 0, -1) stays (0, 0, -1) and twice gives equal results
        Vector axis = new Vector(0, 0, -1);
        Vector a1 = axis.orthogonal();
        assertNotSame(axis, a1, "TC10: orthogonal must return a new vector");
        assertComponents(0, 0, -1, axis, "TC10: orthogonal changed the original vector");
        assertEquals(a1, axis.orthogonal(), "TC10: the same vector must give the same orthogonal vector");
    }
}
