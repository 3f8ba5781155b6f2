package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestBundles.triangleData;

import java.util.Random;

import org.junit.jupiter.api.Test;

/** Unit tests for {@link accel.RayOrigins}: the two origins of shadow rays leaving a surface on both sides. */
class RayOriginsTest {
    /** A rounding margin small next to the offset of 0.1. */
    private static final double ROUNDING = 1e-9;

    /** {@return origins p = (1, 2, 3) ± n, n = (0, 0, 0.1)} */
    private static RayOrigins origins() {
        RayOrigins origins = new RayOrigins();
        origins.set(1, 2, 3, 0, 0, 0.1);
        return origins;
    }

    /** {@return a triangle across the plane z = 3 + height, around p} */
    private static double[] flat(double height) {
        double z = 3 + height;
        return new double[] { 0, 1, z, 3, 1, z, 1, 4, z };
    }

    /** Test method for {@link RayOrigins#originOf(double, double, double, double, double, double)}. */
    @Test
    void testOriginOf() {
        RayOrigins origins = origins();

        // ===== Equivalence Partitions Tests =====
        // TC01: from p + n, leaving to n's side: ABOVE
        assertEquals(ShadowFrustum.ABOVE, origins.originOf(1, 2, 3 + 0.1, 0.6, 0, 0.8), "TC01: from p + n");
        // TC02: from p − n, leaving to the other side: BELOW
        assertEquals(ShadowFrustum.BELOW, origins.originOf(1, 2, 3 - 0.1, 0, 0.6, -0.8), "TC02: from p − n");
        // TC03: from p + n but leaving to the other side: 0
        assertEquals(0, origins.originOf(1, 2, 3 + 0.1, 0, 0, -1), "TC03: from p + n against n");

        // ===== Boundary Values Tests =====
        // TC11: from p itself: 0
        assertEquals(0, origins.originOf(1, 2, 3, 0, 0, 1), "TC11: from p");
        // TC12: no origins set, or a zero offset: 0
        assertEquals(0, new RayOrigins().originOf(1, 2, 3.1, 0, 0, 1), "TC12: no origins");
        RayOrigins zero = new RayOrigins();
        zero.set(1, 2, 3, 0, 0, 0);
        assertFalse(zero.isSet(), "TC12: a zero offset sets no origins");
        // TC13: cleared: 0
        origins.clear();
        assertEquals(0, origins.originOf(1, 2, 3.1, 0, 0, 1), "TC13: cleared");
    }

    /**
     * Test method for {@link RayOrigins#behind(double[], int, int, int, double)} and
     * {@link RayOrigins#behindBoth(double[], int, int, int, double)}.
     */
    @Test
    void testBehind() {
        RayOrigins origins = origins();

        // ===== Equivalence Partitions Tests =====
        // TC01: a triangle 0.5 under p: behind p + n only (ABOVE)
        assertEquals(ShadowFrustum.ABOVE, origins.behind(flat(-0.5), 0, 3, 6, ROUNDING), "TC01: under p");
        // TC02: a triangle 0.5 over p: behind p − n only (BELOW)
        assertEquals(ShadowFrustum.BELOW, origins.behind(flat(0.5), 0, 3, 6, ROUNDING), "TC02: over p");
        // TC03: a triangle through p: behind both, and remembered
        assertFalse(origins.leftBehind(), "TC03: nothing set aside yet");
        assertTrue(origins.behindBoth(flat(0), 0, 3, 6, ROUNDING), "TC03: through p");
        assertTrue(origins.leftBehind(), "TC03: set aside is remembered");

        // ===== Boundary Values Tests =====
        // TC11: in the plane of p + n: not behind it (BELOW only)
        assertEquals(ShadowFrustum.BELOW, origins.behind(flat(0.1), 0, 3, 6, ROUNDING), "TC11: at p + n");
        // TC12: no origins set: 0, and never behind both
        RayOrigins none = new RayOrigins();
        assertEquals(0, none.behind(flat(0), 0, 3, 6, ROUNDING), "TC12: no origins");
        assertFalse(none.behindBoth(flat(0), 0, 3, 6, ROUNDING), "TC12: no origins");
    }

    /**
     * Test method for {@link RayOrigins#behind(double[], int, double)}: a triangle's data (p1 and its
     * edges) give the answer its vertices give.
     */
    @Test
    void testBehindData() {
        RayOrigins origins = origins();
        Random rnd = new Random(77);

        // ===== Equivalence Partitions Tests =====
        // TC01: 300 random triangles near p, their data at an offset: the vertices' answer, each of
        // the four answers met
        int[] answers = new int[4];
        for (int k = 0; k < 300; ++k) {
            double[] v = new double[9];
            for (int c = 0; c < 9; ++c)
                v[c] = (c % 3 == 0 ? 1 : c % 3 == 1 ? 2 : 3) + (c % 3 == 2 ? 0.3 : 2) * (2 * rnd.nextDouble() - 1);
            int expected = origins.behind(v, 0, 3, 6, ROUNDING);
            assertEquals(expected, origins.behind(triangleData(2, v), 2, ROUNDING), "TC01: triangle " + k);
            ++answers[expected];
        }
        for (int a = 0; a < 4; ++a)
            assertTrue(answers[a] > 0, "TC01: answer " + a + " never met");

        // ===== Boundary Values Tests =====
        // TC11: no origins set: 0
        assertEquals(0, new RayOrigins().behind(triangleData(0, flat(0)), 0, ROUNDING), "TC11: no origins");
        // TC12: in the plane of p + n: BELOW only, as from the vertices
        assertEquals(ShadowFrustum.BELOW, origins.behind(triangleData(0, flat(0.1)), 0, ROUNDING), "TC12: at p + n");
    }
}
