package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestMeshes.cube;
import static testutil.TestMeshes.merge;
import static testutil.TestMeshes.tetrahedron;
import static testutil.TestMeshes.tetrahedronVertices;

import org.junit.jupiter.api.Test;

import geometries.TriangleMesh;
import primitives.Point3D;

/**
 * Unit tests for {@link InsideParity}: whether a point lies inside a closed mesh by the parity of its
 * rays' crossings.
 */
class InsideParityTest {
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
        TriangleMesh open = new TriangleMesh(tetrahedronVertices(), new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2 });
        assertTrue(InsideParity.parity(open, 0.2, 0.2, 0.2) != 0,
                "TC12: inside the open tetrahedron the point must not be told outside");
    }
}
