package accel;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestBundles.STANDARD_MARGIN;
import static testutil.TestBundles.standard;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

import testutil.TestBundles.RandomBundle;

/**
 * Unit tests for {@link CoreCrossing}: whether every ray of a bundle passes through a closed mesh's
 * inner box, on its way to a base outside the mesh's box. Most cases use the standard pyramid ({@link testutil.TestBundles#standard}):
 * apex (0, 0, 0), base (±2, ±2, 10), its cross-section at height z the square of half-side z/5, its
 * margin {@value testutil.TestBundles#STANDARD_MARGIN}.
 */
class CoreCrossingTest {
    /**
     * Test method for {@link CoreCrossing#baseOutside} on the standard pyramid, whose base is the square
     * (±2, ±2) at z = 10.
     */
    @Test
    void testBaseOutside() {
        ShadowFrustum frustum = standard();
        // ===== Equivalence Partitions Tests =====
        // TC01: a box beside the pyramid, under the base's height: outside
        assertTrue(baseOutside(frustum, 20, 20, 0, 30, 30, 5), "TC01: a box away from the base");
        // TC02: a box around the whole base: not outside
        assertFalse(baseOutside(frustum, -5, -5, 5, 5, 5, 15), "TC02: a box around the base");

        // ===== Boundary Values Tests =====
        // TC11: the base (z = 10) against a box below it: its top at 10 − 1e-5 (beyond the margin): outside;
        // at 10 − 1e-6 (within the margin) and at 10 (touching): not outside
        assertTrue(baseOutside(frustum, -5, -5, 0, 5, 5, 10 - 1e-5), "TC11: a box below the base by 1e-5");
        assertFalse(baseOutside(frustum, -5, -5, 0, 5, 5, 10 - 1e-6), "TC11: a box within the margin of the base");
        assertFalse(baseOutside(frustum, -5, -5, 0, 5, 5, 10), "TC11: a box touching the base");
        // TC12: boxes beside the base along x (from x 2 + 1e-5, past the base's corners at x 2) and above
        // it (from z 10 + 1e-5): outside; a box around the base's corner (2, 2, 10): not outside
        assertTrue(baseOutside(frustum, 2 + 1e-5, -5, 0, 5, 5, 20), "TC12: a box beside the base along x");
        assertTrue(baseOutside(frustum, -5, -5, 10 + 1e-5, 5, 5, 20), "TC12: a box above the base");
        assertFalse(baseOutside(frustum, 1.9, 1.9, 9.9, 3, 3, 20), "TC12: a box around a corner of the base");
    }

    /**
     * Whether the base, grown by the thickness and margin, lies outside a box; the box is placed after a
     * dummy box in the array, so the offset is used.
     *
     * @param frustum the frustum
     * @param box     {minX, minY, minZ, maxX, maxY, maxZ}
     * @return {@link CoreCrossing#baseOutside}'s answer
     */
    private static boolean baseOutside(ShadowFrustum frustum, double... box) {
        double[] boxes = { -50, -50, -50, 50, 50, 50, 0, 0, 0, 0, 0, 0 };
        System.arraycopy(box, 0, boxes, 6, 6);
        return CoreCrossing.baseOutside(frustum, boxes, 6);
    }

    /** A check of a core near a random bundle's axis; {@return whether the bundle crosses the core} */
    private interface CoreCheck {
        boolean check(Random rnd, ShadowFrustum frustum, RandomBundle bundle, double corner);
    }

    /**
     * Checks 8 cores near the axis of each of 300 seeded random pyramids, a quarter of them thin, the
     * others 1e-4 to 1 thick (log-uniform).
     *
     * @param seed  the random seed
     * @param check the check of one core, given the reach of the base's corners from its centre
     * @return how many cores the bundles crossed and how many they did not
     */
    private static int[] forRandomCores(long seed, CoreCheck check) {
        Random rnd = new Random(seed);
        int[] counts = new int[2];
        ShadowFrustum frustum = new ShadowFrustum();
        for (RandomBundle bundle : RandomBundle.walk(rnd, frustum, 300)) {
            double[] p = bundle.pyramid();
            double corner = Math.max(Math.sqrt(squared(p[6] + p[9], p[7] + p[10], p[8] + p[11])),
                    Math.sqrt(squared(p[6] - p[9], p[7] - p[10], p[8] - p[11])));
            for (int b = 0; b < 8; ++b)
                ++counts[check.check(rnd, frustum, bundle, corner) ? 0 : 1];
        }
        return counts;
    }

    /** {@return the squared length of a vector} */
    private static double squared(double x, double y, double z) {
        return x * x + y * y + z * z;
    }

    /** {@return whether every ray of a bundle passes through a box, the box placed after a dummy one in the array} */
    private static boolean crossesBox(ShadowFrustum frustum, double... box) {
        double[] boxes = new double[12];
        System.arraycopy(box, 0, boxes, 6, 6);
        return CoreCrossing.crossesBox(frustum, boxes, 6);
    }

    /**
     * Test method for {@link CoreCrossing#crossesBox} on the standard pyramid, whose corner rays run
     * from the apex to (±2, ±2, 10): at height z they lie at (±z/5, ±z/5).
     */
    @Test
    void testCrossesBox() {
        ShadowFrustum frustum = standard();
        // ===== Equivalence Partitions Tests =====
        // TC01: a box across the axis, z 4..6, half-side 1.5 (the corner rays at 0.8 to 1.2 from it): true
        assertTrue(crossesBox(frustum, -1.5, -1.5, 4, 1.5, 1.5, 6), "TC01: a box across the pyramid");
        // TC02: a box beside the pyramid (x 3..5): false
        assertFalse(crossesBox(frustum, 3, -1, 4, 5, 1, 6), "TC02: a box beside the pyramid");
        // TC03: a wide box reaching beyond the base (z 8..12): false
        assertFalse(crossesBox(frustum, -3, -3, 8, 3, 3, 12), "TC03: a box reaching beyond the light");
        // TC04: a wide box behind the apex (z −6..−4): false
        assertFalse(crossesBox(frustum, -3, -3, -6, 3, 3, -4), "TC04: a box behind the apex");
        // TC05: a thin rod along the axis, half-side 0.5, z 1..9.9: every corner ray passes through it
        // near the apex (z up to 2.5), though none at the base: true
        assertTrue(crossesBox(frustum, -0.5, -0.5, 1, 0.5, 0.5, 9.9), "TC05: a rod the pyramid starts in");
        // TC06: a box across half the pyramid (x 0..3): the corner rays with x < 0 miss it: false
        assertFalse(crossesBox(frustum, 0, -3, 4, 3, 3, 6), "TC06: a box across half the pyramid");
        // TC07: a slanted pyramid, its base turned (apex (4, −2, 3), base (1, −2, 13) ± (2, 1, 0) ± (−1, 2, 0)),
        // and a box of half-side 1.6 around its axis at z 7..9, where its corner rays lie at most 1.5 from
        // the axis each way: true
        ShadowFrustum slanted = new ShadowFrustum();
        assertTrue(slanted.set(new double[] { 4, -2, 3 }, new double[] { 1, -2, 13, 2, 1, 0, -1, 2, 0 }, 0),
                "TC07: the slanted pyramid must be set");
        assertTrue(crossesBox(slanted, 2.5 - 1.6, -2 - 1.6, 7, 2.5 + 1.6, -2 + 1.6, 9),
                "TC07: a box across a slanted pyramid");
        // TC08: after a refused set (a flat pyramid), TC01's box: false
        ShadowFrustum refused = new ShadowFrustum();
        assertFalse(refused.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC08: the flat pyramid must be refused");
        assertFalse(crossesBox(refused, -1.5, -1.5, 4, 1.5, 1.5, 6), "TC08: a refused frustum crosses nothing");

        // ===== Boundary Values Tests =====
        // TC11: a slab z 4..4.001 of half-side w: the corner rays enter its shrunk box at z = 4 + m, at
        // 0.8 + m/5 from the axis, so w must reach 0.8 + 1.2 m: w = 0.8 + 2 m: true; 0.8 + m: false
        double m = STANDARD_MARGIN;
        double wide = 0.8 + 2 * m;
        double narrow = 0.8 + m;
        assertTrue(crossesBox(frustum, -wide, -wide, 4, wide, wide, 4.001), "TC11: a slab just wide enough");
        assertFalse(crossesBox(frustum, -narrow, -narrow, 4, narrow, narrow, 4.001), "TC11: a slab too narrow");
        // TC12: a box of half-side 0.85, z 4..4.5: thin: true; 0.1 thick (shrunk to 0.75, z from 4.1, where
        // the corner rays lie 0.82 away): false
        assertTrue(crossesBox(frustum, -0.85, -0.85, 4, 0.85, 0.85, 4.5), "TC12: the thin bundle");
        assertFalse(crossesBox(standard(0.1), -0.85, -0.85, 4, 0.85, 0.85, 4.5), "TC12: rays straying by 0.1");
        // TC13: a wide box whose top is the base's plane z = 10: false; 3 margins below it (beyond the
        // margin): true
        assertFalse(crossesBox(frustum, -3, -3, 8, 3, 3, 10), "TC13: a box touching the base's plane");
        assertTrue(crossesBox(frustum, -3, -3, 8, 3, 3, 10 - 3 * m), "TC13: a box 3 margins short of the base");
        // TC14: a box thinner than twice the margin: false
        assertFalse(crossesBox(frustum, -3, -3, 5, 3, 3, 5 + m), "TC14: a box thinner than the margins");
    }

    /**
     * Test method for {@link CoreCrossing#crossesBox} on seeded random pyramids, thin and thick, and
     * boxes about their axes: when it says every ray passes through a box, each of 200 segments the
     * bundle's rays may cover (from the apex to the base, each end moved by up to the thickness)
     * passes through the box.
     */
    @Test
    void testRandomBoxes() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 300 random pyramids × 8 boxes centred near the axis at λ −0.1 to 1.1, of half-sides
        // about the section's reach there, some of them long along the axis
        int[] counts = forRandomCores(20261204, (rnd, frustum, bundle, corner) -> {
            double[] p = bundle.pyramid();
            double lambda = 1.2 * rnd.nextDouble() - 0.1;
            double[] box = new double[6];
            for (int k = 0; k < 3; ++k) {
                double centre = p[k] + lambda * (p[3 + k] - p[k]);
                double half = Math.max(1e-3, lambda * corner * (0.5 + rnd.nextDouble())
                        + 2 * bundle.thickness() * rnd.nextDouble() + 0.3 * Math.abs(p[3 + k] - p[k]) * rnd.nextDouble());
                box[k] = centre - half;
                box[3 + k] = centre + half;
            }
            if (!crossesBox(frustum, box))
                return false;
            for (double[] e : bundle.segments())
                assertThroughBox(box, e, "pyramid " + Arrays.toString(p) + " thickness " + bundle.thickness()
                        + ", box " + Arrays.toString(box));
            return true;
        });
        // both answers are common: the test is not vacuous
        assertTrue(counts[0] > 200 && counts[1] > 200, "TC01: too few crossing (" + counts[0] + ") or missing ("
                + counts[1] + ") boxes");
    }

    /** Asserts that a segment {start, end} passes through a box. */
    private static void assertThroughBox(double[] box, double[] e, String label) {
        double dx = e[3] - e[0];
        double dy = e[4] - e[1];
        double dz = e[5] - e[2];
        double length = Math.sqrt(squared(dx, dy, dz));
        RayState ray = new RayState().set(e[0], e[1], e[2], dx / length, dy / length, dz / length, length).invert();
        assertTrue(ray.boxEntry(box, 0, length) != RayState.MISSED,
                () -> "TC01: " + label + ", segment " + Arrays.toString(e) + " must pass through the box");
    }
}
