package accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Unit tests for {@link Boxes}, the flat-array boxes of the build and the caps. */
class BoxesTest {
    private static final double DELTA = 1e-12;
    private static final double INF = Double.POSITIVE_INFINITY;

    /** Test method for {@link Boxes#empty(int)} and {@link Boxes#clear(double[], int)}. */
    @Test
    void testEmpty() {
        // ===== Equivalence Partitions Tests =====
        // TC01: two empty boxes: +∞ lows and −∞ highs
        assertArrayEquals(new double[] { INF, INF, INF, -INF, -INF, -INF, INF, INF, INF, -INF, -INF, -INF },
                Boxes.empty(2), "TC01");
        // TC02: clearing the second box of two leaves the first alone
        double[] boxes = { 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3 };
        Boxes.clear(boxes, 6);
        assertArrayEquals(new double[] { 0, 0, 0, 1, 1, 1, INF, INF, INF, -INF, -INF, -INF }, boxes, "TC02");
        // ===== Boundary Values Tests =====
        // TC11: no box
        assertEquals(0, Boxes.empty(0).length, "TC11");
    }

    /** Test method for {@link Boxes#include(double[], int, double, double, double)}. */
    @Test
    void testInclude() {
        // ===== Equivalence Partitions Tests =====
        // TC01: an empty box grown by two points is their box
        double[] box = Boxes.empty(1);
        Boxes.include(box, 0, 1, -2, 3);
        Boxes.include(box, 0, -1, 4, 0);
        assertArrayEquals(new double[] { -1, -2, 0, 1, 4, 3 }, box, DELTA, "TC01");
        // ===== Boundary Values Tests =====
        // TC11: a point inside changes nothing
        Boxes.include(box, 0, 0, 0, 1);
        assertArrayEquals(new double[] { -1, -2, 0, 1, 4, 3 }, box, DELTA, "TC11");
        // TC12: one point makes a box of no size
        double[] point = Boxes.empty(1);
        Boxes.include(point, 0, 5, 6, 7);
        assertArrayEquals(new double[] { 5, 6, 7, 5, 6, 7 }, point, DELTA, "TC12");
    }

    /** Test method for {@link Boxes#grow(double[], int, double[], int)}. */
    @Test
    void testGrow() {
        // ===== Equivalence Partitions Tests =====
        // TC01: two overlapping boxes: their union
        double[] box = { 0, 0, 0, 2, 2, 2 };
        Boxes.grow(box, 0, new double[] { 1, -1, 1, 3, 1, 1.5 }, 0);
        assertArrayEquals(new double[] { 0, -1, 0, 3, 2, 2 }, box, DELTA, "TC01");
        // TC02: an empty box grown by a box, read at an offset: that box
        double[] empty = Boxes.empty(1);
        Boxes.grow(empty, 0, new double[] { 9, 9, 9, 9, 9, 9, 1, 2, 3, 4, 5, 6 }, 6);
        assertArrayEquals(new double[] { 1, 2, 3, 4, 5, 6 }, empty, DELTA, "TC02");
        // ===== Boundary Values Tests =====
        // TC11: an empty other changes nothing
        Boxes.grow(box, 0, Boxes.empty(1), 0);
        assertArrayEquals(new double[] { 0, -1, 0, 3, 2, 2 }, box, DELTA, "TC11");
    }

    /** Test method for {@link Boxes#halfArea(double[], int)} and {@link Boxes#extent(double[], int)}. */
    @Test
    void testMeasures() {
        double[] boxes = { 0, 0, 0, 0, 0, 0, 1, 2, 3, 2, 4, 6 };
        // ===== Equivalence Partitions Tests =====
        // TC01: a 1 × 2 × 3 box: half its area 2 + 6 + 3 = 11, its longest side 3
        assertEquals(11, Boxes.halfArea(boxes, 6), DELTA, "TC01");
        assertEquals(3, Boxes.extent(boxes, 6), DELTA, "TC01");
        // ===== Boundary Values Tests =====
        // TC11: a box of no size: 0 and 0
        assertEquals(0, Boxes.halfArea(boxes, 0), DELTA, "TC11");
        assertEquals(0, Boxes.extent(boxes, 0), DELTA, "TC11");
    }

    /** Test method for {@link Boxes#pad(double[], double)}. */
    @Test
    void testPad() {
        // ===== Equivalence Partitions Tests =====
        // TC01: two boxes padded by 0.5: each side moved out by 0.5
        double[] boxes = { 0, 0, 0, 1, 2, 3, -1, -1, -1, 1, 1, 1 };
        Boxes.pad(boxes, 0.5);
        assertArrayEquals(new double[] { -0.5, -0.5, -0.5, 1.5, 2.5, 3.5, -1.5, -1.5, -1.5, 1.5, 1.5, 1.5 }, boxes,
                DELTA, "TC01");
        // ===== Boundary Values Tests =====
        // TC11: padded by 0: unchanged
        Boxes.pad(boxes, 0);
        assertArrayEquals(new double[] { -0.5, -0.5, -0.5, 1.5, 2.5, 3.5, -1.5, -1.5, -1.5, 1.5, 1.5, 1.5 }, boxes,
                DELTA, "TC11");
    }

    /** Test method for {@link Boxes#widestAxis(double[], int)}. */
    @Test
    void testWidestAxis() {
        // ===== Equivalence Partitions Tests =====
        // TC01: boxes longest along x, y and z: 0, 1, 2
        assertEquals(0, Boxes.widestAxis(new double[] { 0, 0, 0, 3, 2, 1 }, 0), "TC01: x");
        assertEquals(1, Boxes.widestAxis(new double[] { 0, 0, 0, 1, 3, 2 }, 0), "TC01: y");
        assertEquals(2, Boxes.widestAxis(new double[] { 9, 9, 9, 9, 9, 9, 0, 0, 0, 1, 2, 3 }, 6), "TC01: z, at an offset");
        // ===== Boundary Values Tests =====
        // TC11: ties go to the first axis: a cube 0, y and z equal 1
        assertEquals(0, Boxes.widestAxis(new double[] { 0, 0, 0, 1, 1, 1 }, 0), "TC11: a cube");
        assertEquals(1, Boxes.widestAxis(new double[] { 0, 0, 0, 1, 2, 2 }, 0), "TC11: y and z equal");
    }
}
