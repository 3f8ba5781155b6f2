package geometries;

import testutil.TestMeshes;
import accel.ShadowFrustum;
import accel.BoundingVolumeHierarchy;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertNearestFirst;
import static testutil.TestAssertions.assertNearestFirstThrough;
import static testutil.TestRandom.randomPoint;
import static testutil.TestRandom.rayThrough;
import static testutil.TestBundles.rayFromTo;
import static testutil.TestBundles.rayState;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

import accel.Query;
import accel.RayState;
import geometries.Intersectable.GeoPoint;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.Render;
import scene.Scene;

/**
 * Unit tests for {@link geometries.TriangleMesh}: validation, the course's open edges on its own
 * queries, normals per triangle, and the same hits and normals as the same triangles given as
 * {@link Triangle} objects, on its own queries, through the hierarchy and the brute-force scan, and
 * in rendered pictures.
 */
class TriangleMeshTest {
    private static final double DELTA = 1e-12;

    /** The unit square in the plane z = 0, split along its diagonal (0,0)–(1,1) into two triangles. */
    private static final double[] SQUARE_VERTICES = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
    private static final int[] SQUARE_TRIANGLES = { 0, 1, 2, 0, 2, 3 };

    private final TriangleMesh square = new TriangleMesh(SQUARE_VERTICES, SQUARE_TRIANGLES);

    /** A ray straight down (along −z) onto the point (x, y) of the square's plane. */
    private static Ray down(double x, double y) {
        return new Ray(new Point3D(x, y, 5), new Vector(0, 0, -1));
    }

    /** Asserts that making a mesh throws an IllegalArgumentException whose message has the given words. */
    private static void assertRejected(Executable making, String tc, String... words) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, making, tc + ": must throw");
        for (String word : words)
            assertMessage(e, word, tc);
    }

    /** Asserts two vectors are equal component by component within {@link #DELTA}. */
    private static void assertVector(Vector expected, Vector actual, String message) {
        assertEquals(expected.getX(), actual.getX(), DELTA, message + " (x)");
        assertEquals(expected.getY(), actual.getY(), DELTA, message + " (y)");
        assertEquals(expected.getZ(), actual.getZ(), DELTA, message + " (z)");
    }

    /** Asserts two points are equal coordinate by coordinate within {@link #DELTA}. */
    private static void assertPoint(Point3D expected, Point3D actual, String message) {
        assertEquals(expected.getX(), actual.getX(), DELTA, message + " (x)");
        assertEquals(expected.getY(), actual.getY(), DELTA, message + " (y)");
        assertEquals(expected.getZ(), actual.getZ(), DELTA, message + " (z)");
    }

    /** Test method for {@link TriangleMesh#TriangleMesh(double[], int[])}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the square: 4 vertices, 2 triangles sharing vertices 0 and 2
        TriangleMesh mesh = assertDoesNotThrow(() -> new TriangleMesh(SQUARE_VERTICES, SQUARE_TRIANGLES),
                "TC01: a correct mesh must be accepted");
        assertEquals(4, mesh.getVerticesCount(), "TC01: wrong vertices count");
        assertEquals(2, mesh.getTrianglesCount(), "TC01: wrong triangles count");
        assertEquals(new Point3D(1, 1, 0), mesh.getVertex(2), "TC01: wrong vertex 2");
        assertEquals(2, mesh.getVertexIndex(1, 1), "TC01: the second triangle's middle vertex is vertex 2");
        assertEquals(List.of(new Point3D(0, 0, 0), new Point3D(1, 1, 0), new Point3D(0, 1, 0)),
                mesh.getTriangle(1).getVertices(), "TC01: wrong vertices of triangle 1");

        // TC02: the arrays are copied: changing them afterwards changes nothing
        double[] vertices = SQUARE_VERTICES.clone();
        int[] indices = SQUARE_TRIANGLES.clone();
        TriangleMesh copied = new TriangleMesh(vertices, indices);
        vertices[0] = 7;
        indices[0] = 3;
        assertEquals(Point3D.ZERO, copied.getVertex(0), "TC02: the mesh must keep its own vertices");
        assertEquals(0, copied.getVertexIndex(0, 0), "TC02: the mesh must keep its own indices");

        // TC03: a vertex no triangle uses is allowed
        assertEquals(5, new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 9, 9, 9, 5, 5, 5 },
                new int[] { 0, 1, 2 }).getVerticesCount(), "TC03: an unused vertex must be kept");

        // TC04: null arrays
        assertRejected(() -> new TriangleMesh(null, SQUARE_TRIANGLES), "TC04", "vertices");
        assertRejected(() -> new TriangleMesh(SQUARE_VERTICES, null), "TC04", "triangles");

        // TC05: a coordinate that is NaN or infinite names its vertex
        assertRejected(() -> new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, Double.NaN, 0 },
                new int[] { 0, 1, 2 }), "TC05", "vertex 2", "finite");
        assertRejected(() -> new TriangleMesh(new double[] { 0, 0, 0, Double.POSITIVE_INFINITY, 0, 0, 1, 1, 0 },
                new int[] { 0, 1, 2 }), "TC05", "vertex 1", "finite");

        // ===== Boundary Values Tests =====
        // TC11: an index equal to the number of vertices names the triangle and the range
        assertRejected(() -> new TriangleMesh(SQUARE_VERTICES, new int[] { 0, 1, 2, 0, 2, 4 }), "TC11",
                "triangle 1", "vertex 4", "out of range [0, 4)");
        // TC12: a negative index
        assertRejected(() -> new TriangleMesh(SQUARE_VERTICES, new int[] { -1, 1, 2 }), "TC12", "triangle 0",
                "vertex -1", "out of range");
        // TC13: a degenerate triangle of collinear vertices names the triangle
        assertRejected(() -> new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0 },
                new int[] { 0, 1, 3, 0, 1, 2 }), "TC13", "triangle 1", "degenerate", "collinear");
        // TC14: a triangle whose vertices coincide (twice the same index, or two equal points)
        assertRejected(() -> new TriangleMesh(SQUARE_VERTICES, new int[] { 0, 1, 2, 2, 2, 3 }), "TC14",
                "triangle 1", "degenerate", "coincide");
        assertRejected(() -> new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 0, 0 }, new int[] { 0, 1, 2 }),
                "TC14", "triangle 0", "coincide");
        // TC15: vertices not in threes, no triangle, indices not in threes
        assertRejected(() -> new TriangleMesh(new double[] { 0, 0, 0, 1 }, SQUARE_TRIANGLES), "TC15", "three");
        assertRejected(() -> new TriangleMesh(SQUARE_VERTICES, new int[0]), "TC15", "one triangle or more");
        assertRejected(() -> new TriangleMesh(SQUARE_VERTICES, new int[] { 0, 1, 2, 3 }), "TC15", "three");
    }

    /** Test method for {@link TriangleMesh#isDegenerate(Point3D, Point3D, Point3D)}. */
    @Test
    void testIsDegenerate() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a proper triangle is not degenerate
        assertEquals(false, TriangleMesh.isDegenerate(Point3D.ZERO, new Point3D(1, 0, 0), new Point3D(0, 1, 0)),
                "TC01: a proper triangle");
        // TC02: collinear points are
        assertEquals(true, TriangleMesh.isDegenerate(Point3D.ZERO, new Point3D(1, 1, 1), new Point3D(2, 2, 2)),
                "TC02: collinear points");
        // TC03: a null point
        assertRejected(() -> TriangleMesh.isDegenerate(Point3D.ZERO, null, new Point3D(0, 1, 0)), "TC03", "p2");

        // ===== Boundary Values Tests =====
        // TC11: two coincident points
        assertEquals(true, TriangleMesh.isDegenerate(Point3D.ZERO, Point3D.ZERO, new Point3D(0, 1, 0)),
                "TC11: coincident points");
    }

    /** Test method for {@link TriangleMesh#getTriangles()} and {@link TriangleMesh#getTriangle(int)}. */
    @Test
    void testGetTriangles() {
        Material material = new Material().setKd(0.4).setKs(0.2);
        Color emission = new Color(10, 20, 30);
        TriangleMesh mesh = new TriangleMesh(SQUARE_VERTICES, SQUARE_TRIANGLES);
        mesh.setEmission(emission).setMaterial(material);
        List<Triangle> triangles = mesh.getTriangles();
        // ===== Equivalence Partitions Tests =====
        // TC01: two triangles, in the mesh's order, with its vertices, emission and material
        assertEquals(2, triangles.size(), "TC01: wrong number of triangles");
        assertEquals(List.of(new Point3D(0, 0, 0), new Point3D(1, 1, 0), new Point3D(0, 1, 0)),
                triangles.get(1).getVertices(), "TC01: wrong vertices of triangle 1");
        for (Triangle triangle : triangles) {
            assertSame(material, triangle.getMaterial(), "TC01: a triangle must have the mesh's material");
            assertEquals(emission.getColor(), triangle.getEmission().getColor(), "TC01: wrong emission");
        }
        // TC02: each call gives new objects, equal to getTriangle's
        assertEquals(mesh.getTriangle(0).getVertices(), mesh.getTriangles().get(0).getVertices(),
                "TC02: getTriangles and getTriangle must agree");

        // ===== Boundary Values Tests =====
        // TC11: a one-triangle mesh gives a list of one
        assertEquals(1, new TriangleMesh(SQUARE_VERTICES, new int[] { 0, 1, 2 }).getTriangles().size(),
                "TC11: a mesh of one triangle gives one");
    }

    /** Test method for {@link TriangleMesh#getNormal(int)} and {@link TriangleMesh#getNormal(Point3D)}. */
    @Test
    void testGetNormal() {
        TriangleMesh tent = new TriangleMesh(new double[] { 0, 0, 0, 2, 0, 0, 2, 1, 1, 0, 1, 1, 0, 2, 0, 2, 2, 0 },
                new int[] { 0, 1, 2, 0, 2, 3, 3, 2, 5, 3, 5, 4 });
        Vector front = new Vector(0, -1, 1).normalize();
        Vector back = new Vector(0, 1, 1).normalize();
        // ===== Equivalence Partitions Tests =====
        // TC01: each triangle's normal is its Triangle's, (p2 − p1) × (p3 − p2) normalised
        for (int t = 0; t < tent.getTrianglesCount(); ++t)
            assertVector(tent.getTriangle(t).getNormal(Point3D.ZERO), tent.getNormal(t),
                    "TC01: triangle " + t + "'s normal must be its Triangle's");
        assertVector(front, tent.getNormal(0), "TC01: the front slope faces (0,−1,1)");
        assertVector(back, tent.getNormal(3), "TC01: the back slope faces (0,1,1)");
        // TC02: a point inside a triangle of the back slope gets that slope's normal
        assertVector(back, tent.getNormal(new Point3D(1.5, 1.5, 0.5)), "TC02: wrong normal on the back slope");
        // TC03: a point off the mesh is rejected
        assertRejected(() -> tent.getNormal(new Point3D(1, 0.5, 3)), "TC03", "lies on no triangle");
        assertRejected(() -> tent.getNormal(new Point3D(5, 5, 0)), "TC03", "lies on no triangle");
        // TC04: a hit on the mesh is a MeshPoint that knows its triangle: its normal is that triangle's
        List<GeoPoint> hits = tent.findGeoIntersections(new Ray(new Point3D(0.5, 1.7, 5), new Vector(0, 0, -1)));
        MeshPoint hit = assertInstanceOf(MeshPoint.class, hits.get(0), "TC04: a hit on a mesh is a MeshPoint");
        assertEquals(3, hit.triangle, "TC04: the ray hits triangle 3");
        assertVector(back, hit.getNormal(), "TC04: the hit's normal is its triangle's");

        // ===== Boundary Values Tests =====
        // TC11: on the ridge both slopes hold the point: one of their normals is given
        Vector ridge = tent.getNormal(new Point3D(1, 1, 1));
        assertEquals(true, ridge.equals(front) || ridge.equals(back), "TC11: a normal of the ridge's slopes");
        // TC12: a triangle index out of range
        assertRejected(() -> tent.getNormal(4), "TC12", "triangle 4", "out of range");
        assertRejected(() -> tent.getTriangle(-1), "TC12", "triangle -1", "out of range");
        assertRejected(() -> tent.getVertex(6), "TC12", "vertex 6", "out of range");
        assertRejected(() -> tent.getVertexIndex(0, 3), "TC12", "0, 1 or 2");
    }

    /**
     * Test method for {@link TriangleMesh#findGeoIntersections(Ray)}: the course's open edges, each
     * triangle as its {@link Triangle}'s own query takes it.
     */
    @Test
    void testFindIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a ray into the first triangle (below the diagonal): one hit on triangle 0 at (0.7, 0.2, 0)
        List<GeoPoint> hits = square.findGeoIntersections(down(0.7, 0.2));
        assertEquals(1, hits.size(), "TC01: one hit expected");
        assertEquals(0, ((MeshPoint) hits.get(0)).triangle, "TC01: the first triangle is hit");
        assertSame(square, hits.get(0).geometry, "TC01: the geometry hit is the mesh");
        assertPoint(new Point3D(0.7, 0.2, 0), hits.get(0).point, "TC01: wrong point");
        // TC02: a ray into the second triangle
        assertEquals(1, ((MeshPoint) square.findGeoIntersections(down(0.2, 0.7)).get(0)).triangle,
                "TC02: the second triangle is hit");
        // TC03: a ray beside the square misses
        assertNull(square.findIntersections(down(1.5, 0.5)), "TC03: a ray beside the mesh must miss");
        // TC04: a closed mesh (a tetrahedron) is crossed twice: both hits, nearest first
        TriangleMesh tetrahedron = new TriangleMesh(new double[] { 0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4 },
                new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 });
        List<Point3D> crossing = tetrahedron.findIntersections(new Ray(new Point3D(1, 1, -3), new Vector(0, 0, 1)));
        assertEquals(2, crossing.size(), "TC04: a ray through a tetrahedron crosses it twice");
        assertPoint(new Point3D(1, 1, 0), crossing.get(0), "TC04: the nearer hit first");
        assertPoint(new Point3D(1, 1, 2), crossing.get(1), "TC04: then the farther one");
        // TC05: a distance limit keeps only the nearer hit
        assertEquals(1, tetrahedron.findGeoIntersections(new Ray(new Point3D(1, 1, -3), new Vector(0, 0, 1)), 4)
                .size(), "TC05: only the hit within 4 counts");

        // ===== Boundary Values Tests =====
        // TC11: through the diagonal, the edge the two triangles share: both are open there, no hit
        assertNull(square.findGeoIntersections(down(0.5, 0.5)), "TC11: a ray through a shared edge must miss");
        // TC12: through the square's outer edge
        assertNull(square.findGeoIntersections(down(0.5, 0)), "TC12: a ray through an edge must miss");
        // TC13: through a vertex
        assertNull(square.findGeoIntersections(down(1, 1)), "TC13: a ray through a vertex must miss");
        // TC14: on an edge's continuation
        assertNull(square.findGeoIntersections(down(2, 0)), "TC14: a ray on an edge's continuation must miss");
        // TC15: a ray in the mesh's plane
        assertNull(square.findGeoIntersections(new Ray(new Point3D(-1, 0.3, 0), new Vector(1, 0, 0))),
                "TC15: a ray in the mesh's plane must miss");
        // TC16: the renderer's path is closed: the shared edge is hit there
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(square);
        GeoPoint closed = bvh.closestHit(down(0.5, 0.5), bvh.newQuery());
        assertNotNull(closed, "TC16: the renderer's path must hit a shared edge");
        assertPoint(new Point3D(0.5, 0.5, 0), closed.point, "TC16: wrong point on the shared edge");
    }

    /**
     * Test method for {@link TriangleMesh#mayMeet(int, ShadowFrustum)} and for the hierarchy's gathering
     * of a mesh's triangles: a triangle can meet a shadow bundle only when its plane crosses the
     * bundle's pyramid, so a point on a flat mesh lit from above gathers none of the mesh's triangles.
     */
    @Test
    void testMayMeet() {
        // the unit square at z = 0 (triangles 0 and 1), and a triangle in the plane x = 0.5 (triangle 2)
        TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0, -1,
                0.5, 1, -1, 0.5, 0.5, 6 }, new int[] { 0, 1, 2, 0, 2, 3, 4, 5, 6 });
        ShadowFrustum above = PolygonTest.pyramid(new Point3D(0.5, 0.5, 0.1), 5, 0);
        // ===== Equivalence Partitions Tests =====
        // TC01: the pyramid above the square's plane: false for both of its triangles
        assertFalse(mesh.mayMeet(0, above), "TC01: the pyramid lies above triangle 0's plane");
        assertFalse(mesh.mayMeet(1, above), "TC01: the pyramid lies above triangle 1's plane");
        // TC02: the upright triangle's plane x = 0.5 holds the pyramid's apex and axis: true
        assertTrue(mesh.mayMeet(2, above), "TC02: the pyramid crosses triangle 2's plane");
        // TC03: the hierarchy: a pyramid that passes through the box of the tilted triangle (0,0,0),
        // (1,0,0), (0,1,1) but stays above its plane z = y gathers nothing; the upright triangle, which
        // rises through its pyramid, is gathered
        BoundingVolumeHierarchy tilted = BoundingVolumeHierarchy.build(
                new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 1 }, new int[] { 0, 1, 2 }));
        Query tiltedQuery = tilted.newQuery();
        assertTrue(tiltedQuery.getFrustum().set(new double[] { 0.9, 0.1, 0.3 },
                new double[] { 0.9, -5, 10, 1, 0, 0, 0, 1, 0 }, 0),
                "TC03: the pyramid must be set");
        assertTrue(tiltedQuery.getFrustum().meetsBox(new double[] { 0, 0, 0, 1, 1, 1 }, 0),
                "TC03: the pyramid must meet the tilted triangle's box");
        assertFalse(tilted.gather(tiltedQuery), "TC03: the tilted triangle's plane must leave the bundle open");
        BoundingVolumeHierarchy upright = BoundingVolumeHierarchy.build(mesh);
        Query uprightQuery = upright.newQuery();
        assertTrue(uprightQuery.getFrustum().set(new double[] { 0.5, 0.5, 0.1 },
                new double[] { 0.5, 0.5, 5, 1, 0, 0, 0, 1, 0 }, 0),
                "TC03: the pyramid must be set");
        assertTrue(upright.gather(uprightQuery), "TC03: the upright triangle must close the bundle");
        // TC04: the pyramid from (0, 0, 0) to the square (±2, ±2, 10) and, in the plane y = 0 (which
        // crosses it), the triangle (1.1, 0, 0), (2.5, 0, 10), (5, 0, 10): its box meets the pyramid but
        // it lies outside the side x = z/5: false, and the hierarchy gathers nothing
        TriangleMesh beside = new TriangleMesh(new double[] { 1.1, 0, 0, 2.5, 0, 10, 5, 0, 10, 1, 0, 5 },
                new int[] { 0, 1, 2, 3, 1, 2 });
        BoundingVolumeHierarchy besideTree = BoundingVolumeHierarchy.build(new TriangleMesh(
                new double[] { 1.1, 0, 0, 2.5, 0, 10, 5, 0, 10 }, new int[] { 0, 1, 2 }));
        Query besideQuery = besideTree.newQuery();
        ShadowFrustum side = besideQuery.getFrustum();
        assertTrue(side.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "TC04: the pyramid must be set");
        assertTrue(side.meetsBox(new double[] { 1.1, 0, 0, 5, 0, 10 }, 0), "TC04: the pyramid must meet the box");
        assertFalse(beside.mayMeet(0, side), "TC04: a triangle beside the pyramid must not meet it");
        assertFalse(besideTree.gather(besideQuery), "TC04: a triangle beside the pyramid must leave the bundle open");

        // ===== Boundary Values Tests =====
        // TC11: the apex on the square's plane: true (the rays may graze it)
        assertTrue(mesh.mayMeet(0, PolygonTest.pyramid(new Point3D(0.5, 0.5, 0), 5, 0)),
                "TC11: the apex on triangle 0's plane");
        // TC12: the apex 0.05 above the plane in a pyramid 0.1 thick: true
        assertTrue(mesh.mayMeet(1, PolygonTest.pyramid(new Point3D(0.5, 0.5, 0.05), 5, 0.1)),
                "TC12: within the thickness");
        // TC13: triangle 1 of TC04's mesh, its first vertex (1, 0, 5) on the side x = z/5: true
        assertTrue(beside.mayMeet(1, side), "TC13: a triangle touching a side of the pyramid must meet it");
    }

    /**
     * Test method for {@link TriangleMesh#triangleHit}: the renderer's test of a mesh's triangle is
     * the test on its data and the test of a {@link Triangle} of the same vertices, to the bit.
     */
    @Test
    void testTriangleHit() {
        TriangleMesh mesh = benchmark.SphereMesh.mesh(new Point3D(1, -2, 3), 5, 6, 8);
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        Random rnd = new Random(1610);
        // ===== Equivalence Partitions Tests =====
        // TC01: 500 random rays at points in and around random triangles: the Möller–Trumbore test on
        // the data, the mesh's triangleHit and the Triangle's nearestHit agree to the bit, hit or miss
        int hits = 0;
        for (int r = 0; r < 500; ++r) {
            int t = rnd.nextInt(mesh.getTrianglesCount());
            mesh.triangleData(t, data, 0);
            double u = 1.4 * rnd.nextDouble() - 0.2;
            double v = 1.4 * rnd.nextDouble() - 0.2;
            Point3D target = new Point3D(data[0] + u * data[3] + v * data[6], data[1] + u * data[4] + v * data[7],
                    data[2] + u * data[5] + v * data[8]);
            Point3D o = randomPoint(rnd, new Point3D(1, -2, 3), 12);
            RayState ray = rayState(rayFromTo(o, target));
            ray.set(ray.ox(), ray.oy(), ray.oz(), ray.dx(), ray.dy(), ray.dz(), 30 * rnd.nextDouble());
            double expected = mesh.triangleHit(t, ray);
            assertEquals(expected, Triangle.intersect(ray, data, 0, data[9]), 0,
                    "TC01: ray " + r + " at triangle " + t + ", on its data");
            Triangle own = new Triangle(mesh.getVertex(mesh.getVertexIndex(t, 0)),
                    mesh.getVertex(mesh.getVertexIndex(t, 1)), mesh.getVertex(mesh.getVertexIndex(t, 2)));
            assertEquals(expected, own.nearestHit(ray), 0, "TC01: ray " + r + " at triangle " + t + ", as a Triangle");
            if (expected < Geometry.NO_HIT)
                ++hits;
        }
        assertTrue(hits > 50 && hits < 450, "TC01: too few hits or misses (" + hits + " hits)");

        // ===== Boundary Values Tests =====
        // TC11: one ray from the centre tested on every triangle in turn, its scratch space written
        // over each time: each answer the Triangle's, one hit (or two, through an edge) at the radius 5
        RayState ray = rayState(rayFromTo(new Point3D(1, -2, 3), new Point3D(1.3, -1.6, 20)));
        int crossed = 0;
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            Triangle own = new Triangle(mesh.getVertex(mesh.getVertexIndex(t, 0)),
                    mesh.getVertex(mesh.getVertexIndex(t, 1)), mesh.getVertex(mesh.getVertexIndex(t, 2)));
            double t1 = mesh.triangleHit(t, ray);
            assertEquals(own.nearestHit(ray), t1, 0, "TC11: triangle " + t + " from the centre");
            if (t1 < Geometry.NO_HIT) {
                ++crossed;
                assertTrue(t1 > 4 && t1 <= 5, "TC11: the hit lies inside the radius 5, at " + t1);
            }
        }
        assertTrue(crossed == 1 || crossed == 2, "TC11: the ray crosses the sphere's mesh once, not " + crossed);
    }

    /**
     * Test method for {@link TriangleMesh#triangleData}: a triangle's data for the geometric queries
     * ({@link Triangle#project}) is its first vertex, its two edges from it and its parallel limit.
     */
    @Test
    void testTriangleData() {
        TriangleMesh mesh = benchmark.SphereMesh.mesh(new Point3D(1, -2, 3), 5, 6, 8);
        double[] data = new double[TriangleMesh.TRIANGLE_DATA + 1];
        data[TriangleMesh.TRIANGLE_DATA] = -7;
        // ===== Equivalence Partitions Tests =====
        // TC01: every triangle: p1 its first vertex, e1 = p2 − p1, e2 = p3 − p1, and the Triangle's
        // parallel limit of those edges
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            mesh.triangleData(t, data, 0);
            Point3D p1 = mesh.getVertex(mesh.getVertexIndex(t, 0));
            Vector e1 = mesh.getVertex(mesh.getVertexIndex(t, 1)).subtract(p1);
            Vector e2 = mesh.getVertex(mesh.getVertexIndex(t, 2)).subtract(p1);
            double[] expected = { p1.getX(), p1.getY(), p1.getZ(), e1.getX(), e1.getY(), e1.getZ(), e2.getX(),
                    e2.getY(), e2.getZ(), Triangle.parallelLimit(e1.getX(), e1.getY(), e1.getZ(), e2.getX(), e2.getY(),
                    e2.getZ()) };
            for (int k = 0; k < expected.length; ++k)
                assertEquals(expected[k], data[k], 0, "TC01: triangle " + t + ", number " + k);
        }

        // ===== Boundary Values Tests =====
        // TC11: the array's numbers past the data are left as they were (−7)
        assertEquals(-7, data[TriangleMesh.TRIANGLE_DATA], 0, "TC11: a number past the data must be left alone");
        // TC12: written at an offset (after another triangle's data): the same numbers there, the
        // numbers before the offset left as they were
        double[] two = new double[2 * TriangleMesh.TRIANGLE_DATA];
        mesh.triangleData(0, two, 0);
        mesh.triangleData(5, two, TriangleMesh.TRIANGLE_DATA);
        mesh.triangleData(5, data, 0);
        for (int k = 0; k < TriangleMesh.TRIANGLE_DATA; ++k)
            assertEquals(data[k], two[TriangleMesh.TRIANGLE_DATA + k], 0, "TC12: number " + k + " at the offset");
        mesh.triangleData(0, data, 0);
        for (int k = 0; k < TriangleMesh.TRIANGLE_DATA; ++k)
            assertEquals(data[k], two[k], 0, "TC12: number " + k + " before the offset must be left alone");
    }

    /**
     * Test method for {@link TriangleMesh}: a sphere's mesh and the same triangles as {@link Triangle}
     * objects give the same hits and normals on the course's queries, and on the renderer's path
     * through the hierarchy and through the brute-force scan.
     */
    @Test
    void testSameAsTriangles() {
        TriangleMesh mesh = benchmark.SphereMesh.mesh(Point3D.ZERO, 5, 12, 20);
        Geometries objects = new Geometries(mesh.getTriangles().toArray(new Triangle[0]));
        BoundingVolumeHierarchy meshTree = BoundingVolumeHierarchy.build(mesh, 2);
        BoundingVolumeHierarchy meshScan = BoundingVolumeHierarchy.scan(mesh);
        BoundingVolumeHierarchy objectsTree = BoundingVolumeHierarchy.build(objects);
        Query meshQuery = meshTree.newQuery();
        Query scanQuery = meshScan.newQuery();
        Query objectsQuery = objectsTree.newQuery();
        Random rnd = new Random(16);
        int hits = 0;
        // ===== Equivalence Partitions Tests =====
        // TC01: 2000 rays from around the sphere toward points near it
        for (int r = 0; r < 2000; ++r) {
            Point3D origin = randomPoint(rnd, Point3D.ZERO, 30);
            Ray ray = new Ray(origin, randomPoint(rnd, Point3D.ZERO, 7).subtract(origin));
            String tc = "TC01: ray " + r;
            // the course's query: the same points, each with the normal of its Triangle
            List<GeoPoint> expected = objects.findGeoIntersections(ray);
            List<GeoPoint> actual = mesh.findGeoIntersections(ray);
            assertEquals(expected == null ? 0 : expected.size(), actual == null ? 0 : actual.size(),
                    tc + ": the same number of hits");
            if (expected != null) {
                expected = new ArrayList<>(expected);
                expected.sort((a, b) -> Double.compare(a.point.distance(origin), b.point.distance(origin)));
                for (int h = 0; h < expected.size(); ++h) {
                    assertPoint(expected.get(h).point, actual.get(h).point, tc + ": the same hit " + h);
                    assertVector(expected.get(h).getNormal(), actual.get(h).getNormal(), tc + ": the same normal");
                }
            }
            // the renderer's path: the same nearest hit, the same normal, tree or scan
            GeoPoint objectHit = objectsTree.closestHit(ray, objectsQuery);
            GeoPoint meshHit = meshTree.closestHit(ray, meshQuery);
            GeoPoint scanHit = meshScan.closestHit(ray, scanQuery);
            assertEquals(objectHit == null, meshHit == null, tc + ": hit by the tree as by the triangles");
            assertEquals(objectHit == null, scanHit == null, tc + ": hit by the scan as by the triangles");
            if (objectHit != null) {
                ++hits;
                assertEquals(objectHit.point, meshHit.point, tc + ": the same nearest point (tree)");
                assertEquals(objectHit.point, scanHit.point, tc + ": the same nearest point (scan)");
                assertVector(objectHit.getNormal(), meshHit.getNormal(), tc + ": the same normal (tree)");
                assertVector(objectHit.getNormal(), scanHit.getNormal(), tc + ": the same normal (scan)");
            }
        }
        assertEquals(true, hits > 500, "TC01: most rays must hit the sphere, got " + hits);

        // ===== Boundary Values Tests =====
        // TC11: rays aimed exactly at vertices: the closed renderer's path hits there in both forms
        for (int v = 0; v < mesh.getVerticesCount(); ++v) {
            Point3D origin = randomPoint(rnd, Point3D.ZERO, 30).add(new Vector(0, 0, 40));
            Ray ray = new Ray(origin, mesh.getVertex(v).subtract(origin));
            GeoPoint objectHit = objectsTree.closestHit(ray, objectsQuery);
            GeoPoint meshHit = meshTree.closestHit(ray, meshQuery);
            assertNotNull(meshHit, "TC11: a ray at vertex " + v + " must hit the mesh");
            assertEquals(objectHit.point, meshHit.point, "TC11: the same point at vertex " + v);
        }
    }

    /**
     * Test method for {@link TriangleMesh} in a render: a scene with a mesh gives the same picture as
     * with its triangles as objects, with soft shadows through the bundles, on 1 and 3 threads.
     */
    @Test
    void testRenderSameAsTriangles() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the same pixels, mesh or triangle objects
        ImageWriter objects = renderSphere(false, 1);
        ImageWriter mesh = renderSphere(true, 3);
        int lit = 0;
        for (int y = 0; y < 60; ++y)
            for (int x = 0; x < 60; ++x) {
                assertEquals(objects.getPixel(x, y), mesh.getPixel(x, y), "TC01: pixel (" + x + ", " + y + ")");
                if (mesh.getPixel(x, y).getRed() > 0)
                    ++lit;
            }
        // ===== Boundary Values Tests =====
        // TC11: the picture is not empty: the floor and the sphere are lit
        assertEquals(true, lit > 1000, "TC11: the picture must show the lit floor and sphere, lit pixels " + lit);
        // TC12: the sphere's shadow falls on the floor left of it (x ≈ −14, column 9): darker there than on
        // the floor right of it (x ≈ 14, column 51)
        assertEquals(true, mesh.getPixel(9, 30).getRed() < mesh.getPixel(51, 30).getRed(),
                "TC12: the floor must be darker in the sphere's shadow");
    }

    /**
     * Renders a sphere's mesh over a floor under a square light, with soft shadows.
     *
     * @param asMesh  true for the mesh, false for its triangles as objects
     * @param threads the threads of the render
     * @return the picture
     */
    private static ImageWriter renderSphere(boolean asMesh, int threads) {
        Scene scene = new Scene("mesh");
        Material matte = new Material().setKd(0.6).setKs(0.3).setShininess(20);
        scene.geometries.add(new Plane(new Point3D(0, 0, -10), new Vector(0, 0, 1)).setMaterial(matte));
        TriangleMesh sphere = benchmark.SphereMesh.mesh(new Point3D(0, 0, 2), 8, 10, 16);
        if (asMesh)
            scene.geometries.add(sphere.setMaterial(matte));
        else
            for (Triangle triangle : sphere.getTriangles())
                scene.geometries.add(triangle.setMaterial(matte));
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point3D(10, 0, 40)).setEdgesSize(10)
                .setUV(new Vector(1, 0, 0), new Vector(0, 1, 0)));
        ImageWriter image = new ImageWriter(asMesh ? "mesh" : "triangles", 60, 60,
                Path.of("target", "test-images", "triangle-mesh"));
        Render render = new Render().setImageWriter(image)
                .setCamera(new Camera(new Point3D(0, 0, 1000), new Vector(0, 0, -1), new Vector(0, 1, 0))
                        .setVpSize(40, 40).setVpDistance(1000))
                .setRayTracer(new RayTracerBasic(scene)).setSoftShadows(true).setSqrtBeamNum(5)
                .setMultithreading(threads);
        render.renderImage();
        render.writeToImage();
        return image;
    }

    /** Test method for {@link TriangleMesh#coordinates()}: the vertices' coordinates, as a copy. */
    @Test
    void testCoordinates() {
        TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 2 },
                new int[] { 0, 1, 2, 0, 2, 3 });
        // ===== Equivalence Partitions Tests =====
        // TC01: a quad of two triangles: x, y, z of each of its four vertices in turn
        assertArrayEquals(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 2 }, mesh.coordinates(), 0,
                "TC01: the vertices' coordinates");

        // ===== Boundary Values Tests =====
        // TC11: the returned array changed: the mesh keeps its vertices (vertex 3 still at z = 2)
        mesh.coordinates()[11] = 5;
        assertEquals(2, mesh.getVertex(3).getZ(), 0, "TC11: the mesh must not change with the copy");
    }

    /** Test method for {@link TriangleMesh#indices()}: the triangles' vertex indices, as a copy. */
    @Test
    void testIndices() {
        TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 },
                new int[] { 0, 1, 2, 0, 2, 3 });
        // ===== Equivalence Partitions Tests =====
        // TC01: a square of two triangles: 0 1 2, 0 2 3
        int[] indices = mesh.indices();
        assertEquals(6, indices.length, "TC01: three indices per triangle");
        for (int i = 0; i < indices.length; ++i)
            assertEquals(mesh.getVertexIndex(i / 3, i % 3), indices[i], "TC01: index " + i);

        // ===== Boundary Values Tests =====
        // TC11: the returned array changed: the mesh keeps its triangles (vertex 3 of triangle 1 still 3)
        indices[5] = 1;
        assertEquals(3, mesh.getVertexIndex(1, 2), "TC11: the mesh must not change with the copy");
        assertEquals(3, mesh.indices()[5], "TC11: a new call gives the mesh's own indices again");
    }

    /**
     * Test method for {@link TriangleMesh#findIntersections(Ray)} and {@link TriangleMesh#findGeoIntersections(Ray)}:
     * the points where a ray crosses a closed mesh come by distance along the ray, nearest first, whichever
     * triangles it meets first.
     */
    @Test
    void testIntersectionsNearestFirst() {
        // a cube of 12 triangles from (0, 0, 0) to (2, 2, 2); its faces' diagonals are y = x, y = z and x = z
        TriangleMesh cube = TestMeshes.cube(0, 0, 0, 2);
        // ===== Equivalence Partitions Tests =====
        // TC01: down through the top and the bottom: (0.5, 1.5, 2) then (0.5, 1.5, 0), and back
        assertNearestFirst(cube, new Ray(new Point3D(0.5, 1.5, 5), new Vector(0, 0, -1)),
                List.of(new Point3D(0.5, 1.5, 2), new Point3D(0.5, 1.5, 0)), "TC01");
        // TC02: in through the top, out through the side x = 2: (1.5, 0.7, 2) then (2, 0.7, 1.5), and back
        assertNearestFirst(cube, new Ray(new Point3D(0.5, 0.7, 3), new Vector(1, 0, -1)),
                List.of(new Point3D(1.5, 0.7, 2), new Point3D(2, 0.7, 1.5)), "TC02");
        // TC03: 200 seeded random rays from 10 away through a point inside: 2 points each, nearest first
        assertNearestFirstThrough(cube, rnd -> rayThrough(rnd, randomPoint(rnd, new Point3D(1, 1, 1), 0.9), 10),
                "TC03");

        // ===== Boundary Values Tests =====
        // TC10: across the corner next to the top's edge x = 2, the points 0.01 apart: (1.99, 0.7, 2) then
        // (2, 0.7, 1.99), and back
        assertNearestFirst(cube, new Ray(new Point3D(1.49, 0.7, 2.5), new Vector(1, 0, -1)),
                List.of(new Point3D(1.99, 0.7, 2), new Point3D(2, 0.7, 1.99)), "TC10");
    }
}
