package primitives;

import static org.junit.jupiter.api.Assertions.*;
import static primitives.Util.*;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link primitives.Util}.
 */
class UtilTest {

    /** Test method for {@link primitives.Util#isZero(double)}. */
    @Test
    void testIsZero() {
        // ===== Equivalence Partitions Tests =====
        // TC01: clearly positive number is not zero (false)
        assertFalse(isZero(1), "TC01: 1 is not zero");
        // TC02: clearly negative number is not zero (false)
        assertFalse(isZero(-1), "TC02: -1 is not zero");
        // TC03: a tiny positive number inside the tolerance is zero (true)
        assertTrue(isZero(1e-12), "TC03: 1e-12 is zero");

        // ===== Boundary Values Tests =====
        // TC10: exact zero (true)
        assertTrue(isZero(0), "TC10: 0 is zero");
        // TC11: negative zero (true)
        assertTrue(isZero(-0.0), "TC11: -0.0 is zero");
        // TC12: just inside the tolerance, positive side (true)
        assertTrue(isZero(0.99e-10), "TC12: 0.99e-10 is zero");
        // TC13: just inside the tolerance, negative side (true)
        assertTrue(isZero(-0.99e-10), "TC13: -0.99e-10 is zero");
        // TC14: exactly the tolerance is not zero (strict comparison) (false)
        assertFalse(isZero(1e-10), "TC14: 1e-10 is not zero");
        // TC15: just beyond the tolerance, positive side (false)
        assertFalse(isZero(1.01e-10), "TC15: 1.01e-10 is not zero");
        // TC16: just beyond the tolerance, negative side (false)
        assertFalse(isZero(-1.01e-10), "TC16: -1.01e-10 is not zero");
        // TC17: NaN is not zero (false)
        assertFalse(isZero(Double.NaN), "TC17: NaN is not zero");
    }

    /** Test method for {@link primitives.Util#alignZero(double)}. */
    @Test
    void testAlignZero() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a number beyond the tolerance is kept (5.5)
        assertEquals(5.5, alignZero(5.5), 0, "TC01: wrong aligned value");
        // TC02: a negative number beyond the tolerance is kept (-3.25)
        assertEquals(-3.25, alignZero(-3.25), 0, "TC02: wrong aligned value");
        // TC03: a tiny number inside the tolerance becomes exactly 0.0
        assertEquals(0.0, alignZero(3e-12), 0, "TC03: wrong aligned value");

        // ===== Boundary Values Tests =====
        // TC10: just inside the tolerance becomes exactly 0.0
        assertEquals(0.0, alignZero(-0.99e-10), 0, "TC10: wrong aligned value");
        // TC11: exactly the tolerance is kept (1e-10)
        assertEquals(1e-10, alignZero(1e-10), 0, "TC11: wrong aligned value");
        // TC12: just beyond the tolerance is kept (-1.01e-10)
        assertEquals(-1.01e-10, alignZero(-1.01e-10), 0, "TC12: wrong aligned value");
        // TC13: exact zero stays 0.0
        assertEquals(0.0, alignZero(0), 0, "TC13: wrong aligned value");
    }

    /** Test method for {@link primitives.Util#checkSign(double, double)}. */
    @Test
    void testCheckSign() {
        // ===== Equivalence Partitions Tests =====
        // TC01: both positive (true)
        assertTrue(checkSign(1, 2), "TC01: wrong sign check");
        // TC02: both negative (true)
        assertTrue(checkSign(-1, -0.5), "TC02: wrong sign check");
        // TC03: positive and negative (false)
        assertFalse(checkSign(1, -1), "TC03: wrong sign check");
        // TC04: negative and positive (false)
        assertFalse(checkSign(-2, 3), "TC04: wrong sign check");

        // ===== Boundary Values Tests =====
        // TC10: first is zero (false)
        assertFalse(checkSign(0, 1), "TC10: wrong sign check");
        // TC11: second is zero (false)
        assertFalse(checkSign(-1, 0), "TC11: wrong sign check");
        // TC12: both zero (false)
        assertFalse(checkSign(0, 0), "TC12: wrong sign check");
        // TC13: both tiny positive (true)
        assertTrue(checkSign(1e-300, 1e-300), "TC13: wrong sign check");
    }

    /** Test method for {@link primitives.Util#random(double, double)}. */
    @Test
    void testRandom() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 10000 draws in [2, 5) all lie in the range, and cover both halves of it
        boolean low = false, high = false;
        for (int i = 0; i < 10_000; ++i) {
            double r = random(2, 5);
            assertTrue(r >= 2 && r < 5, "TC01: random value out of [2, 5): " + r);
            low |= r < 3.5;
            high |= r >= 3.5;
        }
        assertTrue(low && high, "TC01: random values do not spread over [2, 5)");
        // TC02: negative range [-3, -1): every draw in range
        for (int i = 0; i < 1000; ++i) {
            double r = random(-3, -1);
            assertTrue(r >= -3 && r < -1, "TC02: random value out of [-3, -1): " + r);
        }
        // TC03: min above max is rejected, the message names the empty range
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> random(5, 2),
                "TC03: min > max must be rejected");
        assertMessage(e, "range", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: min equal to max is rejected (empty range)
        e = assertThrows(IllegalArgumentException.class, () -> random(1, 1),
                "TC10: min == max must be rejected");
        assertMessage(e, "range", "TC10");
        // TC11: NaN bound is rejected
        assertThrows(IllegalArgumentException.class, () -> random(Double.NaN, 1),
                "TC11: NaN min must be rejected");
        assertThrows(IllegalArgumentException.class, () -> random(0, Double.NaN),
                "TC11: NaN max must be rejected");
        // TC12: a very narrow range [1, 1 + 1e-9) still gives values inside it
        for (int i = 0; i < 100; ++i) {
            double r = random(1, 1 + 1e-9);
            assertTrue(r >= 1 && r <= 1 + 1e-9, "TC12: random value out of the narrow range: " + r);
        }
    }

    /** Test method for {@link primitives.Util#requireFinite(double, String)}. */
    @Test
    void testRequireFinite() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a finite number is returned as is (-7.5)
        assertEquals(-7.5, requireFinite(-7.5, "value"), 0, "TC01: wrong returned value");
        // TC02: NaN is rejected, the message names the value and says "finite"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> requireFinite(Double.NaN, "sphere radius"), "TC02: NaN must be rejected");
        assertMessage(e, "sphere radius", "TC02");
        assertMessage(e, "finite", "TC02");
        // TC03: +infinity is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> requireFinite(Double.POSITIVE_INFINITY, "x"), "TC03: +inf must be rejected");
        assertMessage(e, "finite", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: -infinity is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> requireFinite(Double.NEGATIVE_INFINITY, "x"), "TC10: -inf must be rejected");
        assertMessage(e, "finite", "TC10");
        // TC11: the largest finite number is accepted (Double.MAX_VALUE)
        assertEquals(Double.MAX_VALUE, requireFinite(Double.MAX_VALUE, "x"), 0, "TC11: wrong returned value");
        // TC12: zero is accepted (0)
        assertEquals(0, requireFinite(0, "x"), 0, "TC12: wrong returned value");
    }

    /** Test method for {@link primitives.Util#requirePositive(double, String)}. */
    @Test
    void testRequirePositive() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a positive number is returned as is (3)
        assertEquals(3, requirePositive(3, "radius"), 0, "TC01: wrong returned value");
        // TC02: a negative number is rejected, the message names the value and says "positive"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> requirePositive(-2, "radius"), "TC02: negative must be rejected");
        assertMessage(e, "radius", "TC02");
        assertMessage(e, "positive", "TC02");
        // TC03: NaN is rejected as not finite
        e = assertThrows(IllegalArgumentException.class,
                () -> requirePositive(Double.NaN, "radius"), "TC03: NaN must be rejected");
        assertMessage(e, "finite", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: zero is rejected
        e = assertThrows(IllegalArgumentException.class,
                () -> requirePositive(0, "height"), "TC10: zero must be rejected");
        assertMessage(e, "height", "TC10");
        assertMessage(e, "positive", "TC10");
        // TC11: the smallest positive double is accepted (Double.MIN_VALUE)
        assertEquals(Double.MIN_VALUE, requirePositive(Double.MIN_VALUE, "x"), 0, "TC11: wrong returned value");
        // TC12: +infinity is rejected as not finite
        e = assertThrows(IllegalArgumentException.class,
                () -> requirePositive(Double.POSITIVE_INFINITY, "x"), "TC12: +inf must be rejected");
        assertMessage(e, "finite", "TC12");
    }

    /** Test method for {@link primitives.Util#requireNonNegative(double, String)}. */
    @Test
    void testRequireNonNegative() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a positive number is returned as is (0.5)
        assertEquals(0.5, requireNonNegative(0.5, "kD"), 0, "TC01: wrong returned value");
        // TC02: a negative number is rejected, the message names the value and says "negative"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> requireNonNegative(-1, "edge size"), "TC02: negative must be rejected");
        assertMessage(e, "edge size", "TC02");
        assertMessage(e, "negative", "TC02");
        // TC03: NaN is rejected as not finite
        e = assertThrows(IllegalArgumentException.class,
                () -> requireNonNegative(Double.NaN, "kD"), "TC03: NaN must be rejected");
        assertMessage(e, "finite", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: zero is accepted (0)
        assertEquals(0, requireNonNegative(0, "kD"), 0, "TC10: wrong returned value");
        // TC11: the negative number closest to zero is rejected (-Double.MIN_VALUE)
        e = assertThrows(IllegalArgumentException.class,
                () -> requireNonNegative(-Double.MIN_VALUE, "kD"), "TC11: -MIN_VALUE must be rejected");
        assertMessage(e, "negative", "TC11");
    }

    /** Test method for {@link primitives.Util#requireNonNull(Object, String)}. */
    @Test
    void testRequireNonNull() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a non-null argument is returned as the same object
        String s = "value";
        assertSame(s, requireNonNull(s, "name"), "TC01: the argument itself must be returned");
        // TC02: null is rejected with an IllegalArgumentException naming the argument and "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> requireNonNull(null, "ray direction"), "TC02: null must be rejected");
        assertMessage(e, "ray direction", "TC02");
        assertMessage(e, "null", "TC02");
    }
}
