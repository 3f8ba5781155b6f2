package accel;

import geometries.TriangleMesh;
import java.util.Arrays;

/**
 * Boxes inside a closed mesh that touch none of its triangles: the convex cores of an occluder,
 * found on a grid of cubic cells over the mesh's box (64 per triangle, 4,096 to 110,592 of them). A
 * cell that no triangle's box reaches lies wholly inside or wholly outside the mesh, and so does
 * every cell it reaches through such cells, face to face; a group of them that does not reach the
 * grid's border is inside when the parity rays from one of its cells say so surely
 * ({@link InsideParity}). The largest boxes of inside cells, grown greedily from the cells deepest
 * inside, are the mesh's inner boxes.
 * <p>
 * A ray through an inner box passes through the inside of the closed mesh, so on its way to a point
 * outside the mesh's box it crosses the surface: an opaque mesh blocks it. And since the rays from one
 * apex through a convex box fill a convex cone, a bundle whose four corner rays pass through the box
 * has every ray pass through it ({@link CoreCrossing#crossesBox}).
 */
final class InnerBoxes {
    /** The cells per triangle of the grid, and the fewest and the most cells of a grid. */
    private static final int CELLS_PER_TRIANGLE = 64;
    private static final int MIN_CELLS = 4096;
    private static final int MAX_CELLS = 110_592;
    /** The most boxes kept. */
    static final int MAX_BOXES = 32;
    /** The fewest cells along each side of a box kept. */
    private static final int MIN_SIDE = 2;
    /** The part of the cell's size a triangle's box is grown by when it marks cells, for rounding. */
    private static final double GROW = 1e-6;
    /** The part of the mesh's largest coordinate a box is shrunk by, for rounding. */
    private static final double ROUNDING = 1e-12;
    /** How many cells of a group the parity rays try before the group counts as outside. */
    private static final int TRIES = 4;

    private static final int OUTSIDE = -1;
    private static final int TOUCHED = -2;

    private final TriangleMesh mesh;
    private final int[] n = new int[3];
    private final double[] origin = new double[3];
    private final double cell;
    /** Per cell: a group number (0 or more) while grouping, then 1 inside, or {@link #OUTSIDE}, {@link #TOUCHED}. */
    private final int[] state;

    private InnerBoxes(TriangleMesh mesh, double[] box) {
        this.mesh = mesh;
        // cubic cells, about as many as the mesh's triangles call for, in its box
        long cells = Math.max(MIN_CELLS, Math.min(MAX_CELLS, (long) CELLS_PER_TRIANGLE * mesh.getTrianglesCount()));
        this.cell = Math.cbrt((box[3] - box[0]) * (box[4] - box[1]) * (box[5] - box[2]) / cells);
        for (int k = 0; k < 3; ++k) {
            n[k] = (int) Math.ceil((box[3 + k] - box[k]) / cell) + 2;
            origin[k] = box[k] - cell;
        }
        this.state = new int[n[0] * n[1] * n[2]];
    }

    /**
     * Finds the inner boxes of a closed mesh.
     *
     * @param mesh the mesh, closed (see {@link ClosedParts})
     * @return the boxes, {minX, minY, minZ, maxX, maxY, maxZ} each, the largest first; none when the
     *         mesh is too thin for a box of {@value #MIN_SIDE} cells a side
     */
    static double[] of(TriangleMesh mesh) {
        double[] box = new double[6];
        mesh.bounds(box, 0);
        if (!(box[3] - box[0] > 0 && box[4] - box[1] > 0 && box[5] - box[2] > 0))
            return new double[0];
        InnerBoxes grid = new InnerBoxes(mesh, box);
        grid.markTouched();
        grid.classify();
        return grid.boxes(scale(box));
    }

    /**
     * Half the shortest side of a box: the radius of the largest ball it holds.
     *
     * @param boxes the boxes, {minX, minY, minZ, maxX, maxY, maxZ} each
     * @param b     where the box lies in them
     * @return half its shortest side
     */
    static double halfShortestSide(double[] boxes, int b) {
        return Math.min(boxes[b + 3] - boxes[b], Math.min(boxes[b + 4] - boxes[b + 1], boxes[b + 5] - boxes[b + 2])) / 2;
    }

    /** {@return the largest |coordinate| of a box} */
    private static double scale(double[] box) {
        double scale = 0;
        for (double bound : box)
            scale = Math.max(scale, Math.abs(bound));
        return scale;
    }

    private int index(int i, int j, int k) {
        return (k * n[1] + j) * n[0] + i;
    }

    /** {@return the place, i, j and k, of the cell of an index: the inverse of {@link #index}, in at} */
    private int[] cellOf(int c, int[] at) {
        at[0] = c % n[0];
        at[1] = c / n[0] % n[1];
        at[2] = c / (n[0] * n[1]);
        return at;
    }

    /** Marks the cells that a triangle's box, grown a little, reaches. */
    private void markTouched() {
        double[] tb = new double[6];
        int[] low = new int[3];
        int[] high = new int[3];
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            mesh.bounds(t, tb, 0);
            for (int k = 0; k < 3; ++k) {
                low[k] = Math.max(0, (int) Math.floor((tb[k] - origin[k]) / cell - GROW));
                high[k] = Math.min(n[k] - 1, (int) Math.floor((tb[3 + k] - origin[k]) / cell + GROW));
            }
            for (int k = low[2]; k <= high[2]; ++k)
                for (int j = low[1]; j <= high[1]; ++j)
                    for (int i = low[0]; i <= high[0]; ++i)
                        state[index(i, j, k)] = TOUCHED;
        }
    }

    /** Groups the untouched cells face to face and tells each group inside (1) or {@link #OUTSIDE}. */
    private void classify() {
        boolean[] reached = new boolean[state.length];
        // a group's cells in the order the flood reaches them: its queue, and then its members
        int[] members = new int[state.length];
        int[] stride = { 1, n[0], n[0] * n[1] };
        int[] at = new int[3];
        for (int start = 0; start < state.length; ++start) {
            if (state[start] == TOUCHED || reached[start])
                continue;
            int count = 0;
            boolean border = false;
            reached[start] = true;
            members[count++] = start;
            for (int head = 0; head < count; ++head) {
                int c = members[head];
                cellOf(c, at);
                for (int axis = 0; axis < 3; ++axis) {
                    border |= at[axis] == 0 || at[axis] == n[axis] - 1;
                    for (int step = -1; step <= 1; step += 2) {
                        if (at[axis] + step < 0 || at[axis] + step >= n[axis])
                            continue;
                        int d = c + step * stride[axis];
                        if (state[d] != TOUCHED && !reached[d]) {
                            reached[d] = true;
                            members[count++] = d;
                        }
                    }
                }
            }
            int verdict = !border && surelyInside(members, count) ? 1 : OUTSIDE;
            for (int m = 0; m < count; ++m)
                state[members[m]] = verdict;
        }
    }

    /** Whether the parity rays from one of a few cells of a group say surely that it lies inside. */
    private boolean surelyInside(int[] members, int count) {
        for (int tried = 0; tried < Math.min(TRIES, count); ++tried) {
            int[] at = cellOf(members[tried * count / Math.min(TRIES, count)], new int[3]);
            int verdict = InsideParity.parity(mesh, origin[0] + (at[0] + 0.5) * cell,
                    origin[1] + (at[1] + 0.5) * cell, origin[2] + (at[2] + 0.5) * cell);
            if (verdict >= 0)
                return verdict == 1;
        }
        return false;
    }

    /** The largest boxes of inside cells, grown from the cells deepest inside, shrunk for rounding. */
    private double[] boxes(double scale) {
        int[] depth = depths();
        int[] seeds = deepestFirst(depth);
        boolean[] covered = new boolean[state.length];
        double[] found = new double[6 * MAX_BOXES];
        int count = 0;
        for (int s = 0; s < seeds.length && count < MAX_BOXES; ++s) {
            int seed = seeds[s];
            if (covered[seed])
                continue;
            int[] range = grow(seed, depth[seed] - 1);
            for (int k = range[2]; k <= range[5]; ++k)
                for (int j = range[1]; j <= range[4]; ++j)
                    for (int i = range[0]; i <= range[3]; ++i)
                        covered[index(i, j, k)] = true;
            if (range[3] - range[0] + 1 < MIN_SIDE || range[4] - range[1] + 1 < MIN_SIDE
                    || range[5] - range[2] + 1 < MIN_SIDE)
                continue;
            double shrink = ROUNDING * scale;
            for (int a = 0; a < 3; ++a) {
                found[6 * count + a] = origin[a] + range[a] * cell + shrink;
                found[6 * count + 3 + a] = origin[a] + (range[3 + a] + 1) * cell - shrink;
            }
            ++count;
        }
        return Arrays.copyOf(found, 6 * count);
    }

    /** {@return the inside cells, the deepest first (a counting sort by depth), in order of index among equals} */
    private int[] deepestFirst(int[] depth) {
        int deepest = 0;
        int inside = 0;
        for (int c = 0; c < state.length; ++c)
            if (state[c] == 1) {
                deepest = Math.max(deepest, depth[c]);
                ++inside;
            }
        int[] starts = new int[deepest + 2];
        for (int c = 0; c < state.length; ++c)
            if (state[c] == 1)
                ++starts[deepest - depth[c] + 1];
        for (int d = 1; d < starts.length; ++d)
            starts[d] += starts[d - 1];
        int[] seeds = new int[inside];
        for (int c = 0; c < state.length; ++c)
            if (state[c] == 1)
                seeds[starts[deepest - depth[c]]++] = c;
        return seeds;
    }

    /**
     * Per inside cell, its chessboard distance in cells to the nearest cell not inside (1 next to one):
     * the two raster passes of Rosenfeld and Pfaltz, each taking the least depth of the 13 neighbours
     * it has passed, plus one. Both are exact for the chessboard distance; no inside cell lies on the
     * grid's border, so all 26 neighbours of one exist.
     */
    private int[] depths() {
        int[] before = new int[13];
        int count = 0;
        for (int dk = -1; dk <= 1; ++dk)
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    int offset = (dk * n[1] + dj) * n[0] + di;
                    if (offset < 0)
                        before[count++] = offset;
                }
        int[] depth = new int[state.length];
        for (int c = 0; c < state.length; ++c)
            if (state[c] == 1)
                depth[c] = 1 + leastDepth(depth, c, before, 1);
        for (int c = state.length - 1; c >= 0; --c)
            if (state[c] == 1)
                depth[c] = Math.min(depth[c], 1 + leastDepth(depth, c, before, -1));
        return depth;
    }

    /** {@return the least depth of a cell's neighbours at the offsets, times a sign} */
    private static int leastDepth(int[] depth, int c, int[] offsets, int sign) {
        int least = Integer.MAX_VALUE;
        for (int offset : offsets)
            least = Math.min(least, depth[c + sign * offset]);
        return least;
    }

    /**
     * The cube of inside cells around a seed, grown face by face while the next layer is all inside.
     *
     * @return {i0, j0, k0, i1, j1, k1}, inclusive
     */
    private int[] grow(int seed, int radius) {
        int[] at = cellOf(seed, new int[3]);
        int[] range = { at[0] - radius, at[1] - radius, at[2] - radius, at[0] + radius, at[1] + radius,
                at[2] + radius };
        boolean grew = true;
        while (grew) {
            grew = false;
            for (int face = 0; face < 6; ++face) {
                int[] next = range.clone();
                next[face] += face < 3 ? -1 : 1;
                if (allInside(next, face)) {
                    range = next;
                    grew = true;
                }
            }
        }
        return range;
    }

    /** Whether the layer a range gained at a face lies inside the grid and is all inside cells. */
    private boolean allInside(int[] range, int face) {
        int axis = face % 3;
        int layer = range[face];
        if (layer < 0 || layer >= n[axis])
            return false;
        int[] low = { range[0], range[1], range[2] };
        int[] high = { range[3], range[4], range[5] };
        low[axis] = layer;
        high[axis] = layer;
        for (int z = low[2]; z <= high[2]; ++z)
            for (int y = low[1]; y <= high[1]; ++y)
                for (int x = low[0]; x <= high[0]; ++x)
                    if (state[index(x, y, z)] != 1)
                        return false;
        return true;
    }
}
