package accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestMeshes.cube;
import static testutil.TestMeshes.cubeFaces;
import static testutil.TestMeshes.merge;
import static testutil.TestMeshes.tetrahedron;
import static testutil.TestMeshes.tetrahedronFaces;
import static testutil.TestMeshes.tetrahedronVertices;

import java.util.Arrays;
import java.util.List;
import java.util.stream.IntStream;

import org.junit.jupiter.api.Test;

import benchmark.SphereMesh;
import geometries.TriangleMesh;
import primitives.Point3D;
import testutil.TestMeshes;

/** Unit tests for {@link ClosedParts}: welded vertices, closed meshes, connected parts and their inner boxes. */
class ClosedPartsTest {
    private static final double DELTA = 1e-9;

    /**
     * The unit cube with its vertices repeated per face (24 vertices, 4 per face, as a scan's seams
     * repeat them): closed only once its vertices are welded.
     *
     * @param x0 the low corner's x
     * @return the mesh
     */
    private static TriangleMesh cubeOfSeparateFaces(double x0) {
        TriangleMesh cube = TestMeshes.cube(x0, 0, 0, 1);
        double[] vertices = new double[3 * 3 * cube.getTrianglesCount()];
        int[] indices = new int[3 * cube.getTrianglesCount()];
        for (int t = 0; t < cube.getTrianglesCount(); ++t)
            for (int k = 0; k < 3; ++k) {
                Point3D p = cube.getVertex(cube.getVertexIndex(t, k));
                vertices[9 * t + 3 * k] = p.getX();
                vertices[9 * t + 3 * k + 1] = p.getY();
                vertices[9 * t + 3 * k + 2] = p.getZ();
                indices[3 * t + k] = 3 * t + k;
            }
        return new TriangleMesh(vertices, indices);
    }

    /** {@return the number of distinct welded vertices} */
    private static long distinct(int[] welded) {
        return Arrays.stream(welded).distinct().count();
    }

    /** {@return whether a mesh is closed by vertex index: every edge used by an even number of its triangles} */
    private static boolean isClosed(TriangleMesh mesh) {
        return ClosedParts.isClosed(IntStream.range(0, mesh.getVerticesCount()).toArray(), mesh.indices(),
                IntStream.range(0, mesh.getTrianglesCount()).toArray());
    }

    /** {@return the unit cube whose x-max face's triangles use vertex 8, a copy of vertex 7} */
    private static TriangleMesh cubeWithCopiedVertex() {
        double[] vertices = Arrays.copyOf(cube(0, 0, 0, 1).coordinates(), 27);
        Arrays.fill(vertices, 24, 27, 1); // vertex 7's corner (1, 1, 1) again
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

    /** Test method for {@link ClosedParts#weld(TriangleMesh)}. */
    @Test
    void testWeld() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a cube whose 36 corners are vertices of their own: 8 welded vertices
        int[] welded = ClosedParts.weld(cubeOfSeparateFaces(0));
        assertEquals(36, welded.length, "TC01: one entry per vertex");
        assertEquals(8, distinct(welded), "TC01: the cube's 8 corners");
        for (int v = 0; v < welded.length; ++v)
            assertTrue(welded[v] <= v, "TC01: a vertex is welded to the first with its coordinates");
        // TC02: a mesh whose vertices are all different: each its own
        int[] own = ClosedParts.weld(TestMeshes.cube(0, 0, 0, 1));
        for (int v = 0; v < own.length; ++v)
            assertEquals(v, own[v], "TC02: vertex " + v + " is its own");

        // ===== Boundary Values Tests =====
        // TC11: 0.0 and −0.0 differ in their bits: not welded (the weld is exact to the bit)
        TriangleMesh signs = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, -0.0, 0, 0 },
                new int[] { 0, 1, 2, 3, 1, 2 });
        assertEquals(3, ClosedParts.weld(signs)[3], "TC11: -0.0 is not 0.0's vertex");
        // TC12: two vertices one ulp apart: not welded
        TriangleMesh ulp = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, Math.ulp(0.0), 0, 0 },
                new int[] { 0, 1, 2, 3, 1, 2 });
        assertEquals(3, ClosedParts.weld(ulp)[3], "TC12: a vertex one ulp away is not welded");
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
        assertFalse(isClosed(new TriangleMesh(tetrahedronVertices(), new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2 })),
                "TC03: a tetrahedron without a face is open");
        // TC04: two tetrahedra far apart in one mesh: every edge shared twice, closed
        assertTrue(isClosed(merge(tetrahedron(Point3D.ZERO), tetrahedron(new Point3D(10, 0, 0)))),
                "TC04: two separate tetrahedra are closed");
        // TC05: a cube whose x-max face uses a copy of vertex 7 (same position, index 8): open by index
        assertFalse(isClosed(cubeWithCopiedVertex()), "TC05: a copied vertex opens the mesh");

        // ===== Boundary Values Tests =====
        // TC11: a single triangle: open
        assertFalse(isClosed(new TriangleMesh(tetrahedronVertices(), new int[] { 0, 1, 2 })),
                "TC11: a single triangle is open");
        // TC12: a tetrahedron plus a copy of one of its faces: three edges used three times, open
        assertFalse(isClosed(new TriangleMesh(tetrahedronVertices(), concat(tetrahedronFaces(),
                new int[] { 1, 2, 3 }))), "TC12: a face listed twice leaves edges used three times");
        // TC13: a triangle listed twice, once each way round: every edge used twice, closed (though flat)
        assertTrue(isClosed(new TriangleMesh(tetrahedronVertices(), new int[] { 0, 1, 2, 0, 2, 1 })),
                "TC13: a triangle and its reverse share every edge");
        // TC14: the tetrahedron with one face turned the other way round: edges by index, closed
        assertTrue(isClosed(new TriangleMesh(tetrahedronVertices(), new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2,
                1, 3, 2 })), "TC14: the faces' orientation must not matter");
        // TC15: two tetrahedra sharing an edge (a bow tie): that edge used four times, closed
        double[] bowTie = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1 };
        assertTrue(isClosed(new TriangleMesh(bowTie, concat(tetrahedronFaces(),
                new int[] { 0, 1, 4, 0, 5, 1, 0, 4, 5, 1, 5, 4 }))), "TC15: an edge shared by four triangles is closed");
    }

    /** Test method for {@link ClosedParts#of(TriangleMesh)}. */
    @Test
    void testOf() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a sphere's mesh: one part, whose inner boxes are InnerBoxes.of's and whose box is the mesh's
        TriangleMesh sphere = SphereMesh.mesh(new Point3D(1, 2, 3), 4, 8, 12);
        List<ClosedParts.Part> parts = ClosedParts.of(sphere);
        assertEquals(1, parts.size(), "TC01: a sphere's mesh is one closed part");
        assertArrayEquals(InnerBoxes.of(sphere), parts.get(0).innerBoxes(), "TC01: InnerBoxes.of's boxes");
        double[] box = new double[6];
        sphere.bounds(box, 0);
        for (int k = 0; k < 6; ++k)
            assertEquals(box[k], parts.get(0).box()[k], 0, "TC01: the part's box is the mesh's, number " + k);
        // TC02: three spheres as one mesh: three parts, each core inside its own sphere
        Point3D[] centres = { new Point3D(-30, 0, 0), new Point3D(0, 0, 0), new Point3D(30, 0, 0) };
        double[] radii = { 5, 10, 7 };
        TriangleMesh[] spheres = new TriangleMesh[3];
        for (int s = 0; s < 3; ++s)
            spheres[s] = SphereMesh.mesh(centres[s], radii[s], 8, 16);
        List<ClosedParts.Part> three = ClosedParts.of(TestMeshes.merge(spheres));
        assertEquals(3, three.size(), "TC02: three closed parts");
        for (ClosedParts.Part part : three) {
            double[] inner = part.innerBoxes();
            boolean inOne = false;
            for (int s = 0; s < 3; ++s) {
                boolean all = true;
                for (int b = 0; b < inner.length; b += 6)
                    all &= new Point3D(inner[b], inner[b + 1], inner[b + 2]).distance(centres[s]) < radii[s]
                            && new Point3D(inner[b + 3], inner[b + 4], inner[b + 5]).distance(centres[s]) < radii[s];
                inOne |= all;
            }
            assertTrue(inOne, "TC02: each part's inner boxes lie inside one of the spheres");
        }
        // TC03: an open mesh (one square): no part
        TriangleMesh square = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 },
                new int[] { 0, 1, 2, 0, 2, 3 });
        assertTrue(ClosedParts.of(square).isEmpty(), "TC03: an open mesh has no closed part");
        // TC04: a cube whose faces repeat their vertices: closed once welded
        TriangleMesh seams = cubeOfSeparateFaces(0);
        assertEquals(1, ClosedParts.of(seams).size(), "TC04: welded, the cube is one closed part");

        // TC05: a bowl (a sphere's mesh of 24 rings without its top fan): one part, closed by a cap over its
        // hole, the cap's box around the hole at the top, the part's core found
        TriangleMesh bowl = TestMeshes.bowl(new Point3D(0, 0, 0), 2, 24, 48);
        List<ClosedParts.Part> capped = ClosedParts.of(bowl);
        assertEquals(1, capped.size(), "TC05: a bowl with a small hole is one part");
        double[] cap = capped.get(0).capBoxes();
        assertEquals(6, cap.length, "TC05: one cap");
        assertEquals(2 * Math.cos(Math.PI / 24), cap[1], 1e-5, "TC05: the cap lies at the hole's ring");
        assertTrue(capped.get(0).coreSize() > 1, "TC05: the capped part has a core: " + capped.get(0).coreSize());
        assertEquals(0, parts.get(0).capBoxes().length, "TC05: a closed part has no cap");

        // ===== Boundary Values Tests =====
        // TC11: asked again: the same list, kept
        assertSame(parts, ClosedParts.of(sphere), "TC11: the parts are found once and kept");
        // TC12: a closed cube and an open square in one mesh: the cube's part alone
        TriangleMesh mixed = TestMeshes.merge(TestMeshes.cube(5, 5, 5, 1), square);
        List<ClosedParts.Part> cubeOnly = ClosedParts.of(mixed);
        assertEquals(1, cubeOnly.size(), "TC12: only the cube is closed");
        assertEquals(5, cubeOnly.get(0).box()[0], 1e-6, "TC12: the part is the cube");
        // TC13: two cubes with faces of their own, apart in one mesh: two parts
        assertEquals(2, ClosedParts.of(TestMeshes.merge(cubeOfSeparateFaces(0), cubeOfSeparateFaces(3))).size(),
                "TC13: two welded cubes are two parts");
        // TC14: two cubes sharing a corner: one part by the weld, closed, with inner boxes, each inside
        // one of the cubes [0, 1]³ and [1, 2]³
        TriangleMesh touching = TestMeshes.merge(TestMeshes.cube(0, 0, 0, 1), TestMeshes.cube(1, 1, 1, 1));
        List<ClosedParts.Part> corner = ClosedParts.of(touching);
        assertEquals(1, corner.size(), "TC14: cubes sharing a corner are one part");
        double[] inner = corner.get(0).innerBoxes();
        assertTrue(inner.length > 0, "TC14: the cubes have inner boxes");
        for (int b = 0; b < inner.length; b += 6) {
            double low = inner[b] < 1 ? 0 : 1;
            for (int k = 0; k < 3; ++k)
                assertTrue(inner[b + k] > low && inner[b + 3 + k] < low + 1, "TC14: box " + b / 6 + " in one cube");
        }
    }
}
