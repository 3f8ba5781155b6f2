package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestBundles.STANDARD_MARGIN;
import static testutil.TestBundles.holds;
import static testutil.TestBundles.randomPyramid;
import static testutil.TestBundles.raySegment;
import static testutil.TestBundles.segmentPoint;
import static testutil.TestBundles.setPyramid;
import static testutil.TestBundles.standard;
import static testutil.TestBundles.strayVector;
import static testutil.TestBundles.triangleData;
import static testutil.TestScenes.triangle;

import java.util.Arrays;
import java.util.Random;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;

import geometries.Geometry;
import geometries.Triangle;
import primitives.Point3D;
import testutil.TestBundles.RandomBundle;

/**
 * Unit tests for {@link ShadowFrustum}: the pyramid from a lit point to a light's square,
 * and its conservative box and plane tests.
 * <p>
 * Most cases use the pyramid with apex (0, 0, 0) and base (±2, ±2, 10) (centre (0, 0, 10), a = (2, 0, 0),
 * b = (0, 2, 0)): its sides are the planes x = ±z/5 and y = ±z/5, its base the plane z = 10. Its size
 * (largest |coordinate| 10 plus the extents 4 + 4 + 10 of its bounding box) is 28, so its margin is
 * 28·1e-7 = 2.8e-6. A thickness t (rays that start up to t from the apex and end up to t from the
 * base) widens that margin to t + 2.8e-6.
 */
class ShadowFrustumTest {

    /**
     * Whether the frustum may meet a box; the box is placed after a dummy box in the array, so the
     * offset is used.
     *
     * @param frustum the frustum
     * @param box     {minX, minY, minZ, maxX, maxY, maxZ}
     * @return the frustum's answer
     */
    private static boolean meets(ShadowFrustum frustum, double... box) {
        // the dummy box at offset 0 contains the apex: it would be met
        double[] boxes = { -1, -1, -1, 1, 1, 1, 0, 0, 0, 0, 0, 0 };
        System.arraycopy(box, 0, boxes, 6, 6);
        return frustum.meetsBox(boxes, 6);
    }

    /**
     * Whether the frustum may meet a triangle; the vertices are placed after a dummy vertex (at the
     * apex), the third first, so the places are used.
     *
     * @param frustum the frustum
     * @param v       the vertices p1, p2, p3, three coordinates each
     * @return the frustum's answer
     */
    private static boolean meetsTriangle(ShadowFrustum frustum, double... v) {
        double[] vertices = { 0, 0, 0, v[6], v[7], v[8], v[0], v[1], v[2], v[3], v[4], v[5] };
        return frustum.meetsTriangle(vertices, 6, 9, 3);
    }

    /**
     * Whether the frustum may meet a box kept in floats (the box rounded outward to floats), placed
     * after a dummy box in the array.
     *
     * @param frustum the frustum
     * @param box     {minX, minY, minZ, maxX, maxY, maxZ}
     * @return the frustum's answer
     */
    private static boolean meetsFloats(ShadowFrustum frustum, double... box) {
        float[] boxes = { -1, -1, -1, 1, 1, 1, 0, 0, 0, 0, 0, 0 };
        for (int k = 0; k < 3; ++k) {
            float low = (float) box[k];
            float high = (float) box[3 + k];
            boxes[6 + k] = low > box[k] ? Math.nextDown(low) : low;
            boxes[9 + k] = high < box[3 + k] ? Math.nextUp(high) : high;
        }
        return frustum.meetsBox(boxes, 6);
    }

    /** Test method for {@link ShadowFrustum#set}. */
    @Test
    void testSet() {
        ShadowFrustum frustum = new ShadowFrustum();

        // ===== Equivalence Partitions Tests =====
        // TC01: apex off the base's plane, a and b independent: true
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC01: a proper pyramid must be set");
        // TC02: a slanted base (a, b not orthogonal, not along the axes) seen from aside: true
        assertTrue(frustum.set(new double[] { 1, -2, 3 }, new double[] { 7, 5, -4, 1, 2, 0.5, -0.5, 1, 3 }, 0),
                "TC02: a slanted pyramid must be set");
        // TC03: the apex in the base's plane (here its centre): false
        assertFalse(frustum.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC03: apex at the base's centre is flat");
        // TC04: the apex in the base's plane, outside the base: false
        assertFalse(frustum.set(new double[] { 5, 7, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC04: apex in the base's plane is flat");
        // TC05: after a flat pyramid the same instance is set again properly: true, and it works
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC05: a flat pyramid must not spoil the next set");
        assertTrue(meets(frustum, -0.5, -0.5, 4, 0.5, 0.5, 5), "TC05: the reset pyramid must meet a box inside it");
        assertFalse(meets(frustum, -0.5, -0.5, -2, 0.5, 0.5, -1),
                "TC05: the reset pyramid must reject a box behind it");
        // TC06: a proper pyramid with a thickness 0.1 (the renderer's thick bundles): true
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0.1),
                "TC06: a thick pyramid must be set");
        // TC07: the apex in the base's plane with a thickness 0.1: still flat, false
        assertFalse(frustum.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0.1),
                "TC07: a thick flat pyramid is flat");

        // ===== Boundary Values Tests =====
        // TC11: a = 0 (the base is a segment): false
        assertFalse(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 0, 0, 0, 0, 2, 0 }, 0),
                "TC11: a = 0 is a degenerate base");
        // TC12: b = 0: false
        assertFalse(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 0, 0 }, 0),
                "TC12: b = 0 is a degenerate base");
        // TC13: a parallel to b: false
        assertFalse(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, -3, 0, 0 }, 0),
                "TC13: a parallel to b is a degenerate base");
        // TC14: a and b both 0 (the base is a point): false
        assertFalse(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 0, 0, 0, 0, 0, 0 }, 0),
                "TC14: a point base is degenerate");
        // TC15: the apex just off the base's plane (1e-3 of a size of 28, far above the flatness 2.8e-8): true
        assertTrue(frustum.set(new double[] { 0, 0, 10 - 1e-3 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC15: a very low pyramid is not flat");
        // TC16: the apex off the plane by 1e-12 (below the flatness): false
        assertFalse(frustum.set(new double[] { 0, 0, 10 - 1e-12 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC16: a pyramid this low counts as flat");
        // TC17: a tiny light (edge 2e-3) far away (distance 50): a thin pyramid, still true
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 50, 1e-3, 0, 0, 0, 1e-3, 0 }, 0),
                "TC17: a thin pyramid must be set");
        // TC18: a thickness far larger than the pyramid (10 around a pyramid of size 28): true
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 10),
                "TC18: a very thick pyramid must be set");
        // TC19: a thickness that does not lift the flatness: the pyramid 1e-12 low is flat even 1 thick
        assertFalse(frustum.set(new double[] { 0, 0, 10 - 1e-12 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 1),
                "TC19: a thickness must not make a flat pyramid proper");
        // TC20: a negative thickness is rejected with a message naming the thickness
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, -1e-9),
                "TC20: a negative thickness must throw");
        assertMessage(e, "thickness", "TC20");
        // TC21: a thickness that is not a number is rejected too
        e = assertThrows(IllegalArgumentException.class,
                () -> frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, Double.NaN),
                "TC21: a NaN thickness must throw");
        assertMessage(e, "thickness", "TC21");
        // TC22: an apex of 2 numbers, or none, is rejected with a message naming the apex
        double[] base = { 0, 0, 10, 2, 0, 0, 0, 2, 0 };
        e = assertThrows(IllegalArgumentException.class, () -> frustum.set(new double[] { 0, 0 }, base, 0),
                "TC22: an apex of 2 numbers must throw");
        assertMessage(e, "apex", "TC22");
        e = assertThrows(IllegalArgumentException.class, () -> frustum.set(null, base, 0),
                "TC22: a null apex must throw");
        assertMessage(e, "apex", "TC22");
        // TC23: a base of 8 or 10 numbers, or none, is rejected with a message naming the base
        double[] apex = { 0, 0, 0 };
        for (double[] wrong : new double[][] { new double[8], new double[10], null }) {
            e = assertThrows(IllegalArgumentException.class, () -> frustum.set(apex, wrong, 0),
                    "TC23: a base of other than 9 numbers must throw");
            assertMessage(e, "base", "TC23");
        }
    }

    /** Test method for {@link ShadowFrustum#meetsBox(double[], int)}. */
    @Test
    void testMeetsBox() {
        ShadowFrustum frustum = standard();

        // ===== Equivalence Partitions Tests =====
        // TC01: a box around the apex: true
        assertTrue(meets(frustum, -1, -1, -1, 1, 1, 1), "TC01: a box around the apex must be met");
        // TC02: a box inside the pyramid (at z 4..5 the pyramid spans ±0.8): true
        assertTrue(meets(frustum, -0.5, -0.5, 4, 0.5, 0.5, 5), "TC02: a box inside the pyramid must be met");
        // TC03: a box straddling the side x = z/5 (x 1.5..2.5 at z 8..9, where the side is at x 1.6..1.8): true
        assertTrue(meets(frustum, 1.5, -0.5, 8, 2.5, 0.5, 9), "TC03: a box across a side must be met");
        // TC04: a box around the whole pyramid: true
        assertTrue(meets(frustum, -50, -50, -50, 50, 50, 50), "TC04: a box around the pyramid must be met");
        // TC05: a box beyond the base (z 10.5..11): false
        assertFalse(meets(frustum, -1, -1, 10.5, 1, 1, 11), "TC05: a box beyond the base must not be met");
        // TC06: a box behind the apex (z −2..−1): false
        assertFalse(meets(frustum, -1, -1, -2, 1, 1, -1), "TC06: a box behind the apex must not be met");
        // TC07: a box beside the pyramid, inside its bounding box (x 1.5..2 at z 0..2, where the pyramid
        // reaches x 0.4): only the side x = z/5 rejects it: false
        assertFalse(meets(frustum, 1.5, -0.25, 0, 2, 0.25, 2), "TC07: a box beside the pyramid must not be met");
        // TC08: the same beside the side y = −z/5: false
        assertFalse(meets(frustum, -0.25, -2, 0, 0.25, -1.5, 2), "TC08: a box beside the pyramid must not be met");
        // TC09: a box outside the pyramid's bounding box sideways (x 3..4): false
        assertFalse(meets(frustum, 3, -1, 4, 4, 1, 6), "TC09: a box off the bounding box must not be met");
        // TC10: a long thin box across the pyramid, all its corners outside: true
        assertTrue(meets(frustum, -100, -0.1, 5, 100, 0.1, 5.1), "TC10: a box crossing the pyramid must be met");

        // ===== Boundary Values Tests =====
        // The side x = z/5: a point's distance outside it is (x − z/5)/√1.04. A box x from 1 + ε to
        // 1.5, z 0..5 has its nearest corner (1 + ε, 5) at ε/√1.04 outside.
        // TC11: the box touching the side (ε = 0): true
        assertTrue(meets(frustum, 1, -0.1, 0, 1.5, 0.1, 5), "TC11: a box touching a side must be met");
        // TC12: outside by ε = 1e-6 (0.98e-6, within the margin 2.8e-6): true
        assertTrue(meets(frustum, 1 + 1e-6, -0.1, 0, 1.5, 0.1, 5), "TC12: a box within the margin must be met");
        // TC13: outside by ε = 1e-4 (0.98e-4, far beyond the margin): false
        assertFalse(meets(frustum, 1 + 1e-4, -0.1, 0, 1.5, 0.1, 5), "TC13: a box beyond the margin must not be met");
        // TC14: a box touching the base from beyond (z 10..11): true
        assertTrue(meets(frustum, -1, -1, 10, 1, 1, 11), "TC14: a box touching the base must be met");
        // TC15: beyond the base by 1e-6 (within the margin): true; by 1e-4: false
        assertTrue(meets(frustum, -1, -1, 10 + 1e-6, 1, 1, 11),
                "TC15: a box within the margin of the base must be met");
        assertFalse(meets(frustum, -1, -1, 10 + 1e-4, 1, 1, 11),
                "TC15: a box beyond the base's margin must not be met");
        // TC16: a box whose corner touches the apex from behind (max corner (0, 0, 0)): true
        assertTrue(meets(frustum, -1, -1, -1, 0, 0, 0), "TC16: a box touching the apex must be met");
        // TC17: a box touching a base corner (2, 2, 10) from outside (min corner there): true
        assertTrue(meets(frustum, 2, 2, 10, 3, 3, 11), "TC17: a box touching a base corner must be met");
        // TC18: a flat box (zero thickness) in the pyramid: true; a point box beside it: false
        assertTrue(meets(frustum, -0.5, -0.5, 5, 0.5, 0.5, 5), "TC18: a flat box inside must be met");
        assertFalse(meets(frustum, 1.8, 0, 2, 1.8, 0, 2), "TC18: a point box outside must not be met");
        // TC19: a margin of 2.8e-6 in the standard pyramid: a box 2e-6 behind the apex is met, 5e-6 behind it not
        assertTrue(meets(frustum, -1, -1, -1, 1, 1, -2e-6), "TC19: within the margin behind the apex");
        assertFalse(meets(frustum, -1, -1, -1, 1, 1, -5e-6), "TC19: beyond the margin (" + STANDARD_MARGIN
                + ") behind the apex");
    }

    /** Test method for {@link ShadowFrustum#meetsBox(float[], int)}: the same answers as in doubles. */
    @Test
    void testMeetsBoxInFloats() {
        ShadowFrustum frustum = standard();

        // ===== Equivalence Partitions Tests =====
        // TC01: a box inside the pyramid: true
        assertTrue(meetsFloats(frustum, -0.5, -0.5, 4, 0.5, 0.5, 5), "TC01: a box inside the pyramid must be met");
        // TC02: a box across the side x = z/5: true
        assertTrue(meetsFloats(frustum, 1.5, -0.5, 8, 2.5, 0.5, 9), "TC02: a box across a side must be met");
        // TC03: a box beside the pyramid, inside its bounding box: false
        assertFalse(meetsFloats(frustum, 1.5, -0.25, 0, 2, 0.25, 2), "TC03: a box beside the pyramid must not be met");
        // TC04: a box beyond the base: false
        assertFalse(meetsFloats(frustum, -1, -1, 10.5, 1, 1, 11), "TC04: a box beyond the base must not be met");

        // ===== Boundary Values Tests =====
        // TC11: outside the side x = z/5 by 0.98e-6 (within the margin 2.8e-6): true; by 0.98e-4: false
        assertTrue(meetsFloats(frustum, 1 + 1e-6, -0.1, 0, 1.5, 0.1, 5), "TC11: a box within the margin must be met");
        assertFalse(meetsFloats(frustum, 1 + 1e-4, -0.1, 0, 1.5, 0.1, 5),
                "TC11: a box beyond the margin must not be met");
        // TC12: a box touching the apex from behind (max corner (0, 0, 0)): true
        assertTrue(meetsFloats(frustum, -1, -1, -1, 0, 0, 0), "TC12: a box touching the apex must be met");
        // TC13: after a refused set every box is met: true
        assertFalse(frustum.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC13: the flat pyramid must be refused");
        assertTrue(meetsFloats(frustum, -1, -1, 10.5, 1, 1, 11), "TC13: a refused frustum must set no box aside");
    }

    /**
     * Test method for {@link ShadowFrustum#meetsTriangle}: a triangle is set aside only when it lies
     * outside one face of the pyramid by more than the margin, as the renderer's test grows it.
     */
    @Test
    void testMeetsTriangle() {
        ShadowFrustum frustum = standard();
        double len = Math.sqrt(1.04);

        // ===== Equivalence Partitions Tests =====
        // TC01: a triangle inside the pyramid: true
        assertTrue(meetsTriangle(frustum, -0.5, -0.5, 5, 0.5, -0.5, 5, 0, 0.5, 6),
                "TC01: a triangle inside must be met");
        // TC02: a triangle across the side x = z/5 (from x 0 to 3 at z 5, where the side is at x 1): true
        assertTrue(meetsTriangle(frustum, 0, -0.5, 5, 3, -0.5, 5, 3, 0.5, 5),
                "TC02: a triangle across a side must be met");
        // TC03: a triangle around the whole pyramid (its plane z = 5 cuts it): true
        assertTrue(meetsTriangle(frustum, -50, -50, 5, 50, -50, 5, 0, 50, 5),
                "TC03: a triangle around the pyramid must be met");
        // TC04: the triangle (1.1, 0, 0), (2.5, 0, 10), (5, 0, 10) in the plane y = 0, which crosses the
        // pyramid: its box (x 1.1..5, z 0..10) meets the pyramid, but all three vertices are outside the
        // side x = z/5 (by 1.08, 0.49 and 2.94): false
        assertTrue(frustum.meetsPlane(0, 1, 0, 1.1, 0, 0), "TC04: the triangle's plane must cross the pyramid");
        assertTrue(meets(frustum, 1.1, 0, 0, 5, 0, 10), "TC04: the triangle's box must meet the pyramid");
        assertFalse(meetsTriangle(frustum, 1.1, 0, 0, 2.5, 0, 10, 5, 0, 10),
                "TC04: a triangle beside a side must not be met");
        // TC05: a triangle behind the apex and beside it (x 0.5 to 1, z −1 to −3, outside the side x = z/5): false
        assertFalse(meetsTriangle(frustum, 0.5, -1, -1, 1, 1, -1, 0.8, 0, -3),
                "TC05: a triangle behind the apex must not be met");
        // TC06: a triangle beyond the base (z 10.5 to 12), wider than the base: false
        assertFalse(meetsTriangle(frustum, -5, -5, 10.5, 5, -5, 12, 0, 5, 11),
                "TC06: a triangle beyond the base must not be met");

        // ===== Boundary Values Tests =====
        // The triangle of TC04 with its first vertex moved to (1 + ε·√1.04, 0, 5), ε outside the side
        // x = z/5 (the vertex's edge towards the others points away from the pyramid).
        // TC11: the vertex on the side (ε = 0): true
        assertTrue(meetsTriangle(frustum, 1, 0, 5, 2.5, 0, 10, 5, 0, 10),
                "TC11: a triangle touching a side must be met");
        // TC12: ε = 1e-6, within the margin 2.8e-6: true
        assertTrue(meetsTriangle(frustum, 1 + 1e-6 * len, 0, 5, 2.5, 0, 10, 5, 0, 10),
                "TC12: a triangle within the margin of a side must be met");
        // TC13: ε = 1e-4, beyond the margin: false
        assertFalse(meetsTriangle(frustum, 1 + 1e-4 * len, 0, 5, 2.5, 0, 10, 5, 0, 10),
                "TC13: a triangle beyond the margin of a side must not be met");
        // TC14: a triangle in the plane z = 5 with its vertex (1 + 1e-4·√1.04, 0, 5) 1e-4 outside the side,
        // the other two 1e5 away: the renderer's closed test takes it as grown by 1e-9 of its edges,
        // about 2e-4 here, so the ray from the apex to the base's edge point (2, 0, 10) hits it at
        // (1, 0, 5): true
        double[] huge = { 1 + 1e-4 * len, 0, 5, 1e5, -1e5, 5, 1e5, 1e5, 5 };
        double t = triangle(huge).nearestHit(new RayState().set(0, 0, 0, 2 / Math.sqrt(104), 0, 10 / Math.sqrt(104),
                Math.sqrt(104)));
        assertTrue(t < Geometry.NO_HIT, "TC14: the ray along the side must hit the grown triangle");
        assertTrue(meetsTriangle(frustum, huge), "TC14: a triangle grown into the pyramid must be met");
        // TC15: a triangle whose vertex touches the apex from behind: true
        assertTrue(meetsTriangle(frustum, 0, 0, 0, -1, 0, -1, 0, -1, -1),
                "TC15: a triangle touching the apex must be met");
        // TC16: the triangle of TC13 in a pyramid 0.5 thick (within the thickness): true
        assertTrue(meetsTriangle(standard(0.5), 1 + 1e-4 * len, 0, 5, 2.5, 0, 10, 5, 0, 10),
                "TC16: a triangle within the thickness must be met");
        // TC17: after a refused set every triangle is met: true
        assertFalse(frustum.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC17: the flat pyramid must be refused");
        assertTrue(meetsTriangle(frustum, 0.5, -1, -1, 1, 1, -1, 0.8, 0, -3),
                "TC17: a refused frustum must set no triangle aside");
    }

    /**
     * The slanted pyramid of the back-face tests: apex (0, 0, 0), base (5, −3, 0) ± (0.5, 0.5, −1) ±
     * (0.1, 0.1, 0.1), a light low over the plane x + y + z = 0 (its base 1.7·√3 to 2.3·√3 ahead of it
     * along (1, 1, 1)). Its bounding box x 0..5.6, y −3.6..0, z −1.1..1.1 reaches behind that plane near
     * the apex, so a box there is not set aside by the bounding box either. Size 5.6 + 11.4 = 17, margin
     * 1.7e-6.
     *
     * @param frustum the frustum to set
     * @return the frustum
     */
    private static ShadowFrustum slanted(ShadowFrustum frustum) {
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 5, -3, 0, 0.5, 0.5, -1, 0.1, 0.1, 0.1 }, 0),
                "the slanted pyramid must be set");
        return frustum;
    }

    /**
     * Asks a frustum for a back face ({@link ShadowFrustum#setBackFace}).
     *
     * @return whether it has one then ({@link ShadowFrustum#hasBackFace})
     */
    private static boolean backFace(ShadowFrustum frustum, double nx, double ny, double nz) {
        frustum.setBackFace(nx, ny, nz);
        return frustum.hasBackFace();
    }

    /**
     * Test method for {@link ShadowFrustum#setBackFace} and {@link ShadowFrustum#hasBackFace}: the plane through the
     * apex across a direction the whole base lies ahead along sets aside the triangles behind it, also around the
     * apex where no other face does (boxes it leaves to the other faces); it is refused, setting nothing aside, when
     * the base does not lie ahead or the pyramid or direction is not proper, and the next
     * {@link ShadowFrustum#set} takes it away.
     */
    @Test
    void testSetBackFace() {
        ShadowFrustum frustum = slanted(new ShadowFrustum());
        double root3 = Math.sqrt(3);
        // behind the plane x + y + z = 0 by 0.1/√3 (its corner (0.1, 0.6, −0.8) the nearest), around the
        // apex in x and y, inside the pyramid's bounding box and outside none of its five faces
        double[] behind = { -0.5, -0.9, -0.8, 0.1, 0.6, -0.8 };
        // a box about the base's centre, inside the pyramid
        double[] ahead = { 4.9, -3.1, -0.1, 5.1, -2.9, 0.1 };
        // a triangle in the plane x + y + z = −0.03 (0.03/√3 behind), around the apex's foot
        double[] triangle = { 1, 0, -1.03, -1, 1, -0.03, 0, -1, 0.97 };
        // the same triangle lifted 0.06 along z: it crosses the plane x + y + z = 0
        double[] crossing = { 1, 0, -0.97, -1, 1, 0.03, 0, -1, 1.03 };

        // ===== Equivalence Partitions Tests =====
        // TC01: before a back face the box and the triangle behind the apex are met (no face sets them aside)
        assertTrue(meets(frustum, behind), "TC01: without a back face the box behind the apex must be met");
        assertTrue(meetsTriangle(frustum, triangle), "TC01: without a back face the triangle behind must be met");
        // TC02: the direction (1, 1, 1), the base ahead along it: true, and the triangle behind is set
        // aside; the box behind still meets (the back face tests triangles only)
        assertTrue(backFace(frustum, 1, 1, 1), "TC02: a back face with the base ahead must be set");
        assertFalse(meetsTriangle(frustum, triangle), "TC02: the triangle behind the back face must be set aside");
        assertTrue(meets(frustum, behind), "TC02: the back face must not set a box aside");
        // TC03: a box ahead and a triangle crossing the plane are still met
        assertTrue(meets(frustum, ahead), "TC03: a box inside the pyramid must be met");
        assertTrue(meetsTriangle(frustum, crossing), "TC03: a triangle across the back face must be met");
        // TC04: the same direction not normalised, (0.5, 0.5, 0.5): the same back face
        assertTrue(backFace(slanted(frustum), 0.5, 0.5, 0.5), "TC04: the length of the direction must not matter");
        assertFalse(meetsTriangle(frustum, triangle), "TC04: the triangle behind the back face must be set aside");
        // TC05: the next set takes the back face away: the box behind met again
        slanted(frustum);
        assertTrue(meets(frustum, behind), "TC05: a new set must take the back face away");
        assertTrue(meetsTriangle(frustum, triangle), "TC05: a new set must take the back face away (triangle)");
        // TC06: a direction some base corner lies behind, (−1, −1, −1): false, and nothing is set aside more
        assertFalse(backFace(frustum, -1, -1, -1), "TC06: a back face with the base behind must be refused");
        assertTrue(meetsTriangle(frustum, triangle), "TC06: a refused back face must set nothing aside");
        assertTrue(meets(frustum, ahead), "TC06: a refused back face must set nothing aside");

        // ===== Boundary Values Tests =====
        // TC11: the back face set, a triangle in the plane x + y + z = c: 1e-6 behind the back plane
        // (within the margin 1.7e-6): met; 1e-4 behind it: set aside
        assertTrue(backFace(frustum, 1, 1, 1), "TC11: the back face must be set");
        for (double behindBy : new double[] { 1e-6, 1e-4 }) {
            double c = -behindBy * root3;
            assertEquals(behindBy < 1.7e-6, meetsTriangle(frustum, 1, 0, c - 1, -1, 1, c, 0, -1, c + 1),
                    "TC11: a triangle " + behindBy + " behind the back face");
        }
        // TC12: the triangle moved into the back plane x + y + z = 0 itself: met
        assertTrue(meetsTriangle(frustum, 1, 0, -1, -1, 1, 0, 0, -1, 1),
                "TC12: a triangle in the back plane must be met");
        // The standard pyramid (apex 0, base (±2, ±2, 10), margin 2.8e-6) and directions (1, 0, s): the
        // corners (−2, ±2, 10) lie (10s − 2)/√(1 + s²) ahead
        ShadowFrustum standard = standard();
        // TC13: s = 0.2, the corners in the plane: false; s = 0.1, behind it: false
        assertFalse(backFace(standard, 1, 0, 0.2), "TC13: base corners in the back plane must refuse it");
        assertFalse(backFace(standard, 1, 0, 0.1), "TC13: base corners behind the back plane must refuse it");
        // TC14: s = 0.2 + 1e-7, ahead by 0.98e-6 (within the margin): false; s = 0.2 + 1e-6, ahead by
        // 9.8e-6: true
        assertFalse(backFace(standard, 1, 0, 0.2 + 1e-7), "TC14: corners ahead within the margin must refuse it");
        assertTrue(backFace(standard, 1, 0, 0.2 + 1e-6), "TC14: corners ahead beyond the margin must allow it");
        // TC15: a zero, NaN or infinite direction: false, and the triangle behind the slanted apex still met
        slanted(frustum);
        double inf = Double.POSITIVE_INFINITY;
        double[][] bad = { { 0, 0, 0 }, { Double.NaN, 1, 1 }, { 1, 1, Double.NaN }, { inf, 1, 1 }, { 1, -inf, 1 } };
        for (double[] d : bad) {
            assertFalse(backFace(frustum, d[0], d[1], d[2]), "TC15: the direction " + Arrays.toString(d)
                    + " must be refused");
            assertTrue(meetsTriangle(frustum, triangle), "TC15: a refused back face must set nothing aside");
        }
        // TC16: before any set, and after a refused (flat) set: false, every box met
        ShadowFrustum fresh = new ShadowFrustum();
        assertFalse(backFace(fresh, 0, 0, 1), "TC16: an unset frustum must refuse a back face");
        assertTrue(meets(fresh, -1, -1, -2, 1, 1, -1), "TC16: an unset frustum must set no box aside");
        assertFalse(standard.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC16: the flat pyramid must be refused");
        assertFalse(backFace(standard, 0, 0, 1), "TC16: a refused frustum must refuse a back face");
        assertTrue(meets(standard, -1, -1, -2, 1, 1, -1), "TC16: a refused frustum must set no box aside");
        assertTrue(meetsTriangle(standard, -5, -5, -1, 5, -5, -1, 0, 5, -1),
                "TC16: a refused frustum must set no triangle aside");
        // TC17: none asked for since the last set (expects false); a back face placed, then one asked for
        // that cannot be: the later replaces it (expects false, the triangle behind met again)
        assertFalse(slanted(frustum).hasBackFace(), "TC17: no back face was asked for");
        assertTrue(backFace(frustum, 1, 1, 1), "TC17: the back face must be set");
        assertFalse(backFace(frustum, -1, -1, -1), "TC17: the later back face cannot be placed");
        assertTrue(meetsTriangle(frustum, triangle), "TC17: the later request must replace the earlier");
    }

    /**
     * Test method for {@link ShadowFrustum#setLeaving}: a bundle leaving a surface on one side asks for
     * the back face across n (or −n), one leaving on both sides sets the ray origins.
     */
    @Test
    void testSetLeaving() {
        // the standard pyramid (apex 0, base (±2, ±2, 10)) leaving the surface z = 0, n = (0, 0, 0.1)
        // ===== Equivalence Partitions Tests =====
        // TC01: side 1: the back face across n (expects a back face, no ray origins)
        ShadowFrustum above = standard();
        above.setLeaving(1, 0, 0, -0.1, 0, 0, 0.1);
        assertTrue(above.hasBackFace(), "TC01: leaving on n's side must give a back face");
        assertFalse(above.hasOrigins(), "TC01: leaving on one side must set no ray origins");
        // TC02: side −1 with n = (0, 0, −0.1): the back face across −n, the base ahead along it (expects
        // a back face)
        ShadowFrustum below = standard();
        below.setLeaving(-1, 0, 0, 0.1, 0, 0, -0.1);
        assertTrue(below.hasBackFace(), "TC02: leaving on the other side must give a back face across −n");
        // TC03: side 0: the ray origins p ± n (expects ray origins, no back face, p + n an origin)
        ShadowFrustum both = standard(0.1);
        both.setLeaving(0, 0, 0, 0, 0, 0, 0.1);
        assertTrue(both.hasOrigins(), "TC03: leaving on both sides must set the ray origins");
        assertFalse(both.hasBackFace(), "TC03: leaving on both sides must give no back face");
        assertEquals(ShadowFrustum.ABOVE, both.originOf(0, 0, 0.1, 0, 0, 1), "TC03: p + n must be an origin");

        // ===== Boundary Values Tests =====
        // TC11: side 1 with n pointing away from the base: the back face cannot be placed (expects none)
        ShadowFrustum wrong = standard();
        wrong.setLeaving(1, 0, 0, 0.1, 0, 0, -0.1);
        assertFalse(wrong.hasBackFace(), "TC11: a back face the base lies behind must not be placed");
    }

    /**
     * Test method for {@link ShadowFrustum#setOrigins} and {@link ShadowFrustum#originOf}: a ray from
     * exactly p + n to n's side is {@link ShadowFrustum#ABOVE}, one from exactly p − n to the other
     * side {@link ShadowFrustum#BELOW}, any other 0.
     */
    @Test
    void testOriginOf() {
        ShadowFrustum frustum = standard(0.1);
        // p = (1, 2, 3), n = (0, 0.1, 0.1): the ray origins p + n and p − n as the renderer computes them
        double px = 1;
        double py = 2;
        double pz = 3;
        double ny = 0.1;
        double nz = 0.1;
        frustum.setOrigins(px, py, pz, 0, ny, nz);

        // ===== Equivalence Partitions Tests =====
        // TC01: from p + n along n, and slanted to n's side: ABOVE
        assertEquals(ShadowFrustum.ABOVE, frustum.originOf(px, py + ny, pz + nz, 0, 1, 1), "TC01: along n from p + n");
        assertEquals(ShadowFrustum.ABOVE, frustum.originOf(px, py + ny, pz + nz, 0.8, 0.6, -0.2),
                "TC01: slanted to n's side from p + n");
        // TC02: from p − n against n, and slanted to the other side: BELOW
        assertEquals(ShadowFrustum.BELOW, frustum.originOf(px, py - ny, pz - nz, 0, -1, -1),
                "TC02: against n from p − n");
        assertEquals(ShadowFrustum.BELOW, frustum.originOf(px, py - ny, pz - nz, -0.8, 0.2, -0.6),
                "TC02: slanted to the other side from p − n");
        // TC03: from p + n to the other side, from p − n to n's side: 0
        assertEquals(0, frustum.originOf(px, py + ny, pz + nz, 0, -1, 0), "TC03: from p + n against n");
        assertEquals(0, frustum.originOf(px, py - ny, pz - nz, 0, 0, 1), "TC03: from p − n along n");
        // TC04: from p itself, and from a point elsewhere: 0
        assertEquals(0, frustum.originOf(px, py, pz, 0, 1, 1), "TC04: from p itself");
        assertEquals(0, frustum.originOf(5, 5, 5, 0, 1, 1), "TC04: from elsewhere");

        // ===== Boundary Values Tests =====
        // TC11: from p + n with one coordinate one ulp off: 0 (each coordinate in turn), and the same for p − n
        assertEquals(0, frustum.originOf(Math.nextUp(px), py + ny, pz + nz, 0, 1, 1), "TC11: x one ulp off p + n");
        assertEquals(0, frustum.originOf(px, Math.nextUp(py + ny), pz + nz, 0, 1, 1), "TC11: y one ulp off p + n");
        assertEquals(0, frustum.originOf(px, py + ny, Math.nextDown(pz + nz), 0, 1, 1), "TC11: z one ulp off p + n");
        assertEquals(0, frustum.originOf(px, py - ny, Math.nextUp(pz - nz), 0, -1, -1), "TC11: z one ulp off p − n");
        // TC12: a direction along the surface (d·n = 0), from either origin: 0
        assertEquals(0, frustum.originOf(px, py + ny, pz + nz, 0, 1, -1), "TC12: along the surface from p + n");
        assertEquals(0, frustum.originOf(px, py - ny, pz - nz, 1, 0, 0), "TC12: along the surface from p − n");
        // TC13: a new set forgets the ray origins: 0
        frustum = standard(0.1);
        assertEquals(0, frustum.originOf(px, py + ny, pz + nz, 0, 1, 1), "TC13: after a new set no origin is known");
        // TC14: ray origins never set: 0; set with n = 0: 0 (p + n = p − n = p from either side)
        assertEquals(0, new ShadowFrustum().originOf(px, py + ny, pz + nz, 0, 1, 1), "TC14: no ray origins set");
        frustum.setOrigins(px, py, pz, 0, 0, 0);
        assertEquals(0, frustum.originOf(px, py, pz, 0, 1, 1), "TC14: a zero offset sets no ray origins");
    }

    /**
     * The ray origins a triangle lies behind, given by its vertices, its data placed after three zeros.
     *
     * @param frustum the frustum
     * @param v       the vertices p1, p2, p3
     * @return {@link ShadowFrustum#originsBehind} of p1, p2 − p1, p3 − p1
     */
    private static int originsBehind(ShadowFrustum frustum, double... v) {
        return frustum.originsBehind(triangleData(3, v), 3);
    }

    /**
     * A triangle of the plane z = h, around the z axis (from (−1, −1) to (1, 1)).
     *
     * @param h the height
     * @return the vertices
     */
    private static double[] flat(double h) {
        return new double[] { -1, -1, h, 1, -1, h, 0, 1, h };
    }

    /**
     * Test method for {@link ShadowFrustum#originsBehind}: which of the ray origins p ± n a triangle (grown by
     * the renderer's tolerance) lies behind by more than the rounding margin.
     * <p>
     * The standard pyramid 0.1 thick (margin 2.8e-6, plus the thickness for boxes and faces; the
     * origins need only the margin), p = (0, 0, 0), n = (0, 0, 0.1): the ray origins are (0, 0, ±0.1).
     */
    @Test
    void testOriginsBehind() {
        ShadowFrustum frustum = standard(0.1);
        frustum.setOrigins(0, 0, 0, 0, 0, 0.1);
        int both = ShadowFrustum.ABOVE | ShadowFrustum.BELOW;

        // ===== Equivalence Partitions Tests =====
        // TC01: a triangle of the surface (z = 0), between the origins: behind both
        assertEquals(both, originsBehind(frustum, flat(0)), "TC01: the surface's triangle lies behind both origins");
        // TC02: a slanted triangle within the slab (z from −0.05 to 0.05): behind both
        assertEquals(both, originsBehind(frustum, -1, -1, -0.05, 1, -1, -0.05, 0, 1, 0.05),
                "TC02: a triangle between the origins lies behind both");
        // TC03: a triangle below p − n (z = −0.5): behind p + n only
        assertEquals(ShadowFrustum.ABOVE, originsBehind(frustum, flat(-0.5)), "TC03: below both origins: ABOVE");
        // TC04: a triangle above p + n (z = 0.5): behind p − n only
        assertEquals(ShadowFrustum.BELOW, originsBehind(frustum, flat(0.5)), "TC04: above both origins: BELOW");
        // TC05: a triangle crossing the surface from z = −1 to 1: behind neither
        assertEquals(0, originsBehind(frustum, -1, -1, -1, 1, -1, -1, 0, 1, 1), "TC05: a crossing triangle: 0");
        // TC06: a triangle crossing only the plane of p + n (z from 0 to 0.2): behind p − n only
        assertEquals(ShadowFrustum.BELOW, originsBehind(frustum, -1, -1, 0, 1, -1, 0, 0, 1, 0.2),
                "TC06: crossing the plane of p + n: BELOW");
        // TC07: a slanted n, (0.06, 0, 0.08), and the plane 0.6x + 0.8z = 0 through p: behind both
        ShadowFrustum slant = standard(0.1);
        slant.setOrigins(0, 0, 0, 0.06, 0, 0.08);
        assertEquals(both, originsBehind(slant, -0.8, -1, 0.6, 0.8, -1, -0.6, 0, 1, 0), "TC07: a slanted surface");

        // ===== Boundary Values Tests =====
        // TC11: a triangle in the plane of p + n (z = 0.1): not behind it, behind p − n
        assertEquals(ShadowFrustum.BELOW, originsBehind(frustum, flat(0.1)), "TC11: in the plane of p + n");
        // TC12: in the plane of p − n (z = −0.1): behind p + n only
        assertEquals(ShadowFrustum.ABOVE, originsBehind(frustum, flat(-0.1)), "TC12: in the plane of p − n");
        // TC13: 1e-6 behind p + n (within the margin 2.8e-6): not behind it; 1e-5 behind it: behind both
        assertEquals(ShadowFrustum.BELOW, originsBehind(frustum, flat(0.1 - 1e-6)), "TC13: within the margin");
        assertEquals(both, originsBehind(frustum, flat(0.1 - 1e-5)), "TC13: beyond the margin");
        // TC14: the same below p − n
        assertEquals(ShadowFrustum.ABOVE, originsBehind(frustum, flat(-0.1 + 1e-6)), "TC14: within the margin");
        assertEquals(both, originsBehind(frustum, flat(-0.1 + 1e-5)), "TC14: beyond the margin");
        // TC15: a vertex 1e-4 behind p + n whose edges reach 1e5 down: the renderer's test grows it by
        // 1e-9 of its two edges, 2e-4 along n, past the origin: behind neither (without the growth: ABOVE)
        assertEquals(0, originsBehind(frustum, 0, 0, 0.1 - 1e-4, 1, 0, -1e5, 0, 1, -1e5),
                "TC15: a vertex grown past the origin");
        // TC16: no ray origins set (a fresh set forgets them): 0 for every triangle
        frustum = standard(0.1);
        assertEquals(0, originsBehind(frustum, flat(0)), "TC16: no ray origins after a new set");
        assertEquals(0, originsBehind(new ShadowFrustum(), flat(-0.5)), "TC16: no ray origins ever set");
    }

    /**
     * Whether a triangle lies behind both origins, given by its vertices, placed after a dummy vertex
     * (the third first, so the places are used as given).
     *
     * @param frustum the frustum
     * @param v       the vertices p1, p2, p3
     * @return {@link ShadowFrustum#behindOrigins} of them
     */
    private static boolean behindOrigins(ShadowFrustum frustum, double... v) {
        double[] vertices = { 0, 0, 0, v[6], v[7], v[8], v[0], v[1], v[2], v[3], v[4], v[5] };
        return frustum.behindOrigins(vertices, 6, 9, 3);
    }

    /**
     * Test method for {@link ShadowFrustum#behindOrigins}: true only when a triangle lies behind both
     * ray origins p ± n, as {@link ShadowFrustum#originsBehind} tells.
     * <p>
     * The standard pyramid 0.1 thick, p = (0, 0, 0), n = (0, 0, 0.1): the ray origins are (0, 0, ±0.1).
     */
    @Test
    void testBehindOrigins() {
        ShadowFrustum frustum = standard(0.1);
        frustum.setOrigins(0, 0, 0, 0, 0, 0.1);

        // ===== Equivalence Partitions Tests =====
        // TC01: a triangle of the surface (z = 0) between the origins (expects true)
        assertTrue(behindOrigins(frustum, flat(0)), "TC01: the surface's triangle lies behind both origins");
        // TC02: a slanted triangle within the slab (z −0.05..0.05) (expects true)
        assertTrue(behindOrigins(frustum, -1, -1, -0.05, 1, -1, -0.05, 0, 1, 0.05), "TC02: within the slab");
        // TC03: below p − n (z = −0.5), behind p + n only (expects false)
        assertFalse(behindOrigins(frustum, flat(-0.5)), "TC03: behind p + n only");
        // TC04: above p + n (z = 0.5), behind p − n only (expects false)
        assertFalse(behindOrigins(frustum, flat(0.5)), "TC04: behind p − n only");
        // TC05: crossing the surface from z = −1 to 1 (expects false)
        assertFalse(behindOrigins(frustum, -1, -1, -1, 1, -1, -1, 0, 1, 1), "TC05: a crossing triangle");
        // TC06: crossing the plane of p + n only (z 0..0.2) (expects false)
        assertFalse(behindOrigins(frustum, -1, -1, 0, 1, -1, 0, 0, 1, 0.2), "TC06: crossing the plane of p + n");
        // TC07: a slanted n (0.06, 0, 0.08), p = (1, 2, 3), a triangle of the plane 0.6x + 0.8z = 3.6 through p
        // (expects true); the same triangle moved 0.5 along n (expects false)
        ShadowFrustum slant = standard(0.1);
        slant.setOrigins(1, 2, 3, 0.06, 0, 0.08);
        assertTrue(behindOrigins(slant, 0.2, 1, 3.6, 1.8, 1, 2.4, 1, 3, 3), "TC07: a slanted surface");
        assertFalse(behindOrigins(slant, 0.5, 1, 4, 2.1, 1, 2.8, 1.3, 3, 3.4), "TC07: the slanted surface moved off");

        // ===== Boundary Values Tests =====
        // TC11: in the plane of p + n (z = 0.1) and of p − n (z = −0.1) (expects false)
        assertFalse(behindOrigins(frustum, flat(0.1)), "TC11: in the plane of p + n");
        assertFalse(behindOrigins(frustum, flat(-0.1)), "TC11: in the plane of p − n");
        // TC12: 1e-6 inside the slab (within the rounding margin 2.8e-6) (expects false); 1e-5 inside (expects true)
        assertFalse(behindOrigins(frustum, flat(0.1 - 1e-6)), "TC12: within the margin of p + n");
        assertFalse(behindOrigins(frustum, flat(-0.1 + 1e-6)), "TC12: within the margin of p − n");
        assertTrue(behindOrigins(frustum, flat(0.1 - 1e-5)), "TC12: beyond the margin of p + n");
        assertTrue(behindOrigins(frustum, flat(-0.1 + 1e-5)), "TC12: beyond the margin of p − n");
        // TC13: a triangle across the slab, from z = −0.1 + 1e-5 to 0.1 − 1e-5 (expects true); reaching
        // within the margin of p − n, −0.1 + 1e-6 (expects false)
        assertTrue(behindOrigins(frustum, -1, -1, -0.1 + 1e-5, 1, -1, -0.1 + 1e-5, 0, 1, 0.1 - 1e-5),
                "TC13: across the slab, beyond the margins");
        assertFalse(behindOrigins(frustum, -1, -1, -0.1 + 1e-6, 1, -1, -0.1 + 1e-5, 0, 1, 0.1 - 1e-5),
                "TC13: across the slab, one vertex within the margin of p − n");
        // TC14: no ray origins ever set, and after a new set (expects false)
        assertFalse(behindOrigins(new ShadowFrustum(), flat(0)), "TC14: no ray origins ever set");
        frustum = standard(0.1);
        assertFalse(behindOrigins(frustum, flat(0)), "TC14: a new set forgets the ray origins");
        // TC15: ray origins set with n = 0 (expects false)
        frustum.setOrigins(0, 0, 0, 0, 0, 0);
        assertFalse(behindOrigins(frustum, flat(0)), "TC15: a zero offset sets no ray origins");
    }

    /**
     * Test method for {@link ShadowFrustum#behindOrigins} against {@link ShadowFrustum#originsBehind}
     * on seeded random ray origins and triangles: true exactly when the triangle lies behind both.
     */
    @Test
    void testBehindOriginsRandom() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 200 random ray origins (p in [−20, 20]³, n of random direction and length 1e-3..1) × 50 random
        // triangles about p (vertices up to 1e-3..10 from p + a random height along n, heights mostly within
        // the slab) (expects behindOrigins == (originsBehind == ABOVE | BELOW) for every triangle)
        Random rnd = new Random(20261203);
        int both = ShadowFrustum.ABOVE | ShadowFrustum.BELOW;
        int[] kinds = new int[4];
        ShadowFrustum frustum = standard(0.1);
        for (int s = 0; s < 200; ++s) {
            double[] p = { 40 * rnd.nextDouble() - 20, 40 * rnd.nextDouble() - 20, 40 * rnd.nextDouble() - 20 };
            double[] n = strayVector(rnd, Math.pow(10, -3 + 3 * rnd.nextDouble()));
            double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            frustum.setOrigins(p[0], p[1], p[2], n[0], n[1], n[2]);
            for (int t = 0; t < 50; ++t) {
                double size = Math.pow(10, -3 + 4 * rnd.nextDouble());
                double[] v = new double[9];
                for (int i = 0; i < 3; ++i) {
                    // a height along n from −1.5 to 1.5 times |n|, plus a random offset across
                    double height = 3 * rnd.nextDouble() - 1.5;
                    double[] across = strayVector(rnd, size);
                    double along = (across[0] * n[0] + across[1] * n[1] + across[2] * n[2]) / (length * length);
                    for (int k = 0; k < 3; ++k)
                        v[3 * i + k] = p[k] + height * n[k] + across[k] - along * n[k];
                }
                int behind = originsBehind(frustum, v);
                ++kinds[behind];
                int number = t;
                assertEquals(behind == both, behindOrigins(frustum, v), () -> "TC01: origins p " + Arrays.toString(p)
                        + " n " + Arrays.toString(n) + ", triangle " + number + " " + Arrays.toString(v)
                        + ": originsBehind " + behind);
            }
        }
        // every answer of originsBehind is common: the comparison is not vacuous
        for (int kind = 0; kind < 4; ++kind)
            assertTrue(kinds[kind] >= 500, "TC01: too few triangles behind origins " + kind + ": " + kinds[kind]);
    }

    /** Test method for {@link ShadowFrustum#hasOrigins}. */
    @Test
    void testHasOrigins() {
        ShadowFrustum frustum = new ShadowFrustum();

        // ===== Equivalence Partitions Tests =====
        // TC01: a new frustum (expects false)
        assertFalse(frustum.hasOrigins(), "TC01: a new frustum has no ray origins");
        // TC02: after set (expects false)
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0.1),
                "TC02: the pyramid must be set");
        assertFalse(frustum.hasOrigins(), "TC02: set gives no ray origins");
        // TC03: setOrigins with a non-zero n (expects true)
        frustum.setOrigins(1, 2, 3, 0, 0.1, 0);
        assertTrue(frustum.hasOrigins(), "TC03: setOrigins with a non-zero offset");
        // TC04: a new set after setOrigins (expects false)
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0.1),
                "TC04: the pyramid must be set");
        assertFalse(frustum.hasOrigins(), "TC04: a new set forgets the ray origins");

        // ===== Boundary Values Tests =====
        // TC11: setOrigins with n = 0 (expects false), also right after a non-zero n
        frustum.setOrigins(1, 2, 3, 0, 0, 0);
        assertFalse(frustum.hasOrigins(), "TC11: a zero offset sets no ray origins");
        frustum.setOrigins(1, 2, 3, 0, 0, -0.1);
        assertTrue(frustum.hasOrigins(), "TC11: a non-zero offset sets ray origins");
        frustum.setOrigins(1, 2, 3, 0, 0, 0);
        assertFalse(frustum.hasOrigins(), "TC11: a zero offset takes the ray origins away");
        // TC12: the smallest non-zero n, one coordinate Double.MIN_VALUE (expects true)
        frustum.setOrigins(1, 2, 3, Double.MIN_VALUE, 0, 0);
        assertTrue(frustum.hasOrigins(), "TC12: a tiny offset still sets ray origins");
        // TC13: a refused (flat) set after setOrigins (expects false)
        assertFalse(frustum.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0.1),
                "TC13: the flat pyramid must be refused");
        assertFalse(frustum.hasOrigins(), "TC13: a refused set forgets the ray origins too");
    }

    /** Test method for {@link ShadowFrustum#meetsPlane}. */
    @Test
    void testMeetsPlane() {
        ShadowFrustum frustum = standard();
        double s = Math.sqrt(0.5);

        // ===== Equivalence Partitions Tests =====
        // TC01: the plane z = 5 crosses the pyramid: true
        assertTrue(frustum.meetsPlane(0, 0, 1, 0, 0, 5), "TC01: a crossing plane must be met");
        // TC02: a slanted plane through the middle of the pyramid: true
        assertTrue(frustum.meetsPlane(0.6, 0, 0.8, 0, 0, 5), "TC02: a slanted crossing plane must be met");
        // TC03: the plane z = −1, below all the vertices: false
        assertFalse(frustum.meetsPlane(0, 0, 1, 0, 0, -1), "TC03: a plane behind the apex must not be met");
        // TC04: the plane z = 11, parallel to the base beyond it: false (either normal direction)
        assertFalse(frustum.meetsPlane(0, 0, 1, 3, 4, 11), "TC04: a plane beyond the base must not be met");
        assertFalse(frustum.meetsPlane(0, 0, -1, 3, 4, 11), "TC04: the flipped plane beyond the base neither");
        // TC05: the plane x = 3, beside the pyramid: false
        assertFalse(frustum.meetsPlane(1, 0, 0, 3, 0, 0), "TC05: a plane beside the pyramid must not be met");

        // ===== Boundary Values Tests =====
        // TC11: the plane z = 0 through the apex only: true
        assertTrue(frustum.meetsPlane(0, 0, 1, 0, 0, 0), "TC11: a plane through the apex must be met");
        // TC12: the plane x + y = 4 touching only the base corner (2, 2, 10): true
        assertTrue(frustum.meetsPlane(s, s, 0, 2, 2, 0), "TC12: a plane touching a base corner must be met");
        // TC13: the base's own plane z = 10: true
        assertTrue(frustum.meetsPlane(0, 0, 1, 0, 0, 10), "TC13: the base's plane must be met");
        // TC14: a side's own plane x = z/5: true
        double len = Math.sqrt(1.04);
        assertTrue(frustum.meetsPlane(1 / len, 0, -0.2 / len, 0, 0, 0), "TC14: a side's plane must be met");
        // TC15: z = −1e-6 (within the margin 2.8e-6 of the apex): true; z = −1e-4: false
        assertTrue(frustum.meetsPlane(0, 0, 1, 0, 0, -1e-6), "TC15: a plane within the margin must be met");
        assertFalse(frustum.meetsPlane(0, 0, 1, 0, 0, -1e-4), "TC15: a plane beyond the margin must not be met");
        // TC16: x + y = 4 + 1e-4 (just past the corner): false
        assertFalse(frustum.meetsPlane(s, s, 0, 2 + 5e-5, 2 + 5e-5, 0),
                "TC16: a plane past the corner must not be met");
    }

    /**
     * Test method for {@link ShadowFrustum#meetsBox(double[], int)} and {@link ShadowFrustum#meetsPlane}
     * of a thick pyramid: the standard pyramid 0.5 thick keeps what lies outside it by less than 0.5
     * (plus the margin 2.8e-6) and sets aside what lies clearly farther.
     */
    @Test
    void testThickness() {
        ShadowFrustum thick = standard(0.5);
        ShadowFrustum thin = standard();
        double len = Math.sqrt(1.04);
        double s = Math.sqrt(0.5);

        // ===== Equivalence Partitions Tests =====
        // Boxes. The side x = z/5: a box x from 1 + ε to 2, z 0..5 is ε/√1.04 outside it.
        // TC01: outside the side by 0.392 (ε = 0.4): kept by the thick pyramid, set aside by the thin one
        assertTrue(meets(thick, 1.4, -0.1, 0, 2, 0.1, 5), "TC01: a box 0.392 outside a side is within the thickness");
        assertFalse(meets(thin, 1.4, -0.1, 0, 2, 0.1, 5), "TC01: without thickness the box is outside");
        // TC02: outside the side by 0.588 (ε = 0.6): set aside
        assertFalse(meets(thick, 1.6, -0.1, 0, 2, 0.1, 5), "TC02: a box 0.588 outside a side is beyond the thickness");
        // TC03: behind the apex by 0.4 (z −1..−0.4): kept; by 0.6 (z −1..−0.6): set aside
        assertTrue(meets(thick, -1, -1, -1, 1, 1, -0.4), "TC03: a box 0.4 behind the apex is within the thickness");
        assertFalse(meets(thick, -1, -1, -1, 1, 1, -0.6), "TC03: a box 0.6 behind the apex is beyond the thickness");
        // TC04: beyond the base by 0.4 (z 10.4..11): kept; by 0.6 (z 10.6..11): set aside
        assertTrue(meets(thick, -1, -1, 10.4, 1, 1, 11), "TC04: a box 0.4 beyond the base is within the thickness");
        assertFalse(meets(thick, -1, -1, 10.6, 1, 1, 11), "TC04: a box 0.6 beyond the base is beyond the thickness");
        // TC05: beside the bounding box (x from 2.4, z 9.5..10, 0.392 off the side x = z/5): kept; from
        // x 2.6 (0.588 off the side, 0.6 off the bounding box): set aside
        assertTrue(meets(thick, 2.4, -0.1, 9.5, 3, 0.1, 10),
                "TC05: a box 0.392 beside the base is within the thickness");
        assertFalse(meets(thick, 2.6, -0.1, 9.5, 3, 0.1, 10),
                "TC05: a box 0.588 beside the base is beyond the thickness");
        // TC06: a box inside the pyramid stays met: true
        assertTrue(meets(thick, -0.5, -0.5, 4, 0.5, 0.5, 5), "TC06: a box inside the thick pyramid must be met");
        // Planes.
        // TC07: the plane z = −0.4 (either normal): kept; z = −0.6: set aside
        assertTrue(thick.meetsPlane(0, 0, 1, 0, 0, -0.4), "TC07: a plane 0.4 behind the apex is within the thickness");
        assertTrue(thick.meetsPlane(0, 0, -1, 0, 0, -0.4), "TC07: the flipped plane 0.4 behind the apex too");
        assertFalse(thin.meetsPlane(0, 0, 1, 0, 0, -0.4), "TC07: without thickness the plane is outside");
        assertFalse(thick.meetsPlane(0, 0, 1, 0, 0, -0.6), "TC07: a plane 0.6 behind the apex is beyond the thickness");
        assertFalse(thick.meetsPlane(0, 0, -1, 0, 0, -0.6), "TC07: the flipped plane 0.6 behind the apex too");
        // TC08: the plane z = 10.4 beyond the base: kept; z = 10.6: set aside
        assertTrue(thick.meetsPlane(0, 0, 1, 0, 0, 10.4), "TC08: a plane 0.4 beyond the base is within the thickness");
        assertFalse(thick.meetsPlane(0, 0, 1, 0, 0, 10.6), "TC08: a plane 0.6 beyond the base is beyond the thickness");
        // TC09: the plane x = 2.4 beside the base: kept; x = 2.6: set aside
        assertTrue(thick.meetsPlane(1, 0, 0, 2.4, 0, 0), "TC09: a plane 0.4 beside the base is within the thickness");
        assertFalse(thick.meetsPlane(1, 0, 0, 2.6, 0, 0), "TC09: a plane 0.6 beside the base is beyond the thickness");
        // TC10: the plane x + y = 4 + 0.4·√2, 0.4 past the corner (2, 2, 10): kept; 0.6 past it: set aside
        assertTrue(thick.meetsPlane(s, s, 0, 2 + 0.4 * s, 2 + 0.4 * s, 0), "TC10: a plane 0.4 past a corner is kept");
        assertFalse(thick.meetsPlane(s, s, 0, 2 + 0.6 * s, 2 + 0.6 * s, 0),
                "TC10: a plane 0.6 past a corner is set aside");

        // ===== Boundary Values Tests =====
        // TC11: a box behind the apex by exactly the thickness 0.5: kept; by 0.5 + 1e-6 (within the margin
        // 2.8e-6): kept; by 0.5 + 1e-4: set aside
        assertTrue(meets(thick, -1, -1, -1, 1, 1, -0.5), "TC11: a box the thickness behind the apex must be kept");
        assertTrue(meets(thick, -1, -1, -1, 1, 1, -0.5 - 1e-6), "TC11: a box within thickness + margin must be kept");
        assertFalse(meets(thick, -1, -1, -1, 1, 1, -0.5 - 1e-4),
                "TC11: a box beyond thickness + margin must be set aside");
        // TC12: a box outside the side x = z/5 by 0.5 + 1e-6: kept; by 0.5 + 1e-4: set aside
        assertTrue(meets(thick, 1 + (0.5 + 1e-6) * len, -0.1, 0, 2, 0.1, 5),
                "TC12: within thickness + margin of a side");
        assertFalse(meets(thick, 1 + (0.5 + 1e-4) * len, -0.1, 0, 2, 0.1, 5),
                "TC12: beyond thickness + margin of a side");
        // TC13: the plane z = −0.5 − 1e-6: kept; z = −0.5 − 1e-4: set aside
        assertTrue(thick.meetsPlane(0, 0, 1, 0, 0, -0.5 - 1e-6),
                "TC13: a plane within thickness + margin must be kept");
        assertFalse(thick.meetsPlane(0, 0, 1, 0, 0, -0.5 - 1e-4),
                "TC13: a plane beyond thickness + margin must be set aside");
        // TC14: the same instance set again with thickness 0: the box and plane of TC01/TC07 are set aside again
        assertTrue(thick.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC14: the thin pyramid must be set");
        assertFalse(meets(thick, 1.4, -0.1, 0, 2, 0.1, 5), "TC14: the thickness must not outlive its set");
        assertFalse(thick.meetsPlane(0, 0, 1, 0, 0, -0.4), "TC14: the thickness must not outlive its set");
    }

    /**
     * Test method for {@link ShadowFrustum#meetsBox(double[], int)} and {@link ShadowFrustum#meetsPlane}
     * after a refused {@link ShadowFrustum#set} (a flat pyramid), or before any set: nothing is set aside.
     */
    @Test
    void testRefusedSet() {
        // a box and a plane far from any pyramid used here, and a box and a plane the standard pyramid rejects
        double[] far = { 1000, 1000, 1000, 1001, 1001, 1001 };

        // ===== Equivalence Partitions Tests =====
        // TC01: a new instance, never set: every box and plane is met
        ShadowFrustum fresh = new ShadowFrustum();
        assertTrue(meets(fresh, far), "TC01: an unset frustum must set no box aside");
        assertTrue(fresh.meetsPlane(1, 0, 0, 1000, 0, 0), "TC01: an unset frustum must set no plane aside");
        // TC02: a new instance whose first set is refused (apex at the base's centre): everything met
        assertFalse(fresh.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC02: the flat pyramid must be refused");
        assertTrue(meets(fresh, far), "TC02: a refused frustum must set no box aside");
        assertTrue(meets(fresh, -1, -1, -2, 1, 1, -1), "TC02: a refused frustum must set no box aside");
        assertTrue(fresh.meetsPlane(1, 0, 0, 1000, 0, 0), "TC02: a refused frustum must set no plane aside");
        assertTrue(fresh.meetsPlane(0, 0, 1, 0, 0, -1), "TC02: a refused frustum must set no plane aside");
        // TC03: a proper set rejects the box behind the apex and the plane z = −1; a refused set after it
        // (apex in the base's plane, outside the base) keeps them, and every far box and plane
        ShadowFrustum frustum = standard();
        assertFalse(meets(frustum, -1, -1, -2, 1, 1, -1), "TC03: the proper pyramid rejects the box behind it");
        assertFalse(frustum.meetsPlane(0, 0, 1, 0, 0, -1), "TC03: the proper pyramid rejects the plane behind it");
        assertFalse(frustum.set(new double[] { 5, 7, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC03: the flat pyramid must be refused");
        assertTrue(meets(frustum, -1, -1, -2, 1, 1, -1), "TC03: after a refused set the box must be met");
        assertTrue(frustum.meetsPlane(0, 0, 1, 0, 0, -1), "TC03: after a refused set the plane must be met");
        assertTrue(meets(frustum, far), "TC03: after a refused set a far box must be met");
        assertTrue(frustum.meetsPlane(0, 0, -1, 0, 0, 1000), "TC03: after a refused set a far plane must be met");

        // ===== Boundary Values Tests =====
        // TC11: refused for a degenerate base (a = 0) after a proper thick set: everything met
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0.1),
                "TC11: the proper pyramid must be set");
        assertFalse(meets(frustum, far), "TC11: the proper pyramid rejects the far box");
        assertFalse(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 0, 0, 0, 0, 2, 0 }, 0.1),
                "TC11: a = 0 must be refused");
        assertTrue(meets(frustum, far), "TC11: after a refused set the far box must be met");
        assertTrue(frustum.meetsPlane(1, 0, 0, 1000, 0, 0), "TC11: after a refused set the far plane must be met");
        // TC12: refused for a pyramid just too low (1e-12): everything met
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC12: the proper pyramid must be set");
        assertFalse(frustum.set(new double[] { 0, 0, 10 - 1e-12 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC12: the low pyramid must be refused");
        assertTrue(meets(frustum, far), "TC12: after a refused set the far box must be met");
        assertTrue(frustum.meetsPlane(0, 0, 1, 0, 0, -1), "TC12: after a refused set the plane behind must be met");
        // TC13: a proper set after the refused one sets boxes and planes aside again
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC13: the proper pyramid must be set");
        assertFalse(meets(frustum, far), "TC13: the proper pyramid must reject the far box again");
        assertFalse(frustum.meetsPlane(0, 0, 1, 0, 0, -1), "TC13: the proper pyramid must reject the plane again");
        assertTrue(meets(frustum, -0.5, -0.5, 4, 0.5, 0.5, 5), "TC13: the proper pyramid must meet a box inside it");
    }

    /**
     * Test method for {@link ShadowFrustum#meetsBox(double[], int)} and {@link ShadowFrustum#meetsPlane}
     * on seeded random pyramids, thin and thick: a set-aside box holds none of 200 sampled points of
     * segments the bundle's rays may cover (from the apex to the base, each end moved by up to the
     * thickness), and a set-aside plane separates none of 200 such segments.
     */
    @Test
    void testRandomPyramids() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 400 random pyramids, a quarter of them thin (thickness 0), the others 1e-4 to 1 thick
        // (log-uniform), × 40 random boxes near them (about a random point of a segment, shifted by up to
        // twice their size plus the thickness) and 20 random planes through a point near them
        Random rnd = new Random(20260112);
        int boxesRejected = 0;
        int boxesMet = 0;
        int planesRejected = 0;
        int planesMet = 0;
        // what only the thickness kept: the answers of the same pyramid without it differ
        int boxesThickOnly = 0;
        int planesThickOnly = 0;
        ShadowFrustum frustum = new ShadowFrustum();
        ShadowFrustum thin = new ShadowFrustum();
        for (int f = 0; f < 400; ++f) {
            double[] p = randomPyramid(rnd);
            double thickness = f % 4 == 0 ? 0 : Math.pow(10, -4 + 4 * rnd.nextDouble());
            if (!setPyramid(frustum, p, thickness))
                continue;
            assertTrue(setPyramid(thin, p, 0),
                    "TC01: the thickness must not change whether a pyramid is flat");
            double[][] segments = new double[200][];
            double[][] samples = new double[200][];
            for (int i = 0; i < segments.length; ++i) {
                segments[i] = raySegment(rnd, p, thickness);
                samples[i] = segmentPoint(rnd, raySegment(rnd, p, thickness));
            }
            String pyramid = Arrays.toString(p) + " thickness " + thickness;
            for (int b = 0; b < 40; ++b) {
                double[] centre = segmentPoint(rnd, raySegment(rnd, p, thickness));
                double size = Math.pow(10, -3 + 3.5 * rnd.nextDouble());
                double[] box = new double[6];
                for (int k = 0; k < 3; ++k) {
                    double middle = centre[k] + (2 * size + thickness) * (2 * rnd.nextDouble() - 1);
                    double half = size * rnd.nextDouble();
                    box[k] = middle - half;
                    box[3 + k] = middle + half;
                }
                if (frustum.meetsBox(box, 0)) {
                    ++boxesMet;
                    if (!thin.meetsBox(box, 0))
                        ++boxesThickOnly;
                    continue;
                }
                ++boxesRejected;
                for (double[] q : samples)
                    if (holds(box, q))
                        fail("TC01: pyramid " + pyramid + " set aside the box " + Arrays.toString(box)
                                + " that holds the point " + Arrays.toString(q) + " of a ray");
            }
            for (int pl = 0; pl < 20; ++pl) {
                double[] q = segmentPoint(rnd, raySegment(rnd, p, thickness));
                double scale = Math.pow(10, -2 + 3 * rnd.nextDouble()) + thickness;
                double nx = rnd.nextGaussian();
                double ny = rnd.nextGaussian();
                double nz = rnd.nextGaussian();
                double norm = Math.sqrt(nx * nx + ny * ny + nz * nz);
                nx /= norm;
                ny /= norm;
                nz /= norm;
                double qx = q[0] + scale * rnd.nextGaussian();
                double qy = q[1] + scale * rnd.nextGaussian();
                double qz = q[2] + scale * rnd.nextGaussian();
                if (frustum.meetsPlane(nx, ny, nz, qx, qy, qz)) {
                    ++planesMet;
                    if (!thin.meetsPlane(nx, ny, nz, qx, qy, qz))
                        ++planesThickOnly;
                    continue;
                }
                ++planesRejected;
                // every end of every segment lies strictly on the side of the (unmoved) apex
                double apex = nx * (p[0] - qx) + ny * (p[1] - qy) + nz * (p[2] - qz);
                for (double[] e : segments) {
                    double start = nx * (e[0] - qx) + ny * (e[1] - qy) + nz * (e[2] - qz);
                    double end = nx * (e[3] - qx) + ny * (e[4] - qy) + nz * (e[5] - qz);
                    if (!(apex * start > 0 && apex * end > 0))
                        fail("TC01: pyramid " + pyramid + " set aside the plane through (" + qx + ", " + qy + ", "
                                + qz + ") normal (" + nx + ", " + ny + ", " + nz + ") that crosses the ray "
                                + Arrays.toString(e));
                }
            }
        }
        // the boxes and planes are placed so that both answers are common, and so that the thickness
        // decides often: the test is not vacuous
        assertTrue(boxesRejected > 1000 && boxesMet > 1000,
                "TC01: too few set-aside (" + boxesRejected + ") or met (" + boxesMet + ") boxes");
        assertTrue(planesRejected > 300 && planesMet > 300,
                "TC01: too few set-aside (" + planesRejected + ") or met (" + planesMet + ") planes");
        assertTrue(boxesThickOnly > 100 && planesThickOnly > 30, "TC01: the thickness decided too rarely (boxes "
                + boxesThickOnly + ", planes " + planesThickOnly + ")");
    }

    /**
     * Whether a segment meets a triangle by the renderer's closed test ({@link Triangle#intersect}).
     *
     * @param segment {start, end}
     * @param v       the vertices p1, p2, p3
     * @return true when the segment hits the triangle
     */
    private static boolean hits(double[] segment, double[] v) {
        double dx = segment[3] - segment[0];
        double dy = segment[4] - segment[1];
        double dz = segment[5] - segment[2];
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        return length > 0 && triangle(v).nearestHit(new RayState().set(segment[0], segment[1], segment[2],
                dx / length, dy / length, dz / length, length)) < Geometry.NO_HIT;
    }

    /**
     * Test method for {@link ShadowFrustum#meetsTriangle} on seeded random pyramids, thin and thick: a
     * set-aside triangle is hit by none of 200 segments the bundle's rays may cover.
     */
    @Test
    void testRandomTriangles() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 300 random pyramids, a quarter of them thin, the others 1e-4 to 1 thick (log-uniform), × 40
        // random triangles near them (vertices about a random point of a segment, up to 1e-3 to 30 apart)
        Random rnd = new Random(20261201);
        int rejected = 0;
        int met = 0;
        // set aside though the triangle's box meets the pyramid: what the triangle test adds
        int boxMet = 0;
        ShadowFrustum frustum = new ShadowFrustum();
        for (RandomBundle bundle : RandomBundle.walk(rnd, frustum, 300)) {
            double[] p = bundle.pyramid();
            double thickness = bundle.thickness();
            double[][] segments = bundle.segments();
            for (int t = 0; t < 40; ++t) {
                double[] centre = segmentPoint(rnd, raySegment(rnd, p, thickness));
                double size = Math.pow(10, -3 + 4.5 * rnd.nextDouble());
                double[] v = new double[9];
                for (int k = 0; k < 9; ++k)
                    v[k] = centre[k % 3] + size * (2 * rnd.nextDouble() - 1) + (size + thickness) * rnd.nextGaussian();
                if (meetsTriangle(frustum, v)) {
                    ++met;
                    continue;
                }
                ++rejected;
                double[] box = new double[6];
                Triangle.bounds(v, 0, 3, 6, box, 0);
                if (frustum.meetsBox(box, 0))
                    ++boxMet;
                for (double[] e : segments)
                    if (hits(e, v))
                        fail("TC01: pyramid " + Arrays.toString(p) + " thickness " + thickness + " set aside the"
                                + " triangle " + Arrays.toString(v) + " that the ray " + Arrays.toString(e) + " hits");
            }
        }
        // both answers are common, and many set-aside triangles have boxes that meet the pyramid
        assertTrue(rejected > 1000 && met > 1000, "TC01: too few set-aside (" + rejected + ") or met (" + met
                + ") triangles");
        assertTrue(boxMet > 100, "TC01: too few triangles set aside only by the triangle test: " + boxMet);
    }
}
