package accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import benchmark.SphereMesh;
import geometries.TriangleMesh;
import primitives.Point3D;
import testutil.TestMeshes;

/** Unit tests for {@link ClosedParts}: welded vertices, connected parts, closed parts and their balls. */
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
        return java.util.Arrays.stream(welded).distinct().count();
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
