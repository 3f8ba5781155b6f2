package renderer;

import java.util.random.RandomGenerator;

import static primitives.Util.requireNonNull;

/**
 * Stratified jittered sampling of the unit square: the square is divided into k × k equal cells and
 * one point is drawn uniformly at random in each. This is the one place sample positions come from:
 * soft shadows place their shadow rays on a light's square with it, anti-aliasing places its rays
 * in a pixel.
 * Glossy and blurry surfaces place their spread rays on the square around the sharp ray with it too.
 * <p>
 * Cells are visited outline first (the cells on the grid's border, going round it), then the inner
 * cells row by row, so that adaptive sampling can look at the outline before deciding whether to
 * sample the rest.
 */
public final class JitteredGrid {
    /**
     * The largest k: a million cells, so that the grid and its points stay small in memory
     * (k² must not overflow an int either).
     */
    public static final int MAX_SQRT_SAMPLES = 1000;

    private final int sqrtSamples;
    private final int outlineCount;
    /** The column and row of every cell, in visiting order: cells[2c], cells[2c + 1]. */
    private final int[] cells;
    private final double cellSize;
    /** Where each column (or row) of cells starts: n / k. */
    private final double[] cellStarts;
    /** The largest coordinate inside each column (or row): just below (n + 1) / k. */
    private final double[] cellEnds;

    /**
     * Creates a grid of k × k cells.
     *
     * @param sqrtSamples k, the number of cells along each side, 1 to {@link #MAX_SQRT_SAMPLES}
     * @throws IllegalArgumentException when k is less than 1 or more than {@link #MAX_SQRT_SAMPLES}
     */
    public JitteredGrid(int sqrtSamples) {
        requireSqrtSamples(sqrtSamples, "the square root of the number of samples");
        this.sqrtSamples = sqrtSamples;
        this.outlineCount = sqrtSamples == 1 ? 1 : 4 * (sqrtSamples - 1);
        this.cells = new int[2 * sqrtSamples * sqrtSamples];
        this.cellSize = 1.0 / sqrtSamples;
        this.cellStarts = new double[sqrtSamples];
        this.cellEnds = new double[sqrtSamples];
        for (int n = 0; n < sqrtSamples; ++n) {
            cellStarts[n] = (double) n / sqrtSamples;
            cellEnds[n] = Math.nextDown((double) (n + 1) / sqrtSamples);
        }
        int c = visitOutline(0);
        for (int row = 1; row < sqrtSamples - 1; ++row)
            for (int column = 1; column < sqrtSamples - 1; ++column)
                c = visit(c, column, row);
    }

    /**
     * Checks a number of cells along each side of a grid.
     *
     * @param sqrtSamples the number, k
     * @param what        what the number is, for the message
     * @return the number
     * @throws IllegalArgumentException when k is less than 1 or more than {@link #MAX_SQRT_SAMPLES}
     */
    public static int requireSqrtSamples(int sqrtSamples, String what) {
        if (sqrtSamples < 1 || sqrtSamples > MAX_SQRT_SAMPLES)
            throw new IllegalArgumentException(what + " must be between 1 and " + MAX_SQRT_SAMPLES + ", got "
                    + sqrtSamples);
        return sqrtSamples;
    }

    /** Lists the border cells going round the grid: top row, right column, bottom row, left column. */
    private int visitOutline(int c) {
        int last = sqrtSamples - 1;
        if (last == 0)
            return visit(c, 0, 0);
        for (int column = 0; column < last; ++column)
            c = visit(c, column, 0);
        for (int row = 0; row < last; ++row)
            c = visit(c, last, row);
        for (int column = last; column > 0; --column)
            c = visit(c, column, last);
        for (int row = last; row > 0; --row)
            c = visit(c, 0, row);
        return c;
    }

    private int visit(int c, int column, int row) {
        cells[2 * c] = column;
        cells[2 * c + 1] = row;
        return c + 1;
    }

    /** {@return k, the number of cells along each side} */
    public int getSqrtSamples() {
        return sqrtSamples;
    }

    /** {@return the column of a cell, by its visiting number, from 0} */
    int columnOf(int cell) {
        return cells[2 * cell];
    }

    /** {@return the row of a cell, by its visiting number, from 0} */
    int rowOf(int cell) {
        return cells[2 * cell + 1];
    }

    /** {@return k², the number of cells and so of sample points} */
    public int getSamplesCount() {
        return sqrtSamples * sqrtSamples;
    }

    /** {@return the number of cells on the grid's border, which come first: 4(k − 1), or 1 when k is 1} */
    public int getOutlineCount() {
        return outlineCount;
    }

    /**
     * Draws one point in every cell, in visiting order (outline first). Point c is
     * {@code (points[2c], points[2c + 1])}, both coordinates in [0, 1) and the point inside its cell
     * (on each axis {@code n / k <= x < (n + 1) / k} for the cell's index n, even for a draw just below 1).
     *
     * @param random the random stream the jitter comes from (2 k² numbers are drawn from it)
     * @param points the array filled with the points' coordinates, of length 2 k² or more
     * @throws IllegalArgumentException when the random stream or the array is null, or the array is too short
     */
    public void sample(RandomGenerator random, double[] points) {
        requireNonNull(random, "random stream");
        if (requireNonNull(points, "sample points array").length < cells.length)
            throw new IllegalArgumentException("sample points array holds " + points.length
                    + " coordinates, the grid needs " + cells.length);
        for (int i = 0; i < cells.length; ++i)
            points[i] = random.nextDouble();
        place(points);
    }

    /**
     * Draws one point in every cell, as {@link #sample(RandomGenerator, double[])} does, without its
     * checks: for the renderer, whose streams and rooms ({@link ThreadState}) are never null and
     * always long enough.
     *
     * @param random the pixel's random stream (2 k² numbers are drawn from it)
     * @param points the array filled with the points' coordinates, of length 2 k² or more
     */
    void sampleUnchecked(SplitMix64 random, double[] points) {
        random.nextDoubles(points, cells.length);
        place(points);
    }

    /** Moves the draws in [0, 1) into their cells: each coordinate n / k + draw / k, kept below (n + 1) / k. */
    private void place(double[] points) {
        for (int i = 0; i < cells.length; ++i) {
            int cell = cells[i];
            double x = cellStarts[cell] + points[i] * cellSize;
            // rounding may carry a draw just below 1 onto the cell's upper edge (1 itself for the last cell)
            points[i] = x < cellEnds[cell] ? x : cellEnds[cell];
        }
    }
}
