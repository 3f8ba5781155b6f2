package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestBundles.assertForgetsSubtree;
import static testutil.TestBundles.assertGathersRowSubtree;
import static testutil.TestBundles.assertKeepsSubtree;
import static testutil.TestScenes.triangleRow;

import org.junit.jupiter.api.Test;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import primitives.Color;

/**
 * Unit tests for {@link ThreadState}: a rendering thread's stream, counters, reused sample room, light
 * square and query, which starts every tile afresh.
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

    /**
     * Test method for {@link ThreadState#pixelPoints(JitteredGrid)} and {@link ThreadState#aperturePoints(JitteredGrid)}:
     * room of their own, apart from the shadows' and from each other, reused.
     */
    @Test
    void testPixelAndAperturePoints() {
        ThreadState state = new ThreadState(new SplitMix64(1));
        JitteredGrid grid = new JitteredGrid(4);

        // ===== Equivalence Partitions Tests =====
        // TC01: a 4 × 4 grid gets room for at least 32 coordinates in each, three different arrays
        double[] pixel = state.pixelPoints(grid);
        double[] aperture = state.aperturePoints(grid);
        double[] shadow = state.points(grid);
        assertTrue(pixel.length >= 32 && aperture.length >= 32, "TC01: a 4 × 4 grid needs 32 coordinates");
        assertNotSame(pixel, aperture, "TC01: pixel and aperture points must not share an array");
        assertNotSame(pixel, shadow, "TC01: pixel and shadow points must not share an array");
        assertNotSame(aperture, shadow, "TC01: aperture and shadow points must not share an array");
        // TC02: asked again (a smaller 2 × 2 grid), each array is reused
        assertSame(pixel, state.pixelPoints(new JitteredGrid(2)), "TC02: the pixel points must be reused");
        assertSame(aperture, state.aperturePoints(new JitteredGrid(2)), "TC02: the aperture points must be reused");

        // ===== Boundary Values Tests =====
        // TC11: a larger grid (10 × 10) gets arrays of at least 200 coordinates
        assertTrue(state.pixelPoints(new JitteredGrid(10)).length >= 200, "TC11: 10 × 10 pixel points");
        assertTrue(state.aperturePoints(new JitteredGrid(10)).length >= 200, "TC11: 10 × 10 aperture points");
    }

    /**
     * Test method for {@link ThreadState#startLattice(int)}, {@link ThreadState#latticeColor(int)} and
     * {@link ThreadState#keepLatticeColor(int, Color)}: a pixel's colours, forgotten at the next pixel.
     */
    @Test
    void testLattice() {
        ThreadState state = new ThreadState(new SplitMix64(1));
        Color red = new Color(200, 0, 0);

        // ===== Equivalence Partitions Tests =====
        // TC01: a new lattice of 9 points knows none; a colour kept at point 4 is given back
        state.startLattice(9);
        assertNull(state.latticeColor(4), "TC01: a new lattice must not know point 4");
        assertSame(red, state.keepLatticeColor(4, red), "TC01: keeping a colour returns it");
        assertSame(red, state.latticeColor(4), "TC01: point 4 must give the colour kept");
        assertNull(state.latticeColor(3), "TC01: point 3 was not kept");
        // TC02: the next pixel's lattice (25 points, larger) forgets it
        state.startLattice(25);
        assertNull(state.latticeColor(4), "TC02: the next pixel must not see the last pixel's point 4");
        state.keepLatticeColor(24, red);
        assertSame(red, state.latticeColor(24), "TC02: the larger lattice keeps its last point");

        // ===== Boundary Values Tests =====
        // TC11: a smaller lattice (1 point) after a larger one forgets too
        state.startLattice(1);
        assertNull(state.latticeColor(0), "TC11: a one-point lattice must start empty");
        assertNull(state.latticeColor(24), "TC11: the last pixel's point 24 must be forgotten");
    }

    /** Test method for {@link ThreadState#lightSquare()}: one light square per thread, reused. */
    @Test
    void testLightSquare() {
        ThreadState state = new ThreadState(new SplitMix64(1));

        // ===== Equivalence Partitions Tests =====
        // TC01: the same light square on every call
        LightSquare square = state.lightSquare();
        assertNotNull(square, "TC01: a state must have a light square");
        assertSame(square, state.lightSquare(), "TC01: the light square must be reused");

        // ===== Boundary Values Tests =====
        // TC11: another thread's state has a light square of its own
        assertNotSame(square, new ThreadState(new SplitMix64(1)).lightSquare(),
                "TC11: two states must not share a light square");
    }

    /**
     * Test method for {@link ThreadState#startTile()}: the thread's query forgets the subtree its last
     * gather kept, so a tile's pixels depend on no earlier tile. On the row of 40 triangles
     * ({@code triangleRow}), under the pyramid over all of them and the one over triangles 19 and 20.
     */
    @Test
    void testStartTile() {
        BoundingVolumeHierarchy rowBvh = BoundingVolumeHierarchy.build(triangleRow());

        // ===== Equivalence Partitions Tests =====
        // TC01: a subtree kept, then a tile started: the middle pyramid's 2 triangles are gathered one by one
        ThreadState state = new ThreadState(new SplitMix64(1));
        Query query = state.query(rowBvh);
        assertForgetsSubtree(rowBvh, query, state::startTile, "TC01");
        // TC02: within a tile, the middle pyramid keeps the subtree of the one before
        assertKeepsSubtree(rowBvh, query, "TC02");

        // ===== Boundary Values Tests =====
        // TC11: a state without a query starts a tile; its query, made after, keeps the subtree of 40
        ThreadState unused = new ThreadState(new SplitMix64(2));
        unused.startTile();
        Query later = unused.query(rowBvh);
        assertGathersRowSubtree(rowBvh, later, "TC11");
    }
}
