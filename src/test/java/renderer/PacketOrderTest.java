package renderer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link PacketOrder}: the serpentine order of a bundle's shadow rays in a packet.
 */
class PacketOrderTest {

    /** {@return the rays of an order, place by place: visiting numbers, −1 for the centre} */
    private static int[] rays(PacketOrder order) {
        int[] rays = new int[order.size()];
        for (int place = 0; place < rays.length; ++place)
            rays[place] = order.rayAt(place);
        return rays;
    }

    /** {@return the column and row of the cell at each place of an order that holds no centre} */
    private static int[][] cells(JitteredGrid grid, PacketOrder order) {
        int[][] cells = new int[order.size()][];
        for (int place = 0; place < cells.length; ++place)
            cells[place] = new int[] { grid.columnOf(order.rayAt(place)), grid.rowOf(order.rayAt(place)) };
        return cells;
    }

    /** Tests for {@link PacketOrder#PacketOrder}: the places of the rays. */
    @Test
    void testOrder() {
        JitteredGrid grid = new JitteredGrid(3);
        // ===== Equivalence Partitions Tests =====
        // TC01: every cell, row by row, the second row backwards: cells 0 1 2 | 3 8 7 | 6 5 4
        assertArrayEquals(new int[] { 0, 1, 2, 3, 8, 7, 6, 5, 4 }, rays(new PacketOrder(grid, 0, false)),
                "TC01: the serpentine over a 3 × 3 grid");
        // TC02: with the centre, in the middle of the packet (after 4 of the 9 cells)
        PacketOrder withCentre = new PacketOrder(grid, 0, true);
        assertArrayEquals(new int[] { 0, 1, 2, 3, PacketOrder.CENTRE, 8, 7, 6, 5, 4 }, rays(withCentre),
                "TC02: the centre's ray at place 4");
        assertEquals(4, withCentre.centrePlace(), "TC02: the centre's place");
        // TC03: each cell's place is where its ray is
        for (int cell = 0; cell < 9; ++cell)
            assertEquals(cell, withCentre.rayAt(withCentre.placeOf(cell)), "TC03: cell " + cell);
        // TC04: on a 9 × 9 grid, each ray's cell is next to the one before it in the packet
        JitteredGrid nine = new JitteredGrid(9);
        int[][] cells = cells(nine, new PacketOrder(nine, 0, false));
        assertEquals(81, cells.length, "TC04: every cell once");
        for (int place = 1; place < cells.length; ++place)
            assertEquals(1, Math.abs(cells[place][0] - cells[place - 1][0]) + Math.abs(cells[place][1] - cells[place - 1][1]),
                    "TC04: place " + place + " must be a neighbour of the place before");
        // TC05: from the first inner cell on: only the inner cells, in serpentine order, no centre
        PacketOrder inner = new PacketOrder(nine, nine.getOutlineCount(), false);
        assertEquals(49, inner.size(), "TC05: the 7 × 7 inner cells");
        assertEquals(-1, inner.centrePlace(), "TC05: no centre");
        int[][] innerCells = cells(nine, inner);
        // the grid's row 1 (odd) runs backwards, row 2 forwards
        assertArrayEquals(new int[] { 7, 1 }, innerCells[0], "TC05: starts at the end of the first inner row");
        assertArrayEquals(new int[] { 1, 2 }, innerCells[7], "TC05: the second inner row forwards");
        for (int place = 1; place < innerCells.length; ++place)
            assertEquals(1, Math.abs(innerCells[place][0] - innerCells[place - 1][0])
                    + Math.abs(innerCells[place][1] - innerCells[place - 1][1]), "TC05: place " + place);
        for (int cell = nine.getOutlineCount(); cell < 81; ++cell)
            assertEquals(cell, inner.rayAt(inner.placeOf(cell)), "TC05: cell " + cell);

        // ===== Boundary Values Tests =====
        // TC11: k = 1 with the centre: the centre's ray, then the only cell's
        assertArrayEquals(new int[] { PacketOrder.CENTRE, 0 }, rays(new PacketOrder(new JitteredGrid(1), 0, true)),
                "TC11: the centre first");
        // TC12: k = 2, no inner cell: an empty packet
        assertEquals(0, new PacketOrder(new JitteredGrid(2), 4, false).size(), "TC12: no inner cell");
    }

    /** Tests for {@link PacketOrder#isFor}. */
    @Test
    void testIsFor() {
        JitteredGrid grid = new JitteredGrid(3);
        PacketOrder order = new PacketOrder(grid, 0, true);
        // ===== Equivalence Partitions Tests =====
        // TC01: the grid it was made for
        assertTrue(order.isFor(grid), "TC01: its own grid");
        // TC02: another grid of the same size
        assertFalse(order.isFor(new JitteredGrid(3)), "TC02: another grid");
    }
}
