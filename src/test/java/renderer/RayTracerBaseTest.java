package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import org.junit.jupiter.api.Test;

import scene.Scene;

/**
 * Unit tests for {@link RayTracerBase}: the sampling settings, the seeded per-pixel streams and the
 * ray counters, tested through {@link RayTracerBasic}.
 */
class RayTracerBaseTest {

    private static RayTracerBase tracer() {
        return new RayTracerBasic(new Scene("t"));
    }

    /** Test method for {@link RayTracerBase#RayTracerBase(Scene)}: the defaults and a null scene. */
    @Test
    void testDefaults() {
        RayTracerBase tracer = tracer();

        // ===== Equivalence Partitions Tests =====
        // TC01: sqrtBeamNum 9 (= DEFAULT_SQRT_BEAM_NUM), a 9 × 9 beam grid
        assertEquals(9, RayTracerBase.DEFAULT_SQRT_BEAM_NUM, "TC01: the default sqrtBeamNum must be 9");
        assertEquals(RayTracerBase.DEFAULT_SQRT_BEAM_NUM, tracer.getSqrtBeamNum(), "TC01: wrong default sqrtBeamNum");
        assertEquals(9, tracer.getBeamGrid().getSqrtSamples(), "TC01: the default beam grid must be 9 × 9");
        assertEquals(81, tracer.getBeamGrid().getSamplesCount(), "TC01: the default beam grid must have 81 cells");
        // TC02: soft shadows and adaptive soft shadows are off
        assertFalse(tracer.isSoftShadows(), "TC02: soft shadows must be off by default");
        assertFalse(tracer.isAdaptiveSoftShadows(), "TC02: adaptive soft shadows must be off by default");
        // TC03: the seed is DEFAULT_SEED
        assertEquals(RayTracerBase.DEFAULT_SEED, tracer.getSeed(), "TC03: wrong default seed");
        // TC04: the ray counters start at 0
        assertEquals(0, tracer.getPrimaryRaysCount(), "TC04: the primary ray count must start at 0");
        assertEquals(0, tracer.getShadowRaysCount(), "TC04: the shadow ray count must start at 0");
        assertEquals(0, tracer.getOpenShadowRaysCount(), "TC04: the open shadow ray count must start at 0");
        assertEquals(0, tracer.getBlockedShadowRaysCount(), "TC04: the blocked shadow ray count must start at 0");
        assertEquals(0, tracer.getSpreadRaysCount(), "TC04: the spread ray count must start at 0");
        assertEquals(0, tracer.getBundleTracingNanos(), "TC04: the bundles' tracing time must start at 0");
        // TC05: sqrtGlossRays 5 (= DEFAULT_SQRT_GLOSS_RAYS), a 5 × 5 gloss grid
        assertEquals(5, RayTracerBase.DEFAULT_SQRT_GLOSS_RAYS, "TC05: the default sqrtGlossRays must be 5");
        assertEquals(5, tracer.getSqrtGlossRays(), "TC05: wrong default sqrtGlossRays");
        assertEquals(25, tracer.getGlossGrid().getSamplesCount(), "TC05: the default gloss grid must have 25 cells");

        // ===== Boundary Values Tests =====
        // TC11: a null scene is rejected with a message naming the scene
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new RayTracerBasic(null),
                "TC11: a null scene must be rejected");
        assertMessage(e, "scene", "TC11");
    }

    /** Test method for {@link RayTracerBase#setSqrtBeamNum(int)} and {@link RayTracerBase#getBeamGrid()}. */
    @Test
    void testSetSqrtBeamNum() {
        RayTracerBase tracer = tracer();

        // ===== Equivalence Partitions Tests =====
        // TC01: sqrtBeamNum 4: the setter returns the tracer, the getter gives 4 and the grid is 4 × 4
        assertSame(tracer, tracer.setSqrtBeamNum(4), "TC01: setSqrtBeamNum must return the same ray tracer");
        assertEquals(4, tracer.getSqrtBeamNum(), "TC01: sqrtBeamNum must be 4");
        assertEquals(4, tracer.getBeamGrid().getSqrtSamples(), "TC01: the beam grid must follow sqrtBeamNum (4)");
        assertEquals(16, tracer.getBeamGrid().getSamplesCount(), "TC01: the beam grid must have 16 cells");
        assertEquals(12, tracer.getBeamGrid().getOutlineCount(), "TC01: the beam grid must have 12 border cells");
        // TC02: a negative sqrtBeamNum (-3) is rejected, and the settings stay as they were
        JitteredGrid before = tracer.getBeamGrid();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> tracer.setSqrtBeamNum(-3),
                "TC02: sqrtBeamNum -3 must be rejected");
        assertMessage(e, "sqrtBeamNum", "TC02");
        assertEquals(4, tracer.getSqrtBeamNum(), "TC02: a rejected sqrtBeamNum must leave 4");
        assertSame(before, tracer.getBeamGrid(), "TC02: a rejected sqrtBeamNum must leave the grid");

        // ===== Boundary Values Tests =====
        // TC11: sqrtBeamNum 0 is rejected
        e = assertThrows(IllegalArgumentException.class, () -> tracer.setSqrtBeamNum(0),
                "TC11: sqrtBeamNum 0 must be rejected");
        assertMessage(e, "sqrtBeamNum", "TC11");
        assertEquals(4, tracer.getSqrtBeamNum(), "TC11: a rejected sqrtBeamNum must leave 4");
        // TC12: sqrtBeamNum 1 is accepted: a single cell
        assertSame(tracer, tracer.setSqrtBeamNum(1), "TC12: setSqrtBeamNum(1) must return the same ray tracer");
        assertEquals(1, tracer.getSqrtBeamNum(), "TC12: sqrtBeamNum must be 1");
        assertEquals(1, tracer.getBeamGrid().getSamplesCount(), "TC12: the beam grid must have 1 cell");
        // TC13: sqrtBeamNum 46341 (whose square overflows an int) is rejected, naming the bound 1000
        e = assertThrows(IllegalArgumentException.class, () -> tracer.setSqrtBeamNum(46_341),
                "TC13: sqrtBeamNum 46341 must be rejected");
        assertMessage(e, "sqrtBeamNum must be between 1 and 1000", "TC13");
        assertEquals(1, tracer.getSqrtBeamNum(), "TC13: a rejected sqrtBeamNum must leave 1");
    }

    /** Test method for {@link RayTracerBase#setSqrtGlossRays(int)} and {@link RayTracerBase#getGlossGrid()}. */
    @Test
    void testSetSqrtGlossRays() {
        RayTracerBase tracer = tracer();

        // ===== Equivalence Partitions Tests =====
        // TC01: sqrtGlossRays 3: the setter returns the tracer, the grid is 3 × 3, the shadow grid stays 9 × 9
        assertSame(tracer, tracer.setSqrtGlossRays(3), "TC01: setSqrtGlossRays must return the same ray tracer");
        assertEquals(3, tracer.getSqrtGlossRays(), "TC01: sqrtGlossRays must be 3");
        assertEquals(9, tracer.getGlossGrid().getSamplesCount(), "TC01: the gloss grid must have 9 cells");
        assertEquals(9, tracer.getSqrtBeamNum(), "TC01: the shadow grid must not change");
        // TC02: a negative count is rejected naming sqrtGlossRays, and the grid stays
        JitteredGrid before = tracer.getGlossGrid();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> tracer.setSqrtGlossRays(-1),
                "TC02: sqrtGlossRays -1 must be rejected");
        assertMessage(e, "sqrtGlossRays", "TC02");
        assertSame(before, tracer.getGlossGrid(), "TC02: a rejected sqrtGlossRays must leave the grid");

        // ===== Boundary Values Tests =====
        // TC11: 1 (one jittered ray) and 1000 (the largest grid) are accepted
        assertEquals(1, tracer.setSqrtGlossRays(1).getSqrtGlossRays(), "TC11: sqrtGlossRays 1 must be accepted");
        assertEquals(JitteredGrid.MAX_SQRT_SAMPLES,
                tracer.setSqrtGlossRays(JitteredGrid.MAX_SQRT_SAMPLES).getSqrtGlossRays(),
                "TC11: sqrtGlossRays 1000 must be accepted");
        // TC12: 0 and 1001 are rejected, naming the bounds
        e = assertThrows(IllegalArgumentException.class, () -> tracer.setSqrtGlossRays(0),
                "TC12: sqrtGlossRays 0 must be rejected");
        assertMessage(e, "between 1 and 1000", "TC12");
        assertThrows(IllegalArgumentException.class, () -> tracer.setSqrtGlossRays(JitteredGrid.MAX_SQRT_SAMPLES + 1),
                "TC12: sqrtGlossRays 1001 must be rejected");
    }

    /**
     * Test method for {@link RayTracerBase#setSoftShadows(boolean)},
     * {@link RayTracerBase#setAdaptiveSoftShadows(boolean)} and {@link RayTracerBase#setSeed(long)}.
     */
    @Test
    void testFlagsAndSeed() {
        RayTracerBase tracer = tracer();

        // ===== Equivalence Partitions Tests =====
        // TC01: soft shadows on, then off again
        assertSame(tracer, tracer.setSoftShadows(true), "TC01: setSoftShadows must return the same ray tracer");
        assertTrue(tracer.isSoftShadows(), "TC01: soft shadows must be on");
        tracer.setSoftShadows(false);
        assertFalse(tracer.isSoftShadows(), "TC01: soft shadows must be off again");
        // TC02: adaptive soft shadows on, then off again, independent of soft shadows
        assertSame(tracer, tracer.setAdaptiveSoftShadows(true),
                "TC02: setAdaptiveSoftShadows must return the same ray tracer");
        assertTrue(tracer.isAdaptiveSoftShadows(), "TC02: adaptive soft shadows must be on");
        assertFalse(tracer.isSoftShadows(), "TC02: adaptive must not turn soft shadows on");
        tracer.setAdaptiveSoftShadows(false);
        assertFalse(tracer.isAdaptiveSoftShadows(), "TC02: adaptive soft shadows must be off again");
        // TC03: the seed 1234
        assertSame(tracer, tracer.setSeed(1234), "TC03: setSeed must return the same ray tracer");
        assertEquals(1234, tracer.getSeed(), "TC03: the seed must be 1234");

        // ===== Boundary Values Tests =====
        // TC11: seeds 0, -1, Long.MIN_VALUE and Long.MAX_VALUE are all accepted as they are
        for (long seed : new long[] { 0, -1, Long.MIN_VALUE, Long.MAX_VALUE }) {
            tracer.setSeed(seed);
            assertEquals(seed, tracer.getSeed(), "TC11: the seed must be " + seed);
        }
    }

    /**
     * Test method for {@link RayTracerBase#startPixel(int, int)}: each pixel's stream comes from the
     * seed and the pixel's position only.
     */
    @Test
    void testPixelStreams() {
        RayTracerBase tracer = tracer();

        // ===== Equivalence Partitions Tests =====
        // TC01: the same pixel twice gives the same stream
        long first = tracer.startPixel(3, 4).random.nextLong();
        assertEquals(first, tracer.startPixel(3, 4).random.nextLong(), "TC01: a pixel must restart the same stream");
        // TC02: another tracer with the same seed gives the same stream for the pixel
        assertEquals(first, tracer().startPixel(3, 4).random.nextLong(),
                "TC02: the same seed and pixel must give the same stream");
        // TC03: swapped coordinates and neighbouring pixels give other streams
        assertNotEquals(first, tracer.startPixel(4, 3).random.nextLong(), "TC03: pixel (4, 3) must differ from (3, 4)");
        assertNotEquals(first, tracer.startPixel(3, 5).random.nextLong(), "TC03: pixel (3, 5) must differ from (3, 4)");
        assertNotEquals(first, tracer.startPixel(2, 4).random.nextLong(), "TC03: pixel (2, 4) must differ from (3, 4)");
        // TC04: another seed gives another stream for the same pixel
        assertNotEquals(first, tracer().setSeed(99).startPixel(3, 4).random.nextLong(),
                "TC04: another seed must give another stream");
        // TC05: the state returned is the calling thread's state
        assertSame(tracer.threadState(), tracer.startPixel(1, 1), "TC05: startPixel must return the thread's state");

        // ===== Boundary Values Tests =====
        // TC11: pixel (0, 0) with seed 0 still gives a stream that differs from pixel (0, 1) and (1, 0)
        RayTracerBase zero = tracer().setSeed(0);
        long origin = zero.startPixel(0, 0).random.nextLong();
        assertNotEquals(origin, zero.startPixel(0, 1).random.nextLong(), "TC11: pixel (0, 1) must differ from (0, 0)");
        assertNotEquals(origin, zero.startPixel(1, 0).random.nextLong(), "TC11: pixel (1, 0) must differ from (0, 0)");
    }

    /**
     * Test method for {@link RayTracerBase#getPrimaryRaysCount()}, {@link RayTracerBase#getShadowRaysCount()}
     * and {@link RayTracerBase#getOpenShadowRaysCount()}: the counts of all threads are added up.
     */
    @Test
    void testRayCounters() throws InterruptedException {
        RayTracerBase tracer = tracer();

        // ===== Equivalence Partitions Tests =====
        // TC01: 5 rays counted on this thread and 7 on another give 12
        tracer.threadState().primaryRays += 5;
        tracer.threadState().openShadowRays += 3;
        onOtherThread(() -> {
            tracer.threadState().primaryRays += 7;
            tracer.threadState().shadowRays += 2;
            tracer.threadState().openShadowRays += 4;
        });
        assertEquals(12, tracer.getPrimaryRaysCount(), "TC01: the primary ray counts of both threads must add up");
        assertEquals(2, tracer.getShadowRaysCount(), "TC01: the shadow ray count must be the other thread's 2");
        assertEquals(7, tracer.getOpenShadowRaysCount(), "TC01: the open shadow ray counts 3 and 4 must add up to 7");

        // ===== Boundary Values Tests =====
        // TC11: another tracer's counters stay at 0
        assertEquals(0, tracer().getPrimaryRaysCount(), "TC11: a new tracer's count must be 0");
    }

    /**
     * Runs a job on another thread and waits for it.
     *
     * @param job the job
     * @throws InterruptedException when the wait is interrupted
     */
    private static void onOtherThread(Runnable job) throws InterruptedException {
        Thread other = new Thread(job);
        other.start();
        other.join();
    }

    /**
     * Test method for {@link RayTracerBase#getBlockedShadowRaysCount()}: the counts of all threads are
     * added up, apart from the other counters.
     */
    @Test
    void testBlockedShadowRaysCount() throws InterruptedException {
        RayTracerBase tracer = tracer();

        // ===== Equivalence Partitions Tests =====
        // TC01: 6 rays of blocked bundles counted on this thread and 9 on another give 15; the shadow rays
        // (6 and 10) add up on their own, and no ray counts as open
        tracer.threadState().blockedShadowRays += 6;
        tracer.threadState().shadowRays += 6;
        onOtherThread(() -> {
            tracer.threadState().blockedShadowRays += 9;
            tracer.threadState().shadowRays += 10;
        });
        assertEquals(15, tracer.getBlockedShadowRaysCount(), "TC01: the blocked counts 6 and 9 must add up to 15");
        assertEquals(16, tracer.getShadowRaysCount(), "TC01: the shadow ray counts 6 and 10 must add up to 16");
        assertEquals(0, tracer.getOpenShadowRaysCount(), "TC01: blocked rays must not count as open");

        // ===== Boundary Values Tests =====
        // TC11: a thread that counted no blocked ray adds nothing
        onOtherThread(() -> tracer.threadState().openShadowRays += 2);
        assertEquals(15, tracer.getBlockedShadowRaysCount(), "TC11: a thread without blocked rays must add 0");
        assertEquals(2, tracer.getOpenShadowRaysCount(), "TC11: the other thread's open rays are counted apart");
        // TC12: another tracer's blocked count stays at 0
        assertEquals(0, tracer().getBlockedShadowRaysCount(), "TC12: a new tracer's blocked count must be 0");
    }
}
