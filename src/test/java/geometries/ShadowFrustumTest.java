package geometries;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link geometries.ShadowFrustum}: the pyramid from a lit point to a light's square,
 * and its conservative box and plane tests.
 * <p>
 * Most cases use the pyramid with apex (0, 0, 0) and base (±2, ±2, 10) (centre (0, 0, 10), a = (2, 0, 0),
 * b = (0, 2, 0)): its sides are the planes x = ±z/5 and y = ±z/5, its base the plane z = 10. Its size
 * (largest |coordinate| 10 plus the extents 4 + 4 + 10 of its bounding box) is 28, so its margin is
 * 28·1e-7 = 2.8e-6.
 */
class ShadowFrustumTest {
    /** The margin of the standard pyramid: 1e-7 of its size 28. */
    private static final double MARGIN = 2.8e-6;

    /**
     * The standard pyramid: apex (0, 0, 0), base (±2, ±2, 10).
     *
     * @return the frustum
     */
    private static ShadowFrustum standard() {
        ShadowFrustum frustum = new ShadowFrustum();
        assertTrue(frustum.set(0, 0, 0, 0, 0, 10, 2, 0, 0, 0, 2, 0), "the standard pyramid must be set");
        return frustum;
    }

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

    /** Test method for {@link ShadowFrustum#set}. */
    @Test
    void testSet() {
        ShadowFrustum frustum = new ShadowFrustum();

        // ===== Equivalence Partitions Tests =====
        // TC01: apex off the base's plane, a and b independent: true
        assertTrue(frustum.set(0, 0, 0, 0, 0, 10, 2, 0, 0, 0, 2, 0), "TC01: a proper pyramid must be set");
        // TC02: a slanted base (a, b not orthogonal, not along the axes) seen from aside: true
        assertTrue(frustum.set(1, -2, 3, 7, 5, -4, 1, 2, 0.5, -0.5, 1, 3), "TC02: a slanted pyramid must be set");
        // TC03: the apex in the base's plane (here its centre): false
        assertFalse(frustum.set(0, 0, 10, 0, 0, 10, 2, 0, 0, 0, 2, 0), "TC03: apex at the base's centre is flat");
        // TC04: the apex in the base's plane, outside the base: false
        assertFalse(frustum.set(5, 7, 10, 0, 0, 10, 2, 0, 0, 0, 2, 0), "TC04: apex in the base's plane is flat");
        // TC05: after a flat pyramid the same instance is set again properly: true, and it works
        assertTrue(frustum.set(0, 0, 0, 0, 0, 10, 2, 0, 0, 0, 2, 0), "TC05: a flat pyramid must not spoil the next set");
        assertTrue(meets(frustum, -0.5, -0.5, 4, 0.5, 0.5, 5), "TC05: the reset pyramid must meet a box inside it");
        assertFalse(meets(frustum, -0.5, -0.5, -2, 0.5, 0.5, -1), "TC05: the reset pyramid must reject a box behind it");

        // ===== Boundary Values Tests =====
        // TC11: a = 0 (the base is a segment): false
        assertFalse(frustum.set(0, 0, 0, 0, 0, 10, 0, 0, 0, 0, 2, 0), "TC11: a = 0 is a degenerate base");
        // TC12: b = 0: false
        assertFalse(frustum.set(0, 0, 0, 0, 0, 10, 2, 0, 0, 0, 0, 0), "TC12: b = 0 is a degenerate base");
        // TC13: a parallel to b: false
        assertFalse(frustum.set(0, 0, 0, 0, 0, 10, 2, 0, 0, -3, 0, 0), "TC13: a parallel to b is a degenerate base");
        // TC14: a and b both 0 (the base is a point): false
        assertFalse(frustum.set(0, 0, 0, 0, 0, 10, 0, 0, 0, 0, 0, 0), "TC14: a point base is degenerate");
        // TC15: the apex just off the base's plane (1e-3 of a size of 28, far above the flatness 2.8e-8): true
        assertTrue(frustum.set(0, 0, 10 - 1e-3, 0, 0, 10, 2, 0, 0, 0, 2, 0), "TC15: a very low pyramid is not flat");
        // TC16: the apex off the plane by 1e-12 (below the flatness): false
        assertFalse(frustum.set(0, 0, 10 - 1e-12, 0, 0, 10, 2, 0, 0, 0, 2, 0), "TC16: a pyramid this low counts as flat");
        // TC17: a tiny light (edge 2e-3) far away (distance 50): a thin pyramid, still true
        assertTrue(frustum.set(0, 0, 0, 0, 0, 50, 1e-3, 0, 0, 0, 1e-3, 0), "TC17: a thin pyramid must be set");
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
        assertTrue(meets(frustum, -1, -1, 10 + 1e-6, 1, 1, 11), "TC15: a box within the margin of the base must be met");
        assertFalse(meets(frustum, -1, -1, 10 + 1e-4, 1, 1, 11), "TC15: a box beyond the base's margin must not be met");
        // TC16: a box whose corner touches the apex from behind (max corner (0, 0, 0)): true
        assertTrue(meets(frustum, -1, -1, -1, 0, 0, 0), "TC16: a box touching the apex must be met");
        // TC17: a box touching a base corner (2, 2, 10) from outside (min corner there): true
        assertTrue(meets(frustum, 2, 2, 10, 3, 3, 11), "TC17: a box touching a base corner must be met");
        // TC18: a flat box (zero thickness) in the pyramid: true; a point box beside it: false
        assertTrue(meets(frustum, -0.5, -0.5, 5, 0.5, 0.5, 5), "TC18: a flat box inside must be met");
        assertFalse(meets(frustum, 1.8, 0, 2, 1.8, 0, 2), "TC18: a point box outside must not be met");
        // TC19: a margin of 2.8e-6 in the standard pyramid: a box 2e-6 behind the apex is met, 5e-6 behind it not
        assertTrue(meets(frustum, -1, -1, -1, 1, 1, -2e-6), "TC19: within the margin behind the apex");
        assertFalse(meets(frustum, -1, -1, -1, 1, 1, -5e-6), "TC19: beyond the margin (" + MARGIN + ") behind the apex");
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
        assertFalse(frustum.meetsPlane(s, s, 0, 2 + 5e-5, 2 + 5e-5, 0), "TC16: a plane past the corner must not be met");
    }

    /**
     * A random point of a pyramid: apex + t·(a base point − apex), the base point c + s·a + r·b with s,
     * r in [−1, 1]; some of them on the base's edges, corners and on the sides (t = 1, s or r = ±1).
     *
     * @param rnd the generator
     * @param p   the pyramid {apex, c, a, b}, 12 doubles
     * @return the point
     */
    private static double[] pyramidPoint(Random rnd, double[] p) {
        double t = rnd.nextInt(5) == 0 ? 1 : rnd.nextDouble();
        double s = rnd.nextInt(4) == 0 ? (rnd.nextBoolean() ? 1 : -1) : 2 * rnd.nextDouble() - 1;
        double r = rnd.nextInt(4) == 0 ? (rnd.nextBoolean() ? 1 : -1) : 2 * rnd.nextDouble() - 1;
        double[] point = new double[3];
        for (int k = 0; k < 3; ++k) {
            double base = p[3 + k] + s * p[6 + k] + r * p[9 + k];
            point[k] = p[k] + t * (base - p[k]);
        }
        return point;
    }

    /**
     * A random base point of a pyramid: c + s·a + r·b.
     *
     * @param rnd the generator
     * @param p   the pyramid {apex, c, a, b}
     * @return the point
     */
    private static double[] basePoint(Random rnd, double[] p) {
        double s = rnd.nextInt(4) == 0 ? (rnd.nextBoolean() ? 1 : -1) : 2 * rnd.nextDouble() - 1;
        double r = rnd.nextInt(4) == 0 ? (rnd.nextBoolean() ? 1 : -1) : 2 * rnd.nextDouble() - 1;
        double[] point = new double[3];
        for (int k = 0; k < 3; ++k)
            point[k] = p[3 + k] + s * p[6 + k] + r * p[9 + k];
        return point;
    }

    /**
     * A random pyramid: apex and base centre in [−20, 20]³, half-sides a and b of random directions
     * and lengths 0.01..5.
     *
     * @param rnd the generator
     * @return {apex, c, a, b}
     */
    private static double[] randomPyramid(Random rnd) {
        double[] p = new double[12];
        for (int k = 0; k < 6; ++k)
            p[k] = 40 * rnd.nextDouble() - 20;
        for (int v = 0; v < 2; ++v) {
            double length = 0.01 + 5 * rnd.nextDouble();
            double x = rnd.nextGaussian();
            double y = rnd.nextGaussian();
            double z = rnd.nextGaussian();
            double norm = Math.sqrt(x * x + y * y + z * z);
            p[6 + 3 * v] = x / norm * length;
            p[7 + 3 * v] = y / norm * length;
            p[8 + 3 * v] = z / norm * length;
        }
        return p;
    }

    /**
     * Test method for {@link ShadowFrustum#meetsBox(double[], int)} and {@link ShadowFrustum#meetsPlane}
     * on seeded random pyramids: a rejected box holds none of 200 sampled points of the pyramid, and a
     * rejected plane separates none of 200 sampled segments from the apex to the base.
     */
    @Test
    void testRandomPyramids() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 300 random pyramids × 40 random boxes near them (about a random point of the pyramid,
        // shifted by up to twice their size) and 20 random planes through a point near them
        Random rnd = new Random(20260112);
        int boxesRejected = 0;
        int boxesMet = 0;
        int planesRejected = 0;
        int planesMet = 0;
        ShadowFrustum frustum = new ShadowFrustum();
        for (int f = 0; f < 300; ++f) {
            double[] p = randomPyramid(rnd);
            if (!frustum.set(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], p[9], p[10], p[11]))
                continue;
            double[][] samples = new double[200][];
            double[][] bases = new double[200][];
            for (int i = 0; i < samples.length; ++i) {
                samples[i] = pyramidPoint(rnd, p);
                bases[i] = basePoint(rnd, p);
            }
            for (int b = 0; b < 40; ++b) {
                double[] centre = pyramidPoint(rnd, p);
                double size = Math.pow(10, -3 + 3.5 * rnd.nextDouble());
                double[] box = new double[6];
                for (int k = 0; k < 3; ++k) {
                    double middle = centre[k] + 2 * size * (2 * rnd.nextDouble() - 1);
                    double half = size * rnd.nextDouble();
                    box[k] = middle - half;
                    box[3 + k] = middle + half;
                }
                if (frustum.meetsBox(box, 0)) {
                    ++boxesMet;
                    continue;
                }
                ++boxesRejected;
                for (double[] q : samples)
                    if (q[0] >= box[0] && q[0] <= box[3] && q[1] >= box[1] && q[1] <= box[4] && q[2] >= box[2]
                            && q[2] <= box[5])
                        fail("TC01: pyramid " + Arrays.toString(p) + " rejected the box " + Arrays.toString(box)
                                + " that holds its point " + Arrays.toString(q));
            }
            for (int pl = 0; pl < 20; ++pl) {
                double[] q = pyramidPoint(rnd, p);
                double scale = Math.pow(10, -2 + 3 * rnd.nextDouble());
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
                    continue;
                }
                ++planesRejected;
                double apex = nx * (p[0] - qx) + ny * (p[1] - qy) + nz * (p[2] - qz);
                for (double[] e : bases) {
                    double end = nx * (e[0] - qx) + ny * (e[1] - qy) + nz * (e[2] - qz);
                    if (!(apex * end > 0))
                        fail("TC01: pyramid " + Arrays.toString(p) + " rejected the plane through (" + qx + ", " + qy
                                + ", " + qz + ") normal (" + nx + ", " + ny + ", " + nz
                                + ") that crosses the segment from the apex to " + Arrays.toString(e));
                }
            }
        }
        // the boxes and planes are placed so that both answers are common: the test is not vacuous
        assertTrue(boxesRejected > 1000 && boxesMet > 1000,
                "TC01: too few rejected (" + boxesRejected + ") or met (" + boxesMet + ") boxes");
        assertTrue(planesRejected > 300 && planesMet > 300,
                "TC01: too few rejected (" + planesRejected + ") or met (" + planesMet + ") planes");
    }
}
