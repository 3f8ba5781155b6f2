package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestMeshes.cube;
import static testutil.TestMeshes.cuboid;
import static testutil.TestMeshes.merge;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

import benchmark.SphereMesh;
import geometries.TriangleMesh;
import primitives.Point3D;

/**
 * Unit tests for {@link InnerBoxes}: boxes inside a closed mesh that touch none of its triangles.
 */
class InnerBoxesTest {
    /**
     * Asserts the boxes' promise: each box is proper, lies inside the mesh (seeded random points of it
     * are inside by the parity rays, when they are sure) and meets no triangle's box.
     *
     * @param mesh  the mesh
     * @param boxes its inner boxes
     * @param tc    the test case's label
     */
    private static void assertInside(TriangleMesh mesh, double[] boxes, String tc) {
        double[] triangle = new double[6];
        Random rnd = new Random(6);
        for (int b = 0; b < boxes.length; b += 6) {
            String label = tc + ": box " + Arrays.toString(Arrays.copyOfRange(boxes, b, b + 6));
            for (int k = 0; k < 3; ++k)
                assertTrue(boxes[b + k] < boxes[b + 3 + k], label + " must be proper");
            for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
                mesh.bounds(t, triangle, 0);
                boolean apart = false;
                for (int k = 0; k < 3; ++k)
                    apart |= triangle[3 + k] < boxes[b + k] || triangle[k] > boxes[b + 3 + k];
                assertTrue(apart, label + " must meet no triangle's box (triangle " + t + ")");
            }
            for (int s = 0; s < 5; ++s) {
                double[] p = new double[3];
                for (int k = 0; k < 3; ++k)
                    p[k] = boxes[b + k] + rnd.nextDouble() * (boxes[b + 3 + k] - boxes[b + k]);
                int parity = InsideParity.parity(mesh, p[0], p[1], p[2]);
                assertTrue(parity != 0, label + ": its point " + Arrays.toString(p) + " must not be outside");
            }
        }
    }

    /** Test method for {@link InnerBoxes#of(TriangleMesh)}. */
    @Test
    void testOf() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a cube [0, 10]³: boxes inside it, the first (the largest) its whole inside
        TriangleMesh box = cube(0, 0, 0, 10);
        double[] inCube = InnerBoxes.of(box);
        assertTrue(inCube.length >= 6, "TC01: a cube has an inner box");
        assertInside(box, inCube, "TC01");
        // ... and it is all of the cube's inside cells: 4,096 cells of 0.625 over the box, those of the faces
        // touched, so [0.625, 9.375] each way (the grown box of the deepest cell, its depth a chessboard distance)
        for (int k = 0; k < 3; ++k) {
            assertEquals(0.625, inCube[k], 1e-6, "TC01: the first box's low side along axis " + k);
            assertEquals(9.375, inCube[3 + k], 1e-6, "TC01: the first box's high side along axis " + k);
        }
        // TC02: a sphere's mesh of radius 5 around (1, 2, 3): every box corner within the radius
        Point3D centre = new Point3D(1, 2, 3);
        TriangleMesh sphere = SphereMesh.mesh(centre, 5, 16, 24);
        double[] inSphere = InnerBoxes.of(sphere);
        assertTrue(inSphere.length >= 6, "TC02: a sphere has an inner box");
        assertInside(sphere, inSphere, "TC02");
        for (int b = 0; b < inSphere.length; b += 6)
            for (int corner = 0; corner < 8; ++corner) {
                Point3D p = new Point3D(inSphere[b + ((corner & 1) == 0 ? 0 : 3)],
                        inSphere[b + 1 + ((corner & 2) == 0 ? 0 : 3)], inSphere[b + 2 + ((corner & 4) == 0 ? 0 : 3)]);
                assertTrue(p.distance(centre) < 5, "TC02: corner " + p + " of a box lies in the sphere");
            }
        // TC03: two cubes apart in one mesh: boxes in both, each inside one of them
        TriangleMesh two = merge(cube(0, 0, 0, 10), cube(20, 0, 0, 10));
        double[] inTwo = InnerBoxes.of(two);
        assertInside(two, inTwo, "TC03");
        boolean first = false;
        boolean second = false;
        for (int b = 0; b < inTwo.length; b += 6) {
            first |= inTwo[b + 3] < 10;
            second |= inTwo[b] > 20;
            assertTrue(inTwo[b + 3] < 10 || inTwo[b] > 20, "TC03: each box lies in one cube");
        }
        assertTrue(first && second, "TC03: both cubes have boxes");
        // TC04: a cube without its top (an open mesh): the inside reaches the outside: no box
        TriangleMesh cubeMesh = cube(0, 0, 0, 10);
        int[] indices = cubeMesh.indices();
        double[] vertices = cubeMesh.coordinates();
        int[] open = openTop(vertices, indices);
        assertEquals(0, InnerBoxes.of(new TriangleMesh(vertices, open)).length, "TC04: an open box has no inner box");

        // ===== Boundary Values Tests =====
        // TC11: a slab 10 × 10 × 0.1, thinner than a cell: no box
        TriangleMesh slab = cuboid(0, 0, 0, 10, 10, 0.1);
        assertEquals(0, InnerBoxes.of(slab).length, "TC11: a slab thinner than a cell has no box");
        // TC12: a flat mesh (no extent along z): no box
        TriangleMesh flat = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 },
                new int[] { 0, 1, 2, 1, 3, 2, 0, 2, 1, 1, 2, 3 });
        assertEquals(0, InnerBoxes.of(flat).length, "TC12: a flat mesh has no box");
        // TC13: a sphere of many cells: at most MAX_BOXES boxes
        assertTrue(inSphere.length / 6 <= InnerBoxes.MAX_BOXES, "TC13: at most " + InnerBoxes.MAX_BOXES + " boxes");
    }

    /**
     * The triangles of a cube but those of its top face (all four vertices at z = max).
     *
     * @param vertices the cube's vertices, three coordinates each
     * @param indices  its triangles' vertex indices
     * @return the indices of the other triangles
     */
    private static int[] openTop(double[] vertices, int[] indices) {
        double top = Double.NEGATIVE_INFINITY;
        for (int v = 2; v < vertices.length; v += 3)
            top = Math.max(top, vertices[v]);
        int[] kept = new int[indices.length];
        int count = 0;
        for (int t = 0; t < indices.length; t += 3) {
            boolean onTop = true;
            for (int k = 0; k < 3; ++k)
                onTop &= vertices[3 * indices[t + k] + 2] == top;
            if (!onTop)
                for (int k = 0; k < 3; ++k)
                    kept[count++] = indices[t + k];
        }
        return Arrays.copyOf(kept, count);
    }
}
