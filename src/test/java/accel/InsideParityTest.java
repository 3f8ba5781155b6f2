package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestMeshes.cube;
import static testutil.TestMeshes.cubeFaces;
import static testutil.TestMeshes.merge;

import java.util.stream.IntStream;

import org.junit.jupiter.api.Test;

import geometries.TriangleMesh;
import primitives.Point3D;

/**
 * Unit tests for {@link InsideParity}: whether a point lies inside a closed mesh by the parity of its
 * rays' crossings, and (through {@link ClosedParts#isClosed}) which meshes are closed at all.
 */
class InsideParityTest {
    /** The tetrahedron (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), its four faces. */
    private static final double[] TETRAHEDRON_VERTICES = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    private static final int[] TETRAHEDRON_FACES = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };

    /** {@return whether a mesh is closed by vertex index: every edge used by an even number of its triangles} */
    private static boolean isClosed(TriangleMesh mesh) {
        return ClosedParts.isClosed(IntStream.range(0, mesh.getVerticesCount()).toArray(), mesh.indices(),
                IntStream.range(0, mesh.getTrianglesCount()).toArray());
    }

    /**
     * The tetrahedron (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1) moved by a point.
     *
     * @param at where the first vertex goes
     * @return the mesh
     */
    private static TriangleMesh tetrahedron(Point3D at) {
        double[] vertices = TETRAHEDRON_VERTICES.clone();
        for (int i = 0; i < vertices.length; i += 3) {
            vertices[i] += at.getX();
            vertices[i + 1] += at.getY();
            vertices[i + 2] += at.getZ();
        }
        return new TriangleMesh(vertices, TETRAHEDRON_FACES);
    }
    /** {@return the unit cube whose x-max face's triangles use vertex 8, a copy of vertex 7} */
    private static TriangleMesh cubeWithCopiedVertex() {
        double[] vertices = new double[27];
        for (int i = 0; i < 8; ++i)
            setVertex(vertices, i, new Point3D(i & 1, i >> 1 & 1, i >> 2 & 1));
        setVertex(vertices, 8, new Point3D(1, 1, 1));
        int[] faces = cubeFaces();
        for (int i = faces.length - 6; i < faces.length; ++i)
            if (faces[i] == 7)
                faces[i] = 8;
        return new TriangleMesh(vertices, faces);
    }
    /** {@return two arrays one after the other} */
    private static int[] concat(int[] first, int[] second) {
        int[] both = new int[first.length + second.length];
        System.arraycopy(first, 0, both, 0, first.length);
        System.arraycopy(second, 0, both, first.length, second.length);
        return both;
    }
    /** Puts a point's coordinates at vertex v of an array. */
    private static void setVertex(double[] vertices, int v, Point3D point) {
        vertices[3 * v] = point.getX();
        vertices[3 * v + 1] = point.getY();
        vertices[3 * v + 2] = point.getZ();
    }

    /** Test method for {@link ClosedParts#isClosed(int[], int[], int[])}, each vertex standing for itself. */
    @Test
    void testIsClosed() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a sphere's mesh (shared poles) and a cube: closed
        assertTrue(isClosed(benchmark.SphereMesh.mesh(Point3D.ZERO, 5, 8, 12)), "TC01: a sphere is closed");
        assertTrue(isClosed(cube(0, 0, 0, 1)), "TC01: a cube is closed");
        // TC02: a terrain (an open sheet): not closed
        assertFalse(isClosed(benchmark.Terrain.mesh(200)), "TC02: a terrain is open");
        // TC03: a tetrahedron with one face removed: not closed
        assertFalse(isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2 })),
                "TC03: a tetrahedron without a face is open");
        // TC04: two tetrahedra far apart in one mesh: every edge shared twice, closed
        assertTrue(isClosed(merge(tetrahedron(Point3D.ZERO), tetrahedron(new Point3D(10, 0, 0)))),
                "TC04: two separate tetrahedra are closed");
        // TC05: a cube whose x-max face uses a copy of vertex 7 (same position, index 8): open by index
        assertFalse(isClosed(cubeWithCopiedVertex()), "TC05: a copied vertex opens the mesh");

        // ===== Boundary Values Tests =====
        // TC11: a single triangle: open
        assertFalse(isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 1, 2 })),
                "TC11: a single triangle is open");
        // TC12: a tetrahedron plus a copy of one of its faces: three edges used three times, open
        assertFalse(isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, concat(TETRAHEDRON_FACES,
                new int[] { 1, 2, 3 }))), "TC12: a face listed twice leaves edges used three times");
        // TC13: a triangle listed twice, once each way round: every edge used twice, closed (though flat)
        assertTrue(isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 1, 2, 0, 2, 1 })),
                "TC13: a triangle and its reverse share every edge");
        // TC14: the tetrahedron with one face turned the other way round: edges by index, closed
        assertTrue(isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2,
                1, 3, 2 })), "TC14: the faces' orientation must not matter");
        // TC15: two tetrahedra sharing an edge (a bow tie): that edge used four times, closed
        double[] bowTie = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1 };
        assertTrue(isClosed(new TriangleMesh(bowTie, concat(TETRAHEDRON_FACES,
                new int[] { 0, 1, 4, 0, 5, 1, 0, 4, 5, 1, 5,
                        4 }))), "TC15: an edge shared by four triangles is closed");
    }

    /** Test method for {@link InsideParity#parity(TriangleMesh, double, double, double)}. */
    @Test
    void testParity() {
        TriangleMesh box = cube(0, 0, 0, 2);
        TriangleMesh twoTetrahedra = merge(tetrahedron(Point3D.ZERO), tetrahedron(new Point3D(10, 0, 0)));
        // ===== Equivalence Partitions Tests =====
        // TC01: the cube's centre and a point off-centre inside it: 1
        assertEquals(1, InsideParity.parity(box, 1, 1, 1), "TC01: the cube's centre is inside");
        assertEquals(1, InsideParity.parity(box, 0.3, 1.7, 0.9), "TC01: a point off-centre is inside");
        // TC02: points beside, above and far from the cube: 0
        assertEquals(0, InsideParity.parity(box, 3, 1, 1), "TC02: a point beside the cube is outside");
        assertEquals(0, InsideParity.parity(box, 1, 5, 1), "TC02: a point above the cube is outside");
        assertEquals(0, InsideParity.parity(box, -40, 70, 12), "TC02: a far point is outside");
        // TC03: a mesh of two tetrahedra: inside either one, 1; between them, 0
        assertEquals(1, InsideParity.parity(twoTetrahedra, 0.2, 0.2, 0.2), "TC03: inside the first tetrahedron");
        assertEquals(1, InsideParity.parity(twoTetrahedra, 10.2, 0.2, 0.2), "TC03: inside the second tetrahedron");
        assertEquals(0, InsideParity.parity(twoTetrahedra, 5, 0.2, 0.2), "TC03: between them is outside");

        // ===== Boundary Values Tests =====
        // TC11: a point 1e-6 inside a face and one 1e-6 outside it: 1 and 0
        assertEquals(1, InsideParity.parity(box, 2 - 1e-6, 0.7, 1.2), "TC11: just inside a face");
        assertEquals(0, InsideParity.parity(box, 2 + 1e-6, 0.7, 1.2), "TC11: just outside a face");
        // TC12: an open mesh (a tetrahedron without a face): the parity rays disagree or cross once; a
        // point outside the open side's plane yet under it is never told inside by all three
        TriangleMesh open = new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2 });
        assertTrue(InsideParity.parity(open, 0.2, 0.2, 0.2) != 0,
                "TC12: inside the open tetrahedron the point must not be told outside");
    }
}
