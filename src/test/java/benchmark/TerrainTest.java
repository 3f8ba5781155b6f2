package benchmark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Triangle;
import primitives.Point3D;

/**
 * Unit tests for {@link benchmark.Terrain}: the height function, the grid's size for a number of
 * triangles, and every vertex on the heightfield within its extent.
 */
class TerrainTest {
    private static final double DELTA = 1e-9;

    /** Test method for {@link Terrain#height(double, double)}. */
    @Test
    void testHeight() {
        // ===== Equivalence Partitions Tests =====
        // TC01: at (10, 20): −45.5 + 2.5·sin 3·cos 5 + 1.5·sin 1.8·sin 2.6
        assertEquals(-45.5 + 2.5 * Math.sin(3) * Math.cos(5) + 1.5 * Math.sin(1.8) * Math.sin(2.6),
                Terrain.height(10, 20), DELTA, "TC01: wrong height");

        // ===== Boundary Values Tests =====
        // TC11: at the origin both bumps vanish: −45.5
        assertEquals(-45.5, Terrain.height(0, 0), DELTA, "TC11: wrong height at the origin");
    }

    /**
     * Test method for {@link Terrain#triangles(int)}, {@link Terrain#cellsAlongX(int)} and
     * {@link Terrain#cellsAlongZ(int)}.
     */
    @Test
    void testTriangles() {
        // ===== Equivalence Partitions Tests =====
        // TC01: about 10,000 triangles: 33 × 152 cells, 10,032 triangles, every vertex on the
        // heightfield within x ∈ [−200, 200], z ∈ [−1500, 340]
        assertEquals(33, Terrain.cellsAlongX(10_000), "TC01: wrong cells along x");
        assertEquals(152, Terrain.cellsAlongZ(10_000), "TC01: wrong cells along z");
        List<Triangle> triangles = Terrain.triangles(10_000);
        assertEquals(2 * 33 * 152, triangles.size(), "TC01: wrong triangles count");
        for (Triangle triangle : triangles)
            for (Point3D p : triangle.getVertices()) {
                assertEquals(Terrain.height(p.getX(), p.getZ()), p.getY(), DELTA, "TC01: a vertex off the heightfield");
                assertTrue(p.getX() >= -200 - DELTA && p.getX() <= 200 + DELTA, "TC01: x out of range " + p);
                assertTrue(p.getZ() >= -1500 - DELTA && p.getZ() <= 340 + DELTA, "TC01: z out of range " + p);
            }

        // ===== Boundary Values Tests =====
        // TC11: 2 triangles: the cells stay about square, so 1 × 2 cells (4 triangles), the first and
        // the last corner the corners of the extent
        List<Triangle> few = Terrain.triangles(2);
        assertEquals(4, few.size(), "TC11: 1 x 2 cells make four triangles");
        Point3D corner = few.get(0).getVertices().get(0);
        assertEquals(-200, corner.getX(), DELTA, "TC11: the first corner's x");
        assertEquals(-1500, corner.getZ(), DELTA, "TC11: the first corner's z");
        Point3D far = few.get(3).getVertices().get(1);
        assertEquals(200, far.getX(), DELTA, "TC11: the far corner's x");
        assertEquals(340, far.getZ(), DELTA, "TC11: the far corner's z");
        // TC12: fewer than 2 triangles are rejected
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Terrain.triangles(1),
                "TC12: 1 triangle must throw"), "2 triangles", "TC12");
    }
}
