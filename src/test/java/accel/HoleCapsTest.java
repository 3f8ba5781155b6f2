package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.stream.IntStream;

import org.junit.jupiter.api.Test;

import geometries.TriangleMesh;
import primitives.Point3D;
import testutil.TestMeshes;

/** Unit tests for {@link accel.HoleCaps}: the caps over the small holes of an open mesh part. */
class HoleCapsTest {
    private static final double DELTA = 1e-9;

    /** {@return the caps over the holes of a mesh taken as one part} */
    private static HoleCaps capsOf(TriangleMesh mesh) {
        return HoleCaps.of(mesh, ClosedParts.weld(mesh), mesh.indices(),
                IntStream.range(0, mesh.getTrianglesCount()).toArray());
    }

    /** Test method for {@link HoleCaps#of(TriangleMesh, int[], int[], int[])}. */
    @Test
    void testOf() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a bowl of 24 rings and 48 slices (a sphere's mesh of radius 2 at (1, 2, 3) without its top
        // fan): one hole, its 48 rim edges capped from its centroid, on the axis at the rim's height
        TriangleMesh bowl = TestMeshes.bowl(new Point3D(1, 2, 3), 2, 24, 48);
        HoleCaps caps = capsOf(bowl);
        assertNotNull(caps, "TC01: the bowl's hole must be capped");
        assertEquals(3, caps.centroids.length, "TC01: one hole");
        assertEquals(3 * 48, caps.triangles.length, "TC01: a cap triangle per rim edge");
        Point3D centroid = caps.centroidOf(0);
        assertEquals(1, centroid.getX(), DELTA, "TC01: the centroid on the axis (x)");
        assertEquals(2 + 2 * Math.cos(Math.PI / 24), centroid.getY(), DELTA, "TC01: the centroid at the rim's height");
        assertEquals(3, centroid.getZ(), DELTA, "TC01: the centroid on the axis (z)");
        // TC02: the cap's box holds the rim, grown a little: x and z within the rim's radius, and more
        double rim = 2 * Math.sin(Math.PI / 24);
        assertTrue(caps.boxes[0] < 1 - rim + DELTA && caps.boxes[3] > 1 + rim - DELTA, "TC02: the box across x");
        assertTrue(caps.boxes[1] <= centroid.getY() && caps.boxes[4] >= centroid.getY(), "TC02: the box holds the centroid");
        assertTrue(caps.boxes[0] > 1 - rim - 1e-3, "TC02: the box is grown by a rounding margin only");

        // ===== Boundary Values Tests =====
        // TC11: a bowl of 8 rings: its hole, 38 % of its extent across, is too large
        assertNull(capsOf(TestMeshes.bowl(new Point3D(1, 2, 3), 2, 8, 16)), "TC11: a wide hole is not capped");
        // TC12: a bowl of 14 rings: its hole, 22 % across (an eye socket's size), is capped
        assertNotNull(capsOf(TestMeshes.bowl(new Point3D(1, 2, 3), 2, 14, 16)), "TC12: a hole 22 % across is capped");
        // TC13: a bowl of 12 rings: its hole, 26 % across, is too large
        assertNull(capsOf(TestMeshes.bowl(new Point3D(1, 2, 3), 2, 12, 16)), "TC13: a hole 26 % across is not capped");
        // TC14: a square of two triangles: its rim is all of it
        assertNull(capsOf(new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 },
                new int[] { 0, 1, 2, 0, 2, 3 })), "TC14: a square is not capped");
    }
}
