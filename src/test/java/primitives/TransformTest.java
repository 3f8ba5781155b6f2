package primitives;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link primitives.Transform}.
 */
class TransformTest {
    /** Tolerance for comparing doubles. */
    private static final double DELTA = 1e-10;

    private static final Point3D P = new Point3D(1, 2, 3);

    /** Asserts a point's coordinates within the tolerance. */
    private static void assertPoint(double x, double y, double z, Point3D p, String tc) {
        assertEquals(x, p.getX(), DELTA, tc + ": x");
        assertEquals(y, p.getY(), DELTA, tc + ": y");
        assertEquals(z, p.getZ(), DELTA, tc + ": z");
    }

    /** Asserts a vector's components within the tolerance. */
    private static void assertVector(double x, double y, double z, Vector v, String tc) {
        assertEquals(x, v.getX(), DELTA, tc + ": x");
        assertEquals(y, v.getY(), DELTA, tc + ": y");
        assertEquals(z, v.getZ(), DELTA, tc + ": z");
    }

    /** Asserts that two transforms move a few points to the same places. */
    private static void assertSameMap(Transform expected, Transform actual, String tc) {
        Random random = new Random(7);
        for (int i = 0; i < 20; i++) {
            Point3D p = new Point3D(random.nextGaussian() * 10, random.nextGaussian() * 10, random.nextGaussian() * 10);
            Point3D e = expected.apply(p);
            assertPoint(e.getX(), e.getY(), e.getZ(), actual.apply(p), tc);
        }
    }

    /** A transform with every kind of part: scale, turn about a slanted axis, move. */
    private static Transform mixed() {
        return Transform.scale(2, 0.5, 3).then(Transform.rotate(new Vector(1, 1, 0), 37))
                .then(Transform.translate(new Vector(4, -5, 6)));
    }

    /** Test method for {@link Transform#IDENTITY}. */
    @Test
    void testIdentity() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the identity leaves a point where it is (1, 2, 3)
        assertPoint(1, 2, 3, Transform.IDENTITY.apply(P), "TC01");
        // TC02: and a vector as it is (1, 2, 3)
        assertVector(1, 2, 3, Transform.IDENTITY.applyToVector(new Vector(1, 2, 3)), "TC02");
    }

    /** Test method for {@link Transform#translate(Vector)}. */
    @Test
    void testTranslate() {
        Transform t = Transform.translate(new Vector(1, -1, 2));
        // ===== Equivalence Partitions Tests =====
        // TC01: a point moves by the offset (2, 1, 5)
        assertPoint(2, 1, 5, t.apply(P), "TC01");
        // TC02: a direction does not move (1, 2, 3)
        assertVector(1, 2, 3, t.applyToVector(new Vector(1, 2, 3)), "TC02");
        // ===== Boundary Values Tests =====
        // TC11: a null offset is refused, the message names the translation
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Transform.translate(null), "TC11"),
                "translation", "TC11");
    }

    /** Test method for {@link Transform#scale(double)} and {@link Transform#scale(double, double, double)}. */
    @Test
    void testScale() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a uniform scale multiplies every coordinate (2, 4, 6)
        assertPoint(2, 4, 6, Transform.scale(2).apply(P), "TC01");
        // TC02: a scale per axis (3, 1, -3)
        assertPoint(3, 1, -3, Transform.scale(3, 0.5, -1).apply(P), "TC02");
        // TC03: NaN is refused, naming "finite"
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Transform.scale(Double.NaN), "TC03"),
                "finite", "TC03");
        // ===== Boundary Values Tests =====
        // TC11: a zero factor is refused, naming the axis
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Transform.scale(1, 0, 1), "TC11"),
                "along y", "TC11");
        // TC12: a factor so small that space is flattened is refused as singular
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Transform.scale(1e-13, 1, 1), "TC12"),
                "singular", "TC12");
    }

    /** Test method for {@link Transform#rotate(Vector, double)} and the axis rotations. */
    @Test
    void testRotate() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a quarter turn about z takes x to y, exactly (0, 1, 0)
        Point3D p = Transform.rotateZ(90).apply(new Point3D(1, 0, 0));
        assertEquals(new Point3D(0, 1, 0), p, "TC01: not exact");
        // TC02: a quarter turn about x takes y to z (0, 0, 1)
        assertPoint(0, 0, 1, Transform.rotateX(90).apply(new Point3D(0, 1, 0)), "TC02");
        // TC03: a quarter turn about y takes z to x (1, 0, 0)
        assertPoint(1, 0, 0, Transform.rotateY(90).apply(new Point3D(0, 0, 1)), "TC03");
        // TC04: a third of a turn about (1, 1, 1) takes x to y to z (the axis need not be unit)
        Transform third = Transform.rotate(new Vector(2, 2, 2), 120);
        assertPoint(0, 1, 0, third.apply(new Point3D(1, 0, 0)), "TC04");
        assertPoint(0, 0, 1, third.apply(new Point3D(0, 1, 0)), "TC04");
        // TC05: 30° about y, against cos and sin (cos 30, 0, -sin 30)
        assertPoint(Math.sqrt(3) / 2, 0, -0.5, Transform.rotateY(30).apply(new Point3D(1, 0, 0)), "TC05");
        // TC06: four quarter turns are the identity
        Transform quarter = Transform.rotate(new Vector(1, 2, 3), 90);
        assertSameMap(Transform.IDENTITY, quarter.then(quarter).then(quarter).then(quarter), "TC06");
        // TC07: a rotation keeps lengths (|p| = sqrt 14)
        assertEquals(Math.sqrt(14), new Vector(third.apply(P)).length(), DELTA, "TC07");
        // ===== Boundary Values Tests =====
        // TC11: a zero angle is the identity
        assertSameMap(Transform.IDENTITY, Transform.rotateX(0), "TC11");
        // TC12: -90 is 270, and 450 is 90
        assertSameMap(Transform.rotateZ(270), Transform.rotateZ(-90), "TC12");
        assertSameMap(Transform.rotateZ(90), Transform.rotateZ(450), "TC12");
        // TC13: a NaN or infinite angle is refused, naming the angle
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Transform.rotateY(Double.NaN), "TC13"),
                "rotation angle", "TC13");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> Transform.rotateY(Double.POSITIVE_INFINITY), "TC13"), "rotation angle", "TC13");
        // TC14: a null axis is refused; a zero axis cannot be built
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Transform.rotate(null, 10), "TC14"),
                "rotation axis", "TC14");
        assertThrows(IllegalArgumentException.class, () -> Transform.rotate(new Vector(0, 0, 0), 10), "TC14");
    }

    /** Test method for {@link Transform#then(Transform)}. */
    @Test
    void testThen() {
        // ===== Equivalence Partitions Tests =====
        // TC01: scale then move differs from move then scale: (3, 5, 7) and (4, 6, 8)
        Transform scale = Transform.scale(2);
        Transform move = Transform.translate(new Vector(1, 1, 1));
        assertPoint(3, 5, 7, scale.then(move).apply(P), "TC01");
        assertPoint(4, 6, 8, move.then(scale).apply(P), "TC01");
        // TC02: a composition is associative
        Transform turn = Transform.rotateX(33);
        assertSameMap(scale.then(turn).then(move), scale.then(turn.then(move)), "TC02");
        // TC03: then applies the first, then the next, point by point
        Transform m = mixed();
        Point3D expected = move.apply(m.apply(P));
        Point3D actual = m.then(move).apply(P);
        assertPoint(expected.getX(), expected.getY(), expected.getZ(), actual, "TC03");
        // ===== Boundary Values Tests =====
        // TC11: the identity on either side changes nothing
        assertSameMap(m, Transform.IDENTITY.then(m), "TC11");
        assertSameMap(m, m.then(Transform.IDENTITY), "TC11");
        // TC12: null is refused
        assertMessage(assertThrows(IllegalArgumentException.class, () -> m.then(null), "TC12"), "next", "TC12");
        // TC13: two scales that together flatten space are refused as singular
        Transform thin = Transform.scale(1e-7, 1, 1);
        assertMessage(assertThrows(IllegalArgumentException.class, () -> thin.then(thin), "TC13"), "singular",
                "TC13");
    }

    /** Test method for {@link Transform#inverse()}. */
    @Test
    void testInverse() {
        Transform m = mixed();
        // ===== Equivalence Partitions Tests =====
        // TC01: the inverse takes a moved point back (1, 2, 3)
        assertPoint(1, 2, 3, m.inverse().apply(m.apply(P)), "TC01");
        // TC02: a transform then its inverse is the identity, both ways
        assertSameMap(Transform.IDENTITY, m.then(m.inverse()), "TC02");
        assertSameMap(Transform.IDENTITY, m.inverse().then(m), "TC02");
        // TC03: the inverse of a composition is the inverses in the other order
        Transform move = Transform.translate(new Vector(0, 3, 0));
        assertSameMap(move.inverse().then(m.inverse()), m.then(move).inverse(), "TC03");
        // ===== Boundary Values Tests =====
        // TC11: the inverse of the inverse is the transform itself, equal number by number
        assertEquals(m, m.inverse().inverse(), "TC11");
        // TC12: the identity is its own inverse
        assertSameMap(Transform.IDENTITY, Transform.IDENTITY.inverse(), "TC12");
    }

    /** Test method for {@link Transform#applyToNormal(Vector)}. */
    @Test
    void testApplyToNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a plane x + y = 0 stretched by 2 along x: its normal becomes (1, 2, 0) / sqrt 5, not (2, 1, 0)
        Vector n = Transform.scale(2, 1, 1).applyToNormal(new Vector(1, 1, 0));
        assertVector(1 / Math.sqrt(5), 2 / Math.sqrt(5), 0, n, "TC01");
        // TC02: under any transform the normal stays perpendicular to the surface's transformed tangents
        Transform m = mixed();
        Vector normal = new Vector(1, -2, 0.5);
        Vector tangent1 = normal.orthogonal();
        Vector tangent2 = normal.crossProduct(tangent1);
        Vector transformed = m.applyToNormal(normal);
        assertEquals(0, transformed.dotProduct(m.applyToVector(tangent1)), DELTA, "TC02");
        assertEquals(0, transformed.dotProduct(m.applyToVector(tangent2)), DELTA, "TC02");
        // TC03: the transformed normal is unit (1)
        assertEquals(1, transformed.length(), DELTA, "TC03");
        // ===== Boundary Values Tests =====
        // TC11: a translation leaves a normal as it is (0, 0, 1)
        assertVector(0, 0, 1, Transform.translate(new Vector(5, 5, 5)).applyToNormal(new Vector(0, 0, 1)), "TC11");
        // TC12: a mirror turns the normal with the surface (-1, 0, 0)
        assertVector(-1, 0, 0, Transform.scale(-1, 1, 1).applyToNormal(new Vector(1, 0, 0)), "TC12");
    }

    /** Test method for {@link Transform#applyToVector(Vector)} and {@link Transform#apply(Point3D)}. */
    @Test
    void testApply() {
        Transform m = mixed();
        // ===== Equivalence Partitions Tests =====
        // TC01: a vector transforms as the difference of two transformed points
        Point3D q = new Point3D(-2, 0.5, 4);
        Vector expected = m.apply(q).subtract(m.apply(P));
        Vector actual = m.applyToVector(q.subtract(P));
        assertVector(expected.getX(), expected.getY(), expected.getZ(), actual, "TC01");
        // ===== Boundary Values Tests =====
        // TC11: null point, vector and normal are refused
        assertThrows(IllegalArgumentException.class, () -> m.apply(null), "TC11");
        assertThrows(IllegalArgumentException.class, () -> m.applyToVector(null), "TC11");
        assertThrows(IllegalArgumentException.class, () -> m.applyToNormal(null), "TC11");
    }

    /** Test method for {@link Transform#toArray()}. */
    @Test
    void testToArray() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the numbers are row-major 3 × 4 (a scale of 2 and a move by (1, 2, 3))
        Transform t = Transform.scale(2).then(Transform.translate(new Vector(1, 2, 3)));
        double[] a = t.toArray();
        assertArrayEquals(new double[] { 2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 3 }, a, DELTA, "TC01");
        // ===== Boundary Values Tests =====
        // TC11: the array is a copy: changing it changes no transform
        a[3] = 100;
        assertPoint(1, 2, 3, t.apply(Point3D.ZERO), "TC11");
        assertEquals(Transform.IDENTITY, Transform.scale(1), "TC11: equal matrices, equal transforms");
    }
}
