package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import primitives.Point3D;
import primitives.Vector;

/**
 * Unit tests for {@link MeshPoint}: a hit on a mesh knows its triangle, and finds its normal, shadow
 * point and surface coordinates from it.
 */
class MeshPointTest {
    /** Tolerance for doubles. */
    private static final double DELTA = 1e-12;

    /** The unit square z = 0 of two triangles, (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1), facing +z. */
    private static TriangleMesh square() {
        return new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 }, new int[] { 0, 1, 2, 0, 2, 3 });
    }

    /** Test method for {@link MeshPoint#MeshPoint(TriangleMesh, int, Point3D)} and its getters. */
    @Test
    void testMeshPoint() {
        TriangleMesh flat = square();
        Point3D p = new Point3D(0.25, 0.75, 0);
        MeshPoint hit = new MeshPoint(flat, 1, p);
        // ===== Equivalence Partitions Tests =====
        // TC01: its mesh, triangle and point are kept
        assertSame(flat, hit.geometry, "TC01: the mesh");
        assertEquals(1, hit.triangle, "TC01: the triangle");
        assertSame(p, hit.point, "TC01: the point");
        // TC02: on a flat mesh, the normal is the triangle's (0, 0, 1), and the shadow point the point itself
        assertEquals(new Vector(0, 0, 1), hit.getNormal(), "TC02: the flat normal");
        assertSame(p, hit.getShadowPoint(new Vector(0, 0, 1)), "TC02: no lift on a flat mesh");
        // TC03: with UVs = the vertices' x and y, the point's UV is its own x and y
        TriangleMesh textured = square().setUVs(new double[] { 0, 0, 1, 0, 1, 1, 0, 1 });
        assertArrayEquals(new double[] { 0.25, 0.75 }, new MeshPoint(textured, 1, p).getUV(), DELTA,
                "TC03: the UV mixed by the barycentric weights");
        // TC04: on a smooth mesh of normals all (0, 0, 1), the normal is (0, 0, 1)
        TriangleMesh smooth = square().setNormals(new double[] { 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1 });
        Vector n = new MeshPoint(smooth, 1, p).getNormal();
        assertEquals(0, n.getX(), DELTA, "TC04: x");
        assertEquals(0, n.getY(), DELTA, "TC04: y");
        assertEquals(1, n.getZ(), DELTA, "TC04: z");
        // TC05: the face normal: the triangle's (0, 0, 1) on the smooth mesh, none (null) on the flat one
        assertEquals(new Vector(0, 0, 1), new MeshPoint(smooth, 1, p).getFaceNormal(), "TC05: the smooth mesh's face");
        org.junit.jupiter.api.Assertions.assertNull(hit.getFaceNormal(), "TC05: a flat mesh is its own face");

        // ===== Boundary Values Tests =====
        // TC11: a hit at a vertex (the triangles' shared (0, 0, 0)): its UV is the vertex's, (0, 0)
        assertArrayEquals(new double[] { 0, 0 }, new MeshPoint(textured, 0, Point3D.ZERO).getUV(), DELTA,
                "TC11: the UV at a vertex");
        // TC12: its text names the triangle and the point
        String text = hit.toString();
        assertTrue(text.contains("triangle 1") && text.contains(p.toString()), "TC12: wrong text " + text);
    }
}
