package renderer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.random.RandomGenerator;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link JitteredGrid}: the stratified jittered sampler of the unit square.
 */
class JitteredGridTest {

    /** A random stream whose every draw is the largest double below 1. */
    private static final RandomGenerator HIGHEST = new RandomGenerator() {
        @Override
        public long nextLong() {
            return -1L;
        }

        @Override
        public double nextDouble() {
            return Math.nextDown(1.0);
        }
    };

    /** A random stream whose every draw is 0. */
    private static final RandomGenerator LOWEST = new RandomGenerator() {
        @Override
        public long nextLong() {
            return 0L;
        }

        @Override
        public double nextDouble() {
            return 0.0;
        }
    };

    /**
     * The cell index, along one side, of a coordinate: the c with c/k ≤ x < (c+1)/k (edges computed
     * as {@code (double) c / k}), or -1 when x is outside [0, 1).
     */
    private static int cellOf(double x, int k) {
        if (!(x >= 0 && x < 1))
            return -1;
        int c = Math.min(k - 1, (int) (x * k));
        while (c > 0 && x < (double) c / k)
            --c;
        while (c < k - 1 && x >= (double) (c + 1) / k)
            ++c;
        return x < (double) (c + 1) / k ? c : -1;
    }

    /** Samples a grid with a new seeded stream into a fresh array. */
    private static double[] sample(JitteredGrid grid, long seed) {
        double[] points = new double[2 * grid.getSamplesCount()];
        grid.sample(new SplittableRandom(seed), points);
        return points;
    }

    /**
     * Asserts that every coordinate lies in [0, 1), that point c lies in the c-th cell of the
     * visiting order, and that the cells visited are every cell once: the outline first, going
     * round the grid, then the inner cells row by row.
     */
    private static void assertStratified(JitteredGrid grid, double[] points, String tc) {
        int k = grid.getSqrtSamples();
        int count = grid.getSamplesCount();
        int outline = grid.getOutlineCount();
        boolean[] seen = new boolean[count];
        int[] columns = new int[count];
        int[] rows = new int[count];
        for (int s = 0; s < count; ++s) {
            double x = points[2 * s];
            double y = points[2 * s + 1];
            assertTrue(x >= 0 && x < 1 && y >= 0 && y < 1,
                    tc + ": point " + s + " (" + x + ", " + y + ") must lie in [0,1)² for k = " + k);
            int column = cellOf(x, k);
            int row = cellOf(y, k);
            assertTrue(column >= 0 && row >= 0, tc + ": point " + s + " must lie in a cell for k = " + k);
            assertFalse(seen[row * k + column],
                    tc + ": cell (" + column + ", " + row + ") holds two points for k = " + k);
            seen[row * k + column] = true;
            columns[s] = column;
            rows[s] = row;
            boolean border = column == 0 || row == 0 || column == k - 1 || row == k - 1;
            assertEquals(s < outline, border, tc + ": point " + s + " in cell (" + column + ", " + row
                    + ") must be a border cell exactly when it is among the first " + outline + " for k = " + k);
        }
        // k² distinct cells among k² cells: a permutation of all the cells
        for (int c = 0; c < count; ++c)
            assertTrue(seen[c], tc + ": cell " + c + " holds no point for k = " + k);
        // the outline goes round the grid: each border cell is next to the one before it
        for (int s = 1; s < outline; ++s)
            assertEquals(1, Math.abs(columns[s] - columns[s - 1]) + Math.abs(rows[s] - rows[s - 1]),
                    tc + ": outline cells " + (s - 1) + " and " + s + " must be neighbours for k = " + k);
        if (outline > 1)
            assertEquals(1, Math.abs(columns[outline - 1] - columns[0]) + Math.abs(rows[outline - 1] - rows[0]),
                    tc + ": the outline must close on its first cell for k = " + k);
        // the inner cells come row by row, each row left to right
        for (int s = outline + 1; s < count; ++s)
            assertTrue(rows[s] * k + columns[s] > rows[s - 1] * k + columns[s - 1],
                    tc + ": inner cells must come row by row for k = " + k);
    }

    /** Test method for {@link JitteredGrid#JitteredGrid(int)}: k below 1 is rejected. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a negative k (-1) is rejected with a message naming the number of samples and the value
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new JitteredGrid(-1),
                "TC01: k = -1 must be rejected");
        assertMessage(e, "number of samples", "TC01");
        assertMessage(e, "-1", "TC01");

        // ===== Boundary Values Tests =====
        // TC11: k = 0 is rejected
        e = assertThrows(IllegalArgumentException.class, () -> new JitteredGrid(0), "TC11: k = 0 must be rejected");
        assertMessage(e, "between 1 and 1000", "TC11");
        // TC12: k = 1 is accepted: a single cell
        assertEquals(1, new JitteredGrid(1).getSqrtSamples(), "TC12: k = 1 must be accepted");
        // TC13: k = 1000, the largest, is accepted: a million cells
        assertEquals(1_000_000, new JitteredGrid(JitteredGrid.MAX_SQRT_SAMPLES).getSamplesCount(),
                "TC13: k = 1000 must be accepted");
        // TC14: k = 1001, 46341 (k² overflows an int) and 1000000 are rejected, naming the bound
        for (int k : new int[] { 1001, 46_341, 1_000_000, Integer.MAX_VALUE }) {
            e = assertThrows(IllegalArgumentException.class, () -> new JitteredGrid(k), "TC14: k = " + k
                    + " must be rejected");
            assertMessage(e, "between 1 and 1000", "TC14");
        }
    }

    /**
     * Test method for {@link JitteredGrid#getSqrtSamples()}, {@link JitteredGrid#getSamplesCount()}
     * and {@link JitteredGrid#getOutlineCount()}.
     */
    @Test
    void testCounts() {
        // ===== Equivalence Partitions Tests =====
        // TC01: k = 3: 3 along a side, 9 cells, 8 on the border
        JitteredGrid grid = new JitteredGrid(3);
        assertEquals(3, grid.getSqrtSamples(), "TC01: wrong sqrt samples for k = 3");
        assertEquals(9, grid.getSamplesCount(), "TC01: wrong samples count for k = 3");
        assertEquals(8, grid.getOutlineCount(), "TC01: wrong outline count for k = 3");
        // TC02: k = 9 (the default beam): 9, 81 cells, 32 on the border
        grid = new JitteredGrid(9);
        assertEquals(9, grid.getSqrtSamples(), "TC02: wrong sqrt samples for k = 9");
        assertEquals(81, grid.getSamplesCount(), "TC02: wrong samples count for k = 9");
        assertEquals(32, grid.getOutlineCount(), "TC02: wrong outline count for k = 9");

        // ===== Boundary Values Tests =====
        // TC11: k = 1: a single cell, which is its own outline (1, 1, 1)
        grid = new JitteredGrid(1);
        assertEquals(1, grid.getSqrtSamples(), "TC11: wrong sqrt samples for k = 1");
        assertEquals(1, grid.getSamplesCount(), "TC11: wrong samples count for k = 1");
        assertEquals(1, grid.getOutlineCount(), "TC11: wrong outline count for k = 1");
        // TC12: k = 2: every cell is on the border (2, 4, 4)
        grid = new JitteredGrid(2);
        assertEquals(2, grid.getSqrtSamples(), "TC12: wrong sqrt samples for k = 2");
        assertEquals(4, grid.getSamplesCount(), "TC12: wrong samples count for k = 2");
        assertEquals(4, grid.getOutlineCount(), "TC12: wrong outline count for k = 2");
    }

    /** Test method for {@link JitteredGrid#sample}: one point in every cell, outline first. */
    @Test
    void testSampleStratified() {
        // ===== Equivalence Partitions Tests =====
        // TC01: k = 3 and k = 9 with several seeds: every point in [0,1)², one per cell, border cells first
        for (int k : new int[] { 3, 9, 4 })
            for (long seed = 1; seed <= 20; ++seed)
                assertStratified(new JitteredGrid(k), sample(new JitteredGrid(k), seed), "TC01");

        // ===== Boundary Values Tests =====
        // TC11: k = 1: the single point anywhere in [0,1)²
        assertStratified(new JitteredGrid(1), sample(new JitteredGrid(1), 5), "TC11");
        // TC12: k = 2: four points, all on the outline
        assertStratified(new JitteredGrid(2), sample(new JitteredGrid(2), 5), "TC12");
        // TC13: every draw 0: each point at its cell's lower corner, still one per cell
        for (int k : new int[] { 1, 2, 3, 9 }) {
            JitteredGrid grid = new JitteredGrid(k);
            double[] points = new double[2 * grid.getSamplesCount()];
            grid.sample(LOWEST, points);
            assertStratified(grid, points, "TC13");
        }
        // TC14: every draw the largest double below 1: each point still below its cell's upper edge,
        // so no coordinate reaches 1 and no point falls into the next cell
        for (int k : new int[] { 1, 2, 3, 9 }) {
            JitteredGrid grid = new JitteredGrid(k);
            double[] points = new double[2 * grid.getSamplesCount()];
            grid.sample(HIGHEST, points);
            assertStratified(grid, points, "TC14");
        }
        // TC15: an array longer than needed is accepted, and the extra room is left untouched
        JitteredGrid grid = new JitteredGrid(3);
        double[] points = new double[2 * 9 + 3];
        Arrays.fill(points, -7);
        grid.sample(new SplittableRandom(3), points);
        assertStratified(grid, points, "TC15");
        for (int i = 18; i < points.length; ++i)
            assertEquals(-7, points[i], 0, "TC15: coordinate " + i + " past 2k² must be left as it was");
    }

    /** Test method for {@link JitteredGrid#sample}: exactly 2k² numbers are drawn from the stream. */
    @Test
    void testSampleDrawCount() {
        // ===== Equivalence Partitions Tests =====
        // TC01: k = 3 and k = 9: after sampling, the stream is where a twin stream is after 2k² draws
        for (int k : new int[] { 3, 9 }) {
            JitteredGrid grid = new JitteredGrid(k);
            SplittableRandom used = new SplittableRandom(42);
            SplittableRandom twin = new SplittableRandom(42);
            grid.sample(used, new double[2 * k * k]);
            for (int d = 0; d < 2 * k * k; ++d)
                twin.nextDouble();
            assertEquals(twin.nextLong(), used.nextLong(), "TC01: sampling must draw exactly 2k² = "
                    + 2 * k * k + " numbers for k = " + k);
        }

        // ===== Boundary Values Tests =====
        // TC11: k = 1: exactly 2 numbers
        SplittableRandom used = new SplittableRandom(43);
        SplittableRandom twin = new SplittableRandom(43);
        new JitteredGrid(1).sample(used, new double[2]);
        twin.nextDouble();
        twin.nextDouble();
        assertEquals(twin.nextLong(), used.nextLong(), "TC11: sampling must draw exactly 2 numbers for k = 1");
    }

    /** Test method for {@link JitteredGrid#sample}: the points depend on the seed and on nothing else. */
    @Test
    void testSampleReproducible() {
        JitteredGrid grid = new JitteredGrid(4);

        // ===== Equivalence Partitions Tests =====
        // TC01: the same seed gives the same points, bit for bit
        assertArrayEquals(sample(grid, 11), sample(grid, 11), 0, "TC01: the same seed must give the same points");
        // TC02: a different seed gives different points
        assertFalse(Arrays.equals(sample(grid, 11), sample(grid, 12)),
                "TC02: a different seed must give different points");
        // TC03: two grids of the same size give the same points from the same seed
        assertArrayEquals(sample(grid, 11), sample(new JitteredGrid(4), 11), 0,
                "TC03: equal grids must give the same points from the same seed");
    }

    /** Test method for {@link JitteredGrid#sample}: over many seeds, each cell's points fill the cell evenly. */
    @Test
    void testSampleSpread() {
        // ===== Equivalence Partitions Tests =====
        // TC01: k = 3, 3000 seeds: the mean point of each cell is its centre ((c + 0.5)/3, within 0.01,
        // about 5 standard deviations), and the points reach near every edge of the cell
        int k = 3;
        int runs = 3000;
        JitteredGrid grid = new JitteredGrid(k);
        double[] points = new double[2 * k * k];
        double[] sumX = new double[k * k];
        double[] sumY = new double[k * k];
        double[] minFraction = new double[2 * k * k];
        double[] maxFraction = new double[2 * k * k];
        Arrays.fill(minFraction, 1);
        for (long seed = 0; seed < runs; ++seed) {
            grid.sample(new SplittableRandom(seed), points);
            for (int s = 0; s < k * k; ++s) {
                int column = cellOf(points[2 * s], k);
                int row = cellOf(points[2 * s + 1], k);
                int cell = row * k + column;
                sumX[cell] += points[2 * s];
                sumY[cell] += points[2 * s + 1];
                double fx = points[2 * s] * k - column;
                double fy = points[2 * s + 1] * k - row;
                minFraction[2 * cell] = Math.min(minFraction[2 * cell], fx);
                minFraction[2 * cell + 1] = Math.min(minFraction[2 * cell + 1], fy);
                maxFraction[2 * cell] = Math.max(maxFraction[2 * cell], fx);
                maxFraction[2 * cell + 1] = Math.max(maxFraction[2 * cell + 1], fy);
            }
        }
        for (int row = 0; row < k; ++row)
            for (int column = 0; column < k; ++column) {
                int cell = row * k + column;
                assertEquals((column + 0.5) / k, sumX[cell] / runs, 0.01,
                        "TC01: the mean x of cell (" + column + ", " + row + ") must be its centre");
                assertEquals((row + 0.5) / k, sumY[cell] / runs, 0.01,
                        "TC01: the mean y of cell (" + column + ", " + row + ") must be its centre");
                for (int axis = 0; axis < 2; ++axis) {
                    assertTrue(minFraction[2 * cell + axis] < 0.01,
                            "TC01: the points of cell (" + column + ", " + row + ") must reach its low edge");
                    assertTrue(maxFraction[2 * cell + axis] > 0.99,
                            "TC01: the points of cell (" + column + ", " + row + ") must reach its high edge");
                }
            }
    }

    /** Test method for {@link JitteredGrid#sample}: bad input is rejected with a message naming it. */
    @Test
    void testSampleBadInput() {
        JitteredGrid grid = new JitteredGrid(2);

        // ===== Equivalence Partitions Tests =====
        // TC01: a null random stream
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> grid.sample(null, new double[8]), "TC01: a null random stream must be rejected");
        assertMessage(e, "random", "TC01");
        // TC02: a null array
        e = assertThrows(IllegalArgumentException.class, () -> grid.sample(new SplittableRandom(1), null),
                "TC02: a null array must be rejected");
        assertMessage(e, "array", "TC02");
        // TC03: an empty array
        e = assertThrows(IllegalArgumentException.class, () -> grid.sample(new SplittableRandom(1), new double[0]),
                "TC03: an empty array must be rejected");
        assertMessage(e, "array", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: an array one coordinate short of 2k² = 8 is rejected and names both lengths
        e = assertThrows(IllegalArgumentException.class, () -> grid.sample(new SplittableRandom(1), new double[7]),
                "TC11: an array of 7 coordinates must be rejected for k = 2");
        assertMessage(e, "7", "TC11");
        assertMessage(e, "8", "TC11");
        // TC12: an array of exactly 2k² = 8 coordinates is accepted
        double[] points = new double[8];
        grid.sample(new SplittableRandom(1), points);
        assertStratified(grid, points, "TC12");
    }

    /**
     * Test method for {@link JitteredGrid#sampleUnchecked(SplitMix64, double[])} and the SplitMix64 path of
     * {@link JitteredGrid#sample}: the same points, bit for bit, as a stream drawing one number at a time.
     */
    @Test
    void testSampleUnchecked() {
        // ===== Equivalence Partitions Tests =====
        // TC01: k = 3, 4 and 9, several seeds: the renderer's path gives the points of SplittableRandom
        // (the same numbers, drawn one at a time through RandomGenerator), and draws 2k² numbers
        for (int k : new int[] { 3, 4, 9 })
            for (long seed = 1; seed <= 10; ++seed) {
                JitteredGrid grid = new JitteredGrid(k);
                SplitMix64 stream = new SplitMix64(seed);
                double[] points = new double[2 * k * k];
                grid.sampleUnchecked(stream, points);
                assertArrayEquals(sample(grid, seed), points, 0, "TC01: k = " + k + ", seed " + seed);
                SplittableRandom twin = new SplittableRandom(seed);
                for (int d = 0; d < 2 * k * k; ++d)
                    twin.nextDouble();
                assertEquals(twin.nextLong(), stream.nextLong(), "TC01: 2k² numbers must be drawn for k = " + k);
            }
        // TC02: the public method given a SplitMix64 gives the same points as the unchecked one
        JitteredGrid grid = new JitteredGrid(9);
        double[] checked = new double[162];
        double[] unchecked = new double[162];
        grid.sample((RandomGenerator) new SplitMix64(31), checked);
        grid.sampleUnchecked(new SplitMix64(31), unchecked);
        assertArrayEquals(checked, unchecked, 0, "TC02: both paths must give the same points");

        // ===== Boundary Values Tests =====
        // TC11: k = 1: the single point is the stream's first two draws
        double[] single = new double[2];
        new JitteredGrid(1).sampleUnchecked(new SplitMix64(32), single);
        SplittableRandom reference = new SplittableRandom(32);
        assertArrayEquals(new double[] { reference.nextDouble(), reference.nextDouble() }, single, 0,
                "TC11: k = 1 must give the first two draws");
        // TC12: the public method still checks its arguments when given a SplitMix64 (a short array)
        assertThrows(IllegalArgumentException.class, () -> grid.sample(new SplitMix64(33), new double[161]),
                "TC12: a short array must be rejected");
    }

    /** Tests for {@link JitteredGrid#columnOf} and {@link JitteredGrid#rowOf}: each cell's place, by visiting number. */
    @Test
    void testCellOf() {
        JitteredGrid grid = new JitteredGrid(3);
        // ===== Equivalence Partitions Tests =====
        // TC01: the outline goes round from the top left corner: (0,0) (1,0) (2,0) (2,1) (2,2) (1,2) (0,2) (0,1)
        int[][] outline = { { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 1 }, { 2, 2 }, { 1, 2 }, { 0, 2 }, { 0, 1 } };
        for (int c = 0; c < outline.length; ++c)
            assertArrayEquals(outline[c], new int[] { grid.columnOf(c), grid.rowOf(c) }, "TC01: cell " + c);
        // TC02: the inner cell comes after the outline
        assertArrayEquals(new int[] { 1, 1 }, new int[] { grid.columnOf(8), grid.rowOf(8) }, "TC02: cell 8 is (1, 1)");

        // ===== Boundary Values Tests =====
        // TC11: k = 1: the single cell is (0, 0)
        JitteredGrid single = new JitteredGrid(1);
        assertArrayEquals(new int[] { 0, 0 }, new int[] { single.columnOf(0), single.rowOf(0) }, "TC11: (0, 0)");
    }
}
