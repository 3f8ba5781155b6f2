package primitives;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link primitives.Color}.
 */
class ColorTest {
    /** Test method for {@link primitives.Color#Color(double, double, double)} and {@link primitives.Color#BLACK}. */
    @Test
    void testConstructorComponents() {
        // ===== Equivalence Partitions Tests =====
        // TC01: components are kept (10, 20.5, 300)
        assertColor(10, 20.5, 300, new Color(10, 20.5, 300), "TC01: wrong components");
        // TC02: a negative component is rejected, the message names it and says "negative"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Color(-1, 0, 0), "TC02: negative red must be rejected");
        assertMessage(e, "red", "TC02");
        assertMessage(e, "negative", "TC02");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Color(0, -1, 0), "TC02: negative green must be rejected");
        assertMessage(e, "green", "TC02");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Color(0, 0, -1), "TC02: negative blue must be rejected");
        assertMessage(e, "blue", "TC02");
        // TC03: NaN and infinite components are rejected ("finite")
        e = assertThrows(IllegalArgumentException.class,
                () -> new Color(Double.NaN, 0, 0), "TC03: NaN red must be rejected");
        assertMessage(e, "finite", "TC03");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Color(0, Double.NaN, 0), "TC03: NaN green must be rejected");
        assertMessage(e, "finite", "TC03");
        e = assertThrows(IllegalArgumentException.class,
                () -> new Color(0, 0, Double.POSITIVE_INFINITY), "TC03: infinite blue must be rejected");
        assertMessage(e, "finite", "TC03");

        // ===== Boundary Values Tests =====
        // TC10: BLACK is (0,0,0)
        assertColor(0, 0, 0, Color.BLACK, "TC10: BLACK must be (0,0,0)");
        assertEquals(new Color(0, 0, 0), Color.BLACK, "TC10: BLACK must equal (0,0,0)");
        // TC11: zero components are accepted (0,0,0)
        assertColor(0, 0, 0, new Color(0, 0, 0), "TC11: wrong components");
        // TC12: a tiny negative component is rejected (-1e-300)
        assertThrows(IllegalArgumentException.class, () -> new Color(0, 0, -1e-300),
                "TC12: tiny negative blue must be rejected");
    }

    /** Test method for {@link primitives.Color#Color(java.awt.Color)}. */
    @Test
    void testConstructorAwt() {
        // ===== Equivalence Partitions Tests =====
        // TC01: AWT (10,20,30) gives (10,20,30)
        assertColor(10, 20, 30, new Color(new java.awt.Color(10, 20, 30)), "TC01: wrong components");
        // TC02: null is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Color((java.awt.Color) null), "TC02: null AWT colour must be rejected");
        assertMessage(e, "null", "TC02");

        // ===== Boundary Values Tests =====
        // TC10: AWT black gives (0,0,0)
        assertColor(0, 0, 0, new Color(java.awt.Color.BLACK), "TC10: wrong components");
        // TC11: AWT white gives (255,255,255)
        assertColor(255, 255, 255, new Color(java.awt.Color.WHITE), "TC11: wrong components");
        // TC12: round trip: getColor() of AWT (1,128,254) gives the same AWT colour
        java.awt.Color awt = new java.awt.Color(1, 128, 254);
        assertEquals(awt, new Color(awt).getColor(), "TC12: round trip through Color must keep the AWT colour");
    }

    /** Test method for {@link primitives.Color#add(primitives.Color...)}. */
    @Test
    void testAdd() {
        Color c1 = new Color(10, 20, 30);
        Color c2 = new Color(1, 2, 3);
        Color c3 = new Color(100, 0, 0.5);
        // ===== Equivalence Partitions Tests =====
        // TC01: one colour: (10,20,30) + (1,2,3) = (11,22,33)
        assertColor(11, 22, 33, c1.add(c2), "TC01: wrong sum");
        // TC02: several colours: (10,20,30) + (1,2,3) + (100,0,0.5) = (111,22,33.5)
        assertColor(111, 22, 33.5, c1.add(c2, c3), "TC02: wrong sum of several colours");
        // TC03: sums above 255 are kept (not clamped): (200,200,200)+(100,100,100) = (300,300,300)
        assertColor(300, 300, 300, new Color(200, 200, 200).add(new Color(100, 100, 100)), "TC03: wrong sum");
        // TC04: the operands are unchanged
        c1.add(c2, c3);
        assertColor(10, 20, 30, c1, "TC04: add changed its colour");
        assertColor(1, 2, 3, c2, "TC04: add changed its argument");
        assertColor(100, 0, 0.5, c3, "TC04: add changed its argument");
        // TC05: a null colour or null array is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> c1.add(c2, null), "TC05: null colour must be rejected");
        assertMessage(e, "null", "TC05");
        e = assertThrows(IllegalArgumentException.class,
                () -> c1.add((Color[]) null), "TC05: null array must be rejected");
        assertMessage(e, "null", "TC05");

        // ===== Boundary Values Tests =====
        // TC10: no argument: an equal colour (10,20,30)
        assertColor(10, 20, 30, c1.add(), "TC10: add() must give the same colour");
        // TC11: adding BLACK: the same colour (10,20,30)
        assertColor(10, 20, 30, c1.add(Color.BLACK), "TC11: adding BLACK must not change the colour");
        // TC12: adding a colour to itself: (20,40,60)
        assertColor(20, 40, 60, c1.add(c1), "TC12: wrong sum c + c");
        // TC13: a sum past the largest double stays at the largest double
        Color huge = new Color(Double.MAX_VALUE, 1, 0);
        assertColor(Double.MAX_VALUE, 2, 0, huge.add(huge), "TC13: an overflowing sum must saturate");
    }

    /** Test method for {@link primitives.Color#scale(double)}. */
    @Test
    void testScale() {
        Color c = new Color(10, 20, 30);
        // ===== Equivalence Partitions Tests =====
        // TC01: factor 2: (20,40,60)
        assertColor(20, 40, 60, c.scale(2), "TC01: wrong scaled colour");
        // TC02: factor 0.5: (5,10,15)
        assertColor(5, 10, 15, c.scale(0.5), "TC02: wrong scaled colour");
        // TC03: operand unchanged
        c.scale(3);
        assertColor(10, 20, 30, c, "TC03: scale changed its colour");
        // TC04: negative factor is rejected, the message names the factor and "negative"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> c.scale(-2), "TC04: negative factor must be rejected");
        assertMessage(e, "scale", "TC04");
        assertMessage(e, "negative", "TC04");
        // TC05: NaN factor is rejected ("finite")
        e = assertThrows(IllegalArgumentException.class, () -> c.scale(Double.NaN),
                "TC05: NaN factor must be rejected");
        assertMessage(e, "finite", "TC05");

        // ===== Boundary Values Tests =====
        // TC10: factor 0: BLACK (0,0,0)
        assertEquals(Color.BLACK, c.scale(0), "TC10: scale(0) must give black");
        // TC11: factor 1: the same colour (10,20,30)
        assertColor(10, 20, 30, c.scale(1), "TC11: scale(1) must keep the colour");
        // TC12: a tiny negative factor is rejected (-1e-300)
        assertThrows(IllegalArgumentException.class, () -> c.scale(-1e-300),
                "TC12: tiny negative factor must be rejected");
        // TC13: a product past the largest double (10 × 1e308) stays at the largest double
        assertColor(Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE, c.scale(1e308),
                "TC13: an overflowing product must saturate");
    }

    /** Test method for {@link primitives.Color#reduce(double)}. */
    @Test
    void testReduce() {
        Color c = new Color(10, 20, 30);
        // ===== Equivalence Partitions Tests =====
        // TC01: divisor 2: (5,10,15)
        assertColor(5, 10, 15, c.reduce(2), "TC01: wrong reduced colour");
        // TC02: divisor 0.5: (20,40,60)
        assertColor(20, 40, 60, c.reduce(0.5), "TC02: wrong reduced colour");
        // TC03: operand unchanged
        c.reduce(4);
        assertColor(10, 20, 30, c, "TC03: reduce changed its colour");
        // TC04: negative divisor is rejected, the message says "positive"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> c.reduce(-2), "TC04: negative divisor must be rejected");
        assertMessage(e, "positive", "TC04");
        // TC05: NaN divisor is rejected ("finite")
        e = assertThrows(IllegalArgumentException.class, () -> c.reduce(Double.NaN),
                "TC05: NaN divisor must be rejected");
        assertMessage(e, "finite", "TC05");

        // ===== Boundary Values Tests =====
        // TC10: divisor 0 is rejected, the message names the divisor and "positive"
        e = assertThrows(IllegalArgumentException.class, () -> c.reduce(0), "TC10: reduce(0) must be rejected");
        assertMessage(e, "divisor", "TC10");
        assertMessage(e, "positive", "TC10");
        // TC11: divisor 1: the same colour (10,20,30)
        assertColor(10, 20, 30, c.reduce(1), "TC11: reduce(1) must keep the colour");
        // TC12: infinite divisor is rejected ("finite")
        e = assertThrows(IllegalArgumentException.class, () -> c.reduce(Double.POSITIVE_INFINITY),
                "TC12: infinite divisor must be rejected");
        assertMessage(e, "finite", "TC12");
        // TC13: a tiny divisor (1e-308) whose quotient overflows: the largest double
        assertColor(Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE, c.reduce(1e-308),
                "TC13: an overflowing quotient must saturate");
    }

    /** Test method for {@link primitives.Color#getColor()}. */
    @Test
    void testGetColor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: components in range are kept: (10,20,30) → AWT (10,20,30)
        assertEquals(new java.awt.Color(10, 20, 30), new Color(10, 20, 30).getColor(), "TC01: wrong AWT colour");
        // TC02: components above 255 are clamped: (300,1000,256) → AWT (255,255,255)
        assertEquals(new java.awt.Color(255, 255, 255), new Color(300, 1000, 256).getColor(),
                "TC02: components above 255 must be clamped");
        // TC03: fractions are truncated: (10.9,20.5,30.1) → AWT (10,20,30)
        assertEquals(new java.awt.Color(10, 20, 30), new Color(10.9, 20.5, 30.1).getColor(),
                "TC03: fractions must be truncated");
        // TC04: mixed: (300,12.7,0.99) → AWT (255,12,0)
        assertEquals(new java.awt.Color(255, 12, 0), new Color(300, 12.7, 0.99).getColor(),
                "TC04: wrong AWT colour");

        // ===== Boundary Values Tests =====
        // TC10: exactly 255 stays 255: (255,255,255) → AWT white
        assertEquals(java.awt.Color.WHITE, new Color(255, 255, 255).getColor(), "TC10: 255 must stay 255");
        // TC11: just below 256 truncates to 255: (255.999,0,0) → AWT (255,0,0)
        assertEquals(new java.awt.Color(255, 0, 0), new Color(255.999, 0, 0).getColor(), "TC11: wrong AWT colour");
        // TC12: BLACK → AWT black
        assertEquals(java.awt.Color.BLACK, Color.BLACK.getColor(), "TC12: BLACK must give AWT black");
        // TC13: just below 1 truncates to 0: (0.999,0.999,0.999) → AWT black
        assertEquals(java.awt.Color.BLACK, new Color(0.999, 0.999, 0.999).getColor(), "TC13: wrong AWT colour");
    }

    /** Test method for {@link primitives.Color#equals(Object)} and {@link primitives.Color#hashCode()}. */
    @Test
    void testEquals() {
        Color c = new Color(10, 20, 30);
        // ===== Equivalence Partitions Tests =====
        // TC01: same components: equal, same hash code
        assertEquals(new Color(10, 20, 30), c, "TC01: colours with the same components must be equal");
        assertEquals(new Color(10, 20, 30).hashCode(), c.hashCode(), "TC01: equal colours must have the same hash");
        // TC02: different components: not equal
        assertNotEquals(new Color(10, 20, 31), c, "TC02: different colours must not be equal");
        // TC03: null and other types: not equal
        assertFalse(c.equals(null), "TC03: a colour is not equal to null");
        assertNotEquals(new java.awt.Color(10, 20, 30), c, "TC03: a colour is not equal to an AWT colour");

        // ===== Boundary Values Tests =====
        // TC10: within the tolerance (5e-11): equal
        assertEquals(c, new Color(10 + 5e-11, 20, 30), "TC10: colours within the tolerance must be equal");
    }

    /** Test method for {@link primitives.Color#add(Color)}: the same sum as adding an array of one colour. */
    @Test
    void testAddOne() {
        Color c1 = new Color(10.1, 20.3, 0.7);
        Color c2 = new Color(1e-3, 2.9, 1e20);
        // ===== Equivalence Partitions Tests =====
        // TC01: (10.1, 20.3, 0.7) + (0.001, 2.9, 1e20): the components of add(Color...) with one colour, bit for bit
        Color one = c1.add(c2);
        Color array = c1.add(new Color[] { c2 });
        assertEquals(array.getR(), one.getR(), 0, "TC01: wrong red");
        assertEquals(array.getG(), one.getG(), 0, "TC01: wrong green");
        assertEquals(array.getB(), one.getB(), 0, "TC01: wrong blue");
        // TC02: a null colour is rejected with a message naming "null"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> c1.add((Color) null),
                "TC02: null colour must be rejected");
        assertMessage(e, "null", "TC02");

        // ===== Boundary Values Tests =====
        // TC11: a sum past the largest double stays at the largest double (MAX, 2, 0)
        Color huge = new Color(Double.MAX_VALUE, 1, 0);
        assertColor(Double.MAX_VALUE, 2, 0, huge.add(huge), "TC11: an overflowing sum must saturate");
        // TC12: adding BLACK gives the same components (10.1, 20.3, 0.7)
        assertColor(10.1, 20.3, 0.7, c1.add(Color.BLACK), "TC12: adding BLACK must not change the colour");
    }

    /** Test method for {@link primitives.Color#getRGB()}. */
    @Test
    void testGetRGB() {
        // ===== Equivalence Partitions Tests =====
        // TC01: components in range, truncated: (10.9, 20, 30.5) → 0x0A141E
        assertEquals(0x0A141E, new Color(10.9, 20, 30.5).getRGB(), "TC01: wrong packed colour");
        // TC02: components above 255 are clamped: (300, 12.7, 1e300) → 0xFF0CFF
        assertEquals(0xFF0CFF, new Color(300, 12.7, 1e300).getRGB(), "TC02: components must be clamped");
        // TC03: the AWT colour's RGB without its alpha, for several colours
        for (Color c : new Color[] { new Color(1, 2, 3), new Color(255.5, 0.5, 128), new Color(64, 1000, 254.99) })
            assertEquals(c.getColor().getRGB() & 0xFFFFFF, c.getRGB(), "TC03: must agree with getColor() for " + c);

        // ===== Boundary Values Tests =====
        // TC11: black → 0
        assertEquals(0, Color.BLACK.getRGB(), "TC11: black must be 0");
        // TC12: 255 and just below 256 give 255, just below 1 gives 0: (255, 255.999, 0.999) → 0xFFFF00
        assertEquals(0xFFFF00, new Color(255, 255.999, 0.999).getRGB(), "TC12: wrong truncation at the limits");
        // TC13: the largest double is clamped to 255: (MAX, 0, 0) → 0xFF0000
        assertEquals(0xFF0000, new Color(Double.MAX_VALUE, 0, 0).getRGB(), "TC13: the largest double must give 255");
    }
}
