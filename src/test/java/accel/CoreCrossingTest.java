package accel;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestBundles.STANDARD_MARGIN;
import static testutil.TestBundles.holds;
import static testutil.TestBundles.standard;

import java.util.Arrays;
import java.util.Random;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;

import primitives.Point3D;
import testutil.TestBundles.RandomBundle;

/**
 * Unit tests for {@link CoreCrossing}: whether every ray of a bundle passes through a closed mesh's
 * inner ball or inner box. Most cases use the standard pyramid ({@link testutil.TestBundles#standard}):
 * apex (0, 0, 0), base (±2, ±2, 10), its cross-section at height z the square of half-side z/5, its
 * margin {@value testutil.TestBundles#STANDARD_MARGIN}.
 */
class CoreCrossingTest {
    /**
     * Whether every ray of the bundle crosses a closed mesh, by its inner ball and its box; the box is
     * placed after a dummy box in the array (one the base lies in), so the offset is used.
     *
     * @param frustum the frustum
     * @param ball    the mesh's inner ball
     * @param box     the mesh's box, {minX, minY, minZ, maxX, maxY, maxZ}
     * @return whether the base lies outside the box and the section inside the ball
     */
    private static boolean crosses(ShadowFrustum frustum, InnerBall ball, double... box) {
        double[] boxes = { -50, -50, -50, 50, 50, 50, 0, 0, 0, 0, 0, 0 };
        System.arraycopy(box, 0, boxes, 6, 6);
        return CoreCrossing.baseOutside(frustum, boxes, 6) && CoreCrossing.sectionInside(frustum, ball);
    }

    /**
     * The box around a point, a half-side each way.
     *
     * @param centre the centre
     * @param half   the half-side
     * @return {minX, minY, minZ, maxX, maxY, maxZ}
     */
    private static double[] boxAround(Point3D centre, double half) {
        return new double[] { centre.getX() - half, centre.getY() - half, centre.getZ() - half,
                centre.getX() + half, centre.getY() + half, centre.getZ() + half };
    }

    /**
     * Test method for {@link ShadowFrustum#crossesClosedMesh}, {@link ShadowFrustum#sectionInside} and
     * {@link CoreCrossing#baseOutside} on the standard pyramid, whose cross-section at height z is the
     * square of half-side z/5: at z = 5 (λ = ½) its corners (±1, ±1, 5) lie √2 from the axis. The balls
     * are the inner balls of cubes (a cube of half-side h: radius h less 1e-6 of it and a rounding).
     */
    @Test
    void testSectionInside() {
        ShadowFrustum frustum = standard();
        Point3D middle = new Point3D(0, 0, 5);
        InnerBall wide = InnerBallTest.cubeBall(middle, 2);
        double[] wideBox = boxAround(middle, 2);

        // ===== Equivalence Partitions Tests =====
        // TC01: a ball of radius about 2 at (0, 0, 5), its cube's box (z 3..7) short of the base: true
        assertTrue(crosses(frustum, wide, wideBox), "TC01: a ball across the whole pyramid must block it");
        // TC02: the same ball beside the pyramid (at (5, 0, 5)): false
        Point3D beside = new Point3D(5, 0, 5);
        assertFalse(crosses(frustum, InnerBallTest.cubeBall(beside, 2), boxAround(beside, 2)),
                "TC02: a ball beside the pyramid must not block it");
        // TC03: a ball beyond the base (at (0, 0, 14), λ 1.4), its box beyond the base too: false
        Point3D beyond = new Point3D(0, 0, 14);
        assertFalse(crosses(frustum, InnerBallTest.cubeBall(beyond, 3), boxAround(beyond, 3)),
                "TC03: a ball beyond the light must not block it");
        // TC04: a ball behind the apex (at (0, 0, −5), λ −½): false
        Point3D behind = new Point3D(0, 0, -5);
        assertFalse(crosses(frustum, InnerBallTest.cubeBall(behind, 3), boxAround(behind, 3)),
                "TC04: a ball behind the apex must not block it");
        // TC05: TC01's ball with a mesh's box around the base (−20..20 each way): the light may be inside
        // the mesh: false, though the section lies inside the ball
        assertTrue(CoreCrossing.sectionInside(frustum, wide), "TC05: the section lies inside the ball");
        assertFalse(crosses(frustum, wide, -20, -20, -20, 20, 20, 20),
                "TC05: a base inside the box must not be blocked");
        // TC06: a ball of radius about 1.3 < √2 at (0, 0, 5): the section's corners poke out: false
        assertFalse(crosses(frustum, InnerBallTest.cubeBall(middle, 1.3), boxAround(middle, 1.3)),
                "TC06: a section poking out of the ball must not be blocked");
        // TC07: a slanted pyramid (apex (1, −2, 3), base (7, 5, −4) ± (1, 2, 0.5) ± (−0.5, 1, 3), its
        // corners up to 4.7 from the centre) and a ball of radius about 2.5 on its axis at λ = 0.3 (the
        // section's corners up to 1.4 from it), its box (x up to 5.3) short of the base (x from 5.5): true
        assertTrue(frustum.set(new double[] { 1, -2, 3 }, new double[] { 7, 5, -4, 1, 2, 0.5, -0.5, 1, 3 }, 0),
                "TC07: the slanted pyramid must be set");
        Point3D onAxis = new Point3D(1 + 0.3 * 6, -2 + 0.3 * 7, 3 - 0.3 * 7);
        assertTrue(crosses(frustum, InnerBallTest.cubeBall(onAxis, 2.5), boxAround(onAxis, 2.5)),
                "TC07: a ball across a slanted pyramid must block it");
        // TC08: after a refused set (a flat pyramid), TC01's ball: false
        assertFalse(frustum.set(new double[] { 0, 0, 10 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC08: the flat pyramid must be refused");
        assertFalse(crosses(frustum, wide, wideBox), "TC08: a refused frustum must block nothing");
        assertFalse(CoreCrossing.sectionInside(frustum, wide), "TC08: a refused frustum has no section inside a ball");

        // ===== Boundary Values Tests =====
        frustum = standard();
        // TC11: a ball of radius about 1.45 at (0, 0, 5): its reach r − 2.8e-6 beyond the corners' √2
        // thin: true; 0.1 thick (rays straying by up to 0.1): false
        InnerBall tight = InnerBallTest.cubeBall(middle, 1.45);
        assertTrue(crosses(frustum, tight, boxAround(middle, 1.45)), "TC11: the thin bundle passes through the ball");
        assertFalse(crosses(standard(0.1), tight, boxAround(middle, 1.45)),
                "TC11: rays straying by the thickness may miss the ball");
        // TC12: the thickness t at which the corners lie r − margin from the centre (r − √2 − 2.8e-6):
        // 1e-9 less: true; 1e-9 more: false
        double limit = tight.radius - Math.sqrt(2) - STANDARD_MARGIN;
        assertTrue(crosses(standard(limit - 1e-9), tight, boxAround(middle, 1.45)),
                "TC12: a thickness just below the limit " + limit);
        assertFalse(crosses(standard(limit + 1e-9), tight, boxAround(middle, 1.45)),
                "TC12: a thickness just above the limit " + limit);
        // TC13: λ = 0 (a huge ball centred on the apex) and λ = 1 (centred on the base's centre): false
        assertFalse(CoreCrossing.sectionInside(frustum, InnerBallTest.cubeBall(Point3D.ZERO, 30)), "TC13: λ = 0");
        assertFalse(CoreCrossing.sectionInside(frustum, InnerBallTest.cubeBall(new Point3D(0, 0, 10), 30)), "TC13: λ = 1");
        // TC14: λ just inside (0, 1): a ball of radius about 1 at (0, 0, 0.01) and at (0, 0, 9.99): the section
        // near the apex is tiny: true; near the base it is the base (corners 2.8 away): false
        assertTrue(CoreCrossing.sectionInside(frustum, InnerBallTest.cubeBall(new Point3D(0, 0, 0.01), 1)), "TC14: λ = 0.001");
        assertFalse(CoreCrossing.sectionInside(frustum, InnerBallTest.cubeBall(new Point3D(0, 0, 9.99), 1)), "TC14: λ = 0.999");
        // TC15: the base (z = 10) against a box below it: its top at 10 − 1e-5 (beyond the margin): outside;
        // at 10 − 1e-6 (within the margin) and at 10 (touching): not outside
        assertTrue(baseOutside(frustum, -5, -5, 0, 5, 5, 10 - 1e-5), "TC15: a box below the base by 1e-5");
        assertFalse(baseOutside(frustum, -5, -5, 0, 5, 5, 10 - 1e-6), "TC15: a box within the margin of the base");
        assertFalse(baseOutside(frustum, -5, -5, 0, 5, 5, 10), "TC15: a box touching the base");
        // TC16: boxes beside the base along x (from x 2 + 1e-5, past the base's corners at x 2) and above
        // it (from z 10 + 1e-5): outside; a box around the base's corner (2, 2, 10): not outside
        assertTrue(baseOutside(frustum, 2 + 1e-5, -5, 0, 5, 5, 20), "TC16: a box beside the base along x");
        assertTrue(baseOutside(frustum, -5, -5, 10 + 1e-5, 5, 5, 20), "TC16: a box above the base");
        assertFalse(baseOutside(frustum, 1.9, 1.9, 9.9, 3, 3, 20), "TC16: a box around a corner of the base");
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

    /**
     * Test method for {@link CoreCrossing#sectionInside} on seeded random pyramids, thin and thick, and
     * balls about their axes: when it says a bundle crosses a ball, each of 200 segments the bundle's
     * rays may cover (from the apex to the base, each end moved by up to the thickness) passes through
     * the ball's inside ({@link InnerBall#crossedBy}) and ends outside the box, and so do the rays along
     * the pyramid's edges moved by the whole thickness away from the ball.
     */
    @Test
    void testRandomBalls() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 300 random pyramids, a quarter of them thin, the others 1e-4 to 1 thick (log-uniform),
        // × 8 balls (the inner balls of cubes) centred near the axis at λ −0.1 to 1.1, of radii about
        // the section's reach there (0.7 to 1.5 times, plus up to twice the thickness)
        int[] counts = forRandomCores(20261203, (rnd, frustum, bundle, corner) -> {
            double[] p = bundle.pyramid();
            double lambda = 1.2 * rnd.nextDouble() - 0.1;
            double half = Math.max(1e-3, lambda * corner * (0.7 + 0.8 * rnd.nextDouble())
                    + 2 * bundle.thickness() * rnd.nextDouble());
            double[] centre = new double[3];
            for (int k = 0; k < 3; ++k)
                centre[k] = p[k] + lambda * (p[3 + k] - p[k]) + 0.1 * half * rnd.nextGaussian();
            Point3D at = new Point3D(centre[0], centre[1], centre[2]);
            InnerBall ball = InnerBallTest.cubeBall(at, half);
            double[] box = boxAround(at, half);
            if (!crosses(frustum, ball, box))
                return false;
            String pyramid = "pyramid " + Arrays.toString(p) + " thickness " + bundle.thickness() + ", ball at "
                    + at + " radius " + ball.radius;
            for (double[] e : bundle.segments())
                assertThroughBall(ball, box, e, "TC01", pyramid);
            // ===== Boundary Values Tests =====
            // TC11: the rays along the pyramid's four edges, moved (start and end) by the whole
            // thickness away from the ball's centre at their section: the rays farthest from it
            for (double[] e : edgeSegments(p, bundle.thickness(), ball))
                assertThroughBall(ball, box, e, "TC11", pyramid);
            return true;
        });
        // both answers are common: the test is not vacuous
        assertTrue(counts[0] > 200 && counts[1] > 200, "TC01: too few crossing (" + counts[0] + ") or missing ("
                + counts[1] + ") balls");
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

    /**
     * Asserts that a segment passes through a ball's inside and ends outside a box.
     *
     * @param ball    the ball
     * @param box     the box
     * @param e       the segment, {start, end}
     * @param tc      the test case's label
     * @param pyramid the pyramid and ball, for the failure message
     */
    private static void assertThroughBall(InnerBall ball, double[] box, double[] e, String tc, String pyramid) {
        double dx = e[3] - e[0];
        double dy = e[4] - e[1];
        double dz = e[5] - e[2];
        double length = Math.sqrt(squared(dx, dy, dz));
        Supplier<String> label = () -> tc + ": " + pyramid + ", segment " + Arrays.toString(e);
        assertTrue(ball.crossedBy(e[0], e[1], e[2], dx / length, dy / length, dz / length, length),
                () -> label.get() + ": the segment must pass through the ball");
        assertFalse(holds(box, new double[] { e[3], e[4], e[5] }),
                () -> label.get() + ": the segment must end outside the box");
    }

    /**
     * The segments along a pyramid's four edges, from the apex to each corner of the base, each moved
     * as a whole by the thickness away from a ball's centre at the fraction λ of the way where the
     * ball's centre lies across the axis.
     *
     * @param p         the pyramid {apex, c, a, b}
     * @param thickness the thickness
     * @param ball      the ball
     * @return the four segments, {start, end} each
     */
    private static double[][] edgeSegments(double[] p, double thickness, InnerBall ball) {
        double[] w = { p[3] - p[0], p[4] - p[1], p[5] - p[2] };
        double lambda = ((ball.cx - p[0]) * w[0] + (ball.cy - p[1]) * w[1] + (ball.cz - p[2]) * w[2])
                / squared(w[0], w[1], w[2]);
        double[] ball3 = { ball.cx, ball.cy, ball.cz };
        double[][] segments = new double[4][];
        int i = 0;
        for (double s : new double[] { -1, 1 })
            for (double r : new double[] { -1, 1 }) {
                double[] corner = new double[3];
                double[] away = new double[3];
                for (int k = 0; k < 3; ++k) {
                    corner[k] = p[3 + k] + s * p[6 + k] + r * p[9 + k];
                    away[k] = p[k] + lambda * (corner[k] - p[k]) - ball3[k];
                }
                double length = Math.sqrt(squared(away[0], away[1], away[2]));
                double[] segment = new double[6];
                for (int k = 0; k < 3; ++k) {
                    double move = length > 0 ? thickness * away[k] / length : 0;
                    segment[k] = p[k] + move;
                    segment[3 + k] = corner[k] + move;
                }
                segments[i++] = segment;
            }
        return segments;
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
