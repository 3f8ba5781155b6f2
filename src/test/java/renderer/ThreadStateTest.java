package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link ThreadState}: a rendering thread's stream, counters, reused sample room and
 * light square.
 */
class ThreadStateTest {

    /** Test method for {@link ThreadState#ThreadState(SplitMix64)}: the stream kept, counters at 0. */
    @Test
    void testConstructor() {
        SplitMix64 random = new SplitMix64(1);
        ThreadState state = new ThreadState(random);

        // ===== Equivalence Partitions Tests =====
        // TC01: the stream given is kept, and both counters are 0
        assertSame(random, state.random, "TC01: the state must keep the stream given");
        assertEquals(0, state.primaryRays, "TC01: the primary ray count must start at 0");
        assertEquals(0, state.shadowRays, "TC01: the shadow ray count must start at 0");
        assertEquals(0, state.openShadowRays, "TC01: the open shadow ray count must start at 0");
    }

    /** Test method for {@link ThreadState#points(JitteredGrid)}: room for 2k² coordinates, reused. */
    @Test
    void testPoints() {
        ThreadState state = new ThreadState(new SplitMix64(1));

        // ===== Equivalence Partitions Tests =====
        // TC01: a 3 × 3 grid gets room for at least 18 coordinates
        double[] points = state.points(new JitteredGrid(3));
        assertTrue(points.length >= 18, "TC01: a 3 × 3 grid needs 18 coordinates, got " + points.length);
        // TC02: a smaller grid (2 × 2) reuses the same array
        assertSame(points, state.points(new JitteredGrid(2)), "TC02: a smaller grid must reuse the array");
        // TC03: a larger grid (9 × 9) gets a new array of at least 162 coordinates, which is then reused
        double[] larger = state.points(new JitteredGrid(9));
        assertTrue(larger.length >= 162, "TC03: a 9 × 9 grid needs 162 coordinates, got " + larger.length);
        assertSame(larger, state.points(new JitteredGrid(9)), "TC03: the same grid must reuse the array");

        // ===== Boundary Values Tests =====
        // TC11: a 1 × 1 grid on a new state gets room for at least 2 coordinates, and the grid can fill it
        double[] single = new ThreadState(new SplitMix64(2)).points(new JitteredGrid(1));
        assertTrue(single.length >= 2, "TC11: a 1 × 1 grid needs 2 coordinates, got " + single.length);
        new JitteredGrid(1).sample(new SplitMix64(2), single);
        assertTrue(single[0] >= 0 && single[0] < 1 && single[1] >= 0 && single[1] < 1,
                "TC11: the single point must lie in [0,1)²");
    }
    /** Test method for {@link ThreadState#lightSquare()}: one light square per thread, reused. */
    @Test
    void testLightSquare() {
        ThreadState state = new ThreadState(new SplitMix64(1));

        // ===== Equivalence Partitions Tests =====
        // TC01: the same light square on every call
        RayTracerBasic.LightSquare square = state.lightSquare();
        assertNotNull(square, "TC01: a state must have a light square");
        assertSame(square, state.lightSquare(), "TC01: the light square must be reused");

        // ===== Boundary Values Tests =====
        // TC11: another thread's state has a light square of its own
        assertNotSame(square, new ThreadState(new SplitMix64(1)).lightSquare(),
                "TC11: two states must not share a light square");
    }
}
