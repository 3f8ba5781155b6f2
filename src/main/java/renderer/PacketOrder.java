package renderer;

import java.util.Arrays;

/**
 * The order in which a bundle's shadow rays go into a packet: serpentine over the light's grid (row
 * by row, every other row from right to left), the ray to the centre in the middle, so that rays next
 * to each other in the packet pass next to each other. The packet walk tests a node on the first and
 * the last of its rays that meet it and a leaf on every ray between ({@link accel.PacketWalk}), so the
 * tighter a node's rays lie in the packet, the fewer tests it costs. The rays' answers are still read,
 * and summed, in the grid's visiting order.
 */
final class PacketOrder {
    /** What {@link #rayAt} answers for the ray to the centre. */
    static final int CENTRE = -1;

    /** The grid the order is for. */
    private final JitteredGrid grid;
    /** Per place in the packet: the visiting number of its ray's cell, or {@link #CENTRE}. */
    private final int[] rays;
    /** Per cell from the first one ordered, by visiting number: its ray's place in the packet. */
    private final int[] places;
    /** The first cell ordered, by visiting number. */
    private final int first;
    /** The centre's place in the packet, or −1 without it. */
    private final int centre;

    /**
     * Orders the rays through a grid's cells from a visiting number on, and the ray to the centre.
     *
     * @param grid       the light's grid
     * @param first      the first cell to order, by visiting number: the cells before are left out
     * @param withCentre whether the ray to the centre is in the packet
     */
    PacketOrder(JitteredGrid grid, int first, boolean withCentre) {
        this.grid = grid;
        this.first = first;
        int k = grid.getSqrtSamples();
        int[] visits = new int[k * k]; // per cell, row by row: its visiting number, −1 when left out
        Arrays.fill(visits, -1);
        for (int c = first; c < grid.getSamplesCount(); ++c)
            visits[grid.rowOf(c) * k + grid.columnOf(c)] = c;
        int count = grid.getSamplesCount() - first;
        this.rays = new int[count + (withCentre ? 1 : 0)];
        this.places = new int[count];
        int place = 0;
        int half = count / 2;
        int centrePlace = -1;
        for (int row = 0; row < k; ++row)
            for (int i = 0; i < k; ++i) {
                int cell = visits[row * k + (row % 2 == 0 ? i : k - 1 - i)];
                if (cell < 0)
                    continue;
                if (withCentre && place == half) {
                    centrePlace = place;
                    rays[place++] = CENTRE;
                }
                places[cell - first] = place;
                rays[place++] = cell;
            }
        this.centre = centrePlace;
    }

    /** {@return whether this order is for a grid} */
    boolean isFor(JitteredGrid grid) {
        return this.grid == grid;
    }

    /** {@return the number of rays in the packet} */
    int size() {
        return rays.length;
    }

    /** {@return the visiting number of the cell of the ray at a place of the packet, or {@link #CENTRE}} */
    int rayAt(int place) {
        return rays[place];
    }

    /** {@return the place in the packet of the ray through a cell, by its visiting number} */
    int placeOf(int cell) {
        return places[cell - first];
    }

    /** {@return the place in the packet of the ray to the centre, or −1 when it is not in the packet} */
    int centrePlace() {
        return centre;
    }
}
