package accel;

import static accel.BvhFixtures.built;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestScenes.randomSphere;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Geometry;
import geometries.Sphere;
import primitives.Point3D;

/** Unit tests for {@link BvhNodes}, the flat nodes: their shape, their boxes in floats and their slab test. */
class BvhNodesTest {
    private static final double DELTA = 1e-6;

    /** Two unit spheres, at the origin and at (4, 0, 0): a root box of about [−1, 5] × [−1, 1] × [−1, 1]. */
    private static BvhNodes twoSpheres() {
        return new BvhNodes(built(new Sphere(Point3D.ZERO, 1), new Sphere(new Point3D(4, 0, 0), 1)));
    }

    /** A ray from a point along a direction, inverted for the slab test. */
    private static RayState ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new RayState().set(ox, oy, oz, dx, dy, dz, Double.POSITIVE_INFINITY).invert();
    }

    /**
     * Test method for {@link BvhNodes#BvhNodes(BvhBuilder)}: the builder's nodes kept, the two children
     * of an inner node neighbours inside its box, and every body in exactly one leaf.
     */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 300 random spheres: the builder's count and depth, children inside their parent,
        // leaves of 1 to 4 bodies covering the 300 bodies once each
        Random rnd = new Random(23);
        Geometry[] spheres = new Geometry[300];
        for (int i = 0; i < spheres.length; ++i)
            spheres[i] = randomSphere(rnd, 20, 0.1, 2);
        BvhBuilder builder = built(spheres);
        BvhNodes nodes = new BvhNodes(builder);
        assertEquals(builder.nodesCount, nodes.count, "TC01: wrong nodes count");
        assertEquals(builder.depth, nodes.depth, "TC01: wrong depth");
        int[] leafOf = new int[spheres.length];
        Arrays.fill(leafOf, -1);
        for (int node = 0; node < nodes.count; ++node) {
            int link = nodes.links[2 * node];
            int count = nodes.links[2 * node + 1];
            if (count < 0) {
                assertTrue(-1 - count <= 2, "TC01: node " + node + ": a split axis is 0, 1 or 2");
                assertTrue(link > node && link + 1 < nodes.count, "TC01: node " + node + ": children after it");
                assertInside(nodes.bounds, link, node, "TC01: node " + node + "'s left child");
                assertInside(nodes.bounds, link + 1, node, "TC01: node " + node + "'s right child");
            } else {
                assertTrue(count >= 1 && count <= 4, "TC01: leaf " + node + " holds " + count + " bodies");
                for (int b = link; b < link + count; ++b) {
                    assertEquals(-1, leafOf[b], "TC01: body " + b + " in two leaves");
                    leafOf[b] = node;
                }
            }
        }
        for (int b = 0; b < leafOf.length; ++b)
            assertTrue(leafOf[b] >= 0, "TC01: body " + b + " in no leaf");

        // ===== Boundary Values Tests =====
        // TC11: one body: one node, a leaf of body 0
        BvhNodes one = new BvhNodes(built(new Sphere(Point3D.ZERO, 1)));
        assertEquals(1, one.count, "TC11: one node");
        assertArrayEquals(new int[] { 0, 1 }, Arrays.copyOf(one.links, 2), "TC11: a leaf of body 0");
        // TC12: no body: no node
        assertEquals(0, new BvhNodes(built()).count, "TC12: no node");
    }

    /** Asserts that a node's box lies inside another's. */
    private static void assertInside(float[] bounds, int inner, int outer, String message) {
        for (int k = 0; k < 3; ++k) {
            assertTrue(bounds[6 * inner + k] >= bounds[6 * outer + k], message + ": low " + k + " outside");
            assertTrue(bounds[6 * inner + 3 + k] <= bounds[6 * outer + 3 + k], message + ": high " + k + " outside");
        }
    }

    /** Test method for {@link BvhNodes#roundOutward(double[], float[], int)}. */
    @Test
    void testRoundOutward() {
        // ===== Equivalence Partitions Tests =====
        // TC01: bounds no float holds exactly: the nearest floats outward (the low at or below, the high
        // at or above, and the next float inward on the wrong side)
        double[] box = { 0.1, -0.1, 1.0 / 3, 0.7, 2.2, 1e10 + 1 };
        float[] rounded = new float[6];
        BvhNodes.roundOutward(box, rounded, 0);
        for (int k = 0; k < 3; ++k) {
            assertTrue(rounded[k] <= box[k] && Math.nextUp(rounded[k]) > box[k], "TC01: low " + k);
            assertTrue(rounded[3 + k] >= box[3 + k] && Math.nextDown(rounded[3 + k]) < box[3 + k], "TC01: high " + k);
        }
        // TC02: the second box of two: the first left as it was
        float[] two = new float[12];
        BvhNodes.roundOutward(new double[] { 9, 9, 9, 9, 9, 9, 0.5, -2, 0, 1, 3, 4.25 }, two, 6);
        assertArrayEquals(new float[] { 0, 0, 0, 0, 0, 0, 0.5f, -2, 0, 1, 3, 4.25f }, two, "TC02");

        // ===== Boundary Values Tests =====
        // TC11: bounds that are floats: the same numbers
        float[] exact = new float[6];
        BvhNodes.roundOutward(new double[] { 0.5, -2, 0, 1, 3, 4.25 }, exact, 0);
        assertArrayEquals(new float[] { 0.5f, -2, 0, 1, 3, 4.25f }, exact, "TC11");
        // TC12: bounds a double above 1 and below 2: the low 1, the high 2
        float[] near = new float[6];
        BvhNodes.roundOutward(new double[] { Math.nextUp(1.0), 0, 0, Math.nextDown(2.0), 0, 0 }, near, 0);
        assertEquals(1f, near[0], "TC12: low");
        assertEquals(2f, near[3], "TC12: high");
    }

    /** Test method for {@link BvhNodes#entry(int, RayState, double)} on the root's box. */
    @Test
    void testEntry() {
        BvhNodes nodes = twoSpheres();
        // ===== Equivalence Partitions Tests =====
        // TC01: along +x from x = −10: the box entered at x = −1, 9
        assertEquals(9, nodes.entry(0, ray(-10, 0, 0, 1, 0, 0), 100), DELTA, "TC01");
        // TC02: along −y from (2, 7, 0): entered at y = 1, 6
        assertEquals(6, nodes.entry(0, ray(2, 7, 0, 0, -1, 0), 100), DELTA, "TC02");
        // TC03: along +x above the box (y = 5): missed
        assertEquals(RayState.MISSED, nodes.entry(0, ray(-10, 5, 0, 1, 0, 0), 100), "TC03");
        // TC04: away from the box: missed
        assertEquals(RayState.MISSED, nodes.entry(0, ray(-10, 0, 0, -1, 0, 0), 100), "TC04");

        // ===== Boundary Values Tests =====
        // TC11: from inside the box: 0
        assertEquals(0, nodes.entry(0, ray(2, 0, 0, 0, 0, 1), 100), "TC11");
        // TC12: the distance that counts ends before the box: missed
        assertEquals(RayState.MISSED, nodes.entry(0, ray(-10, 0, 0, 1, 0, 0), 8.5), "TC12");
        // TC13: the distance that counts ends at the box's face (rounded outward, entered at 9 or less)
        assertEquals(9, nodes.entry(0, ray(-10, 0, 0, 1, 0, 0), 9), DELTA, "TC13");
    }

    /** Test method for {@link BvhNodes#largestExtent()}. */
    @Test
    void testLargestExtent() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the two spheres: 6 along x
        assertEquals(6, twoSpheres().largestExtent(), DELTA, "TC01");
        // ===== Boundary Values Tests =====
        // TC11: no node: 0
        assertEquals(0, new BvhNodes(built()).largestExtent(), 0, "TC11");
    }
}
