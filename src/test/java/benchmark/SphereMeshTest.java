package benchmark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.Test;

import accel.BoundingVolumeHierarchy;
import geometries.Geometries;
import geometries.Intersectable.GeoPoint;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link benchmark.SphereMesh}: the triangle count, vertices on the sphere, a closed
 * and consistently oriented mesh, and rays toward the centre hitting it where they hit the sphere.
 */
class SphereMeshTest {
    private static final Point3D CENTER = new Point3D(1, -2, 3);
    private static final double RADIUS = 5;
    private static final int RINGS = 24;
    private static final int SEGMENTS = 32;
    /**
     * How far inside the sphere a facet of the RINGS × SEGMENTS mesh may lie: every facet is inscribed
     * in a cap of angular radius below π/RINGS + 2π/SEGMENTS, so it is at least R·cos of that from
     * the centre.
     */
    private static final double SAG = RADIUS * (1 - Math.cos(Math.PI / RINGS + 2 * Math.PI / SEGMENTS));

    private final List<Triangle> mesh = SphereMesh.triangles(CENTER, RADIUS, RINGS, SEGMENTS);

    /**
     * Test method for {@link benchmark.SphereMesh#trianglesCount(int, int)} and the size of
     * {@link benchmark.SphereMesh#triangles(Point3D, double, int, int)}.
     */
    @Test
    void testTrianglesCount() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 24 rings × 32 segments: 2·32·23 = 1472 triangles, as many as built
        assertEquals(1472, SphereMesh.trianglesCount(RINGS, SEGMENTS), "TC01: wrong triangle count");
        assertEquals(1472, mesh.size(), "TC01: wrong number of triangles built");

        // TC02: the benchmark's 129 rings × 128 segments: 2·128·128 = 32768 triangles
        assertEquals(32768, SphereMesh.trianglesCount(129, 128), "TC02: wrong triangle count");

        // ===== Boundary Values Tests =====
        // TC11: the fewest rings (2: the two pole fans only) and segments (3): 6 triangles
        assertEquals(6, SphereMesh.trianglesCount(2, 3), "TC11: wrong triangle count");
        assertEquals(6, SphereMesh.triangles(CENTER, RADIUS, 2, 3).size(), "TC11: wrong number of triangles built");

        // TC12: one ring too few
        assertMessage(assertThrows(IllegalArgumentException.class, () -> SphereMesh.trianglesCount(1, 3),
                "TC12: 1 ring must throw"), "rings", "TC12");

        // TC13: one segment too few
        assertMessage(assertThrows(IllegalArgumentException.class, () -> SphereMesh.trianglesCount(2, 2),
                "TC13: 2 segments must throw"), "segments", "TC13");
    }

    /**
     * Test method for {@link benchmark.SphereMesh#triangles(Point3D, double, int, int)}: bad input.
     */
    @Test
    void testTrianglesBadInput() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a negative radius
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> SphereMesh.triangles(CENTER, -1, RINGS, SEGMENTS), "TC01: negative radius must throw"),
                "radius", "TC01");

        // TC02: no centre
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> SphereMesh.triangles(null, RADIUS, RINGS, SEGMENTS), "TC02: null centre must throw"),
                "centre", "TC02");

        // ===== Boundary Values Tests =====
        // TC11: a zero radius
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> SphereMesh.triangles(CENTER, 0, RINGS, SEGMENTS), "TC11: zero radius must throw"),
                "radius", "TC11");

        // TC12: one ring too few
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> SphereMesh.triangles(CENTER, RADIUS, 1, SEGMENTS), "TC12: 1 ring must throw"), "rings", "TC12");
    }

    /**
     * Test method for {@link benchmark.SphereMesh#triangles(Point3D, double, int, int)}: every vertex lies
     * on the sphere and every normal points outward.
     */
    @Test
    void testVerticesOnSphere() {
        // ===== Equivalence Partitions Tests =====
        // TC01: every vertex is at distance R = 5 from the centre
        for (Triangle t : mesh)
            for (Point3D p : t.getVertices())
                assertEquals(RADIUS, p.distance(CENTER), 1e-10, "TC01: vertex off the sphere: " + p);

        // TC02: every triangle's normal (p2 - p1) × (p3 - p1) points away from the centre
        for (Triangle t : mesh) {
            List<Point3D> v = t.getVertices();
            Vector normal = v.get(1).subtract(v.get(0)).crossProduct(v.get(2).subtract(v.get(0)));
            assertTrue(normal.dotProduct(v.get(0).subtract(CENTER)) > 0, "TC02: normal points inward: " + t);
        }

        // ===== Boundary Values Tests =====
        // TC11: the poles (1, 3, 3) and (1, -7, 3) are vertices
        assertTrue(hasVertex(new Point3D(1, 3, 3)), "TC11: no vertex at the top pole");
        assertTrue(hasVertex(new Point3D(1, -7, 3)), "TC11: no vertex at the bottom pole");
    }

    /**
     * Collects the vertices a mesh's triangles use and counts their directed edges, each edge from
     * vertex {@code from} to vertex {@code to} (in the triangle's order) keyed {@code from << 32 | to}.
     *
     * @param mesh the mesh
     * @param used filled with the index of every vertex a triangle uses
     * @return how often each directed edge appears
     */
    private static Map<Long, Integer> directedEdges(TriangleMesh mesh, Set<Integer> used) {
        Map<Long, Integer> directed = new HashMap<>();
        for (int t = 0; t < mesh.getTrianglesCount(); ++t)
            for (int e = 0; e < 3; ++e) {
                long from = mesh.getVertexIndex(t, e);
                long to = mesh.getVertexIndex(t, (e + 1) % 3);
                used.add((int) from);
                directed.merge(from << 32 | to, 1, Integer::sum);
            }
        return directed;
    }

    /**
     * Test method for {@link benchmark.SphereMesh#triangles(Point3D, double, int, int)}: the mesh is
     * closed — every edge is shared by exactly two triangles, which run along it in opposite directions.
     */
    @Test
    void testClosed() {
        // ===== Equivalence Partitions Tests =====
        // TC01: every directed edge appears once and its reverse once, so 3·1472/2 = 2208 edges in all
        Set<Integer> index = new HashSet<>();
        TriangleMesh flat = SphereMesh.mesh(CENTER, RADIUS, RINGS, SEGMENTS);
        Map<Long, Integer> directed = directedEdges(flat, index);
        // vertices are shared: 2 poles + 23 rings of 32 = 738, every one used (Euler: V - E + F = 2)
        assertEquals(738, flat.getVerticesCount(), "TC01: wrong number of vertices");
        assertEquals(738, index.size(), "TC01: every vertex must be used");
        for (int t = 0; t < flat.getTrianglesCount(); ++t)
            assertEquals(flat.getTriangle(t).getVertices(), mesh.get(t).getVertices(),
                    "TC01: triangles() must give the mesh's triangles, in order");
        for (Map.Entry<Long, Integer> edge : directed.entrySet()) {
            long key = edge.getKey();
            long reverse = (key & 0xFFFFFFFFL) << 32 | key >>> 32;
            assertEquals(1, edge.getValue(), "TC01: a directed edge is used twice");
            assertEquals(1, directed.getOrDefault(reverse, 0), "TC01: an edge with no neighbour across it");
        }
        assertEquals(2208, directed.size() / 2, "TC01: wrong number of edges");
        assertEquals(2, index.size() - directed.size() / 2 + mesh.size(), "TC01: Euler characteristic is not 2");

        // ===== Boundary Values Tests =====
        // TC11: the smallest mesh (2 rings × 3 segments: a triangular bipyramid) has 5 vertices and 9 edges
        Set<Integer> smallIndex = new HashSet<>();
        Map<Long, Integer> smallEdges = directedEdges(SphereMesh.mesh(CENTER, RADIUS, 2, 3), smallIndex);
        assertEquals(5, smallIndex.size(), "TC11: wrong number of vertices");
        assertEquals(18, smallEdges.size(), "TC11: wrong number of directed edges");
        for (long key : smallEdges.keySet())
            assertTrue(smallEdges.containsKey((key & 0xFFFFFFFFL) << 32 | key >>> 32), "TC11: an open edge");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(Ray)} and the hierarchy's
     * {@link BoundingVolumeHierarchy#closestHit} on the mesh: rays from outside toward the centre hit it
     * where they hit the sphere, within the facets' sag.
     */
    @Test
    void testRaysTowardCenter() {
        Geometries geometries = new Geometries(mesh.toArray(new Triangle[0]));

        // ===== Equivalence Partitions Tests =====
        // TC01: 1000 seeded random rays from 3R away toward the centre: the nearest hit is at
        // t in [2R, 2R + SAG], the farthest at t in [4R - SAG, 4R]
        Random random = new Random(20_210_621L);
        for (int r = 0; r < 1000; ++r) {
            Vector out = new Vector(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalized();
            Point3D p0 = CENTER.add(out.scale(3 * RADIUS));
            List<GeoPoint> hits = geometries.findGeoIntersections(new Ray(p0, out.scale(-1)));
            assertNotNull(hits, "TC01: ray toward the centre missed the mesh: " + out);
            assertTrue(hits.size() >= 2, "TC01: a closed mesh is entered and left, got " + hits.size() + " points");
            double near = Double.POSITIVE_INFINITY;
            double far = 0;
            for (GeoPoint hit : hits) {
                double t = hit.point.distance(p0);
                near = Math.min(near, t);
                far = Math.max(far, t);
            }
            assertEquals(2 * RADIUS + SAG / 2, near, SAG / 2 + 1e-9, "TC01: wrong distance to the near side");
            assertEquals(4 * RADIUS - SAG / 2, far, SAG / 2 + 1e-9, "TC01: wrong distance to the far side");
        }

        // TC02: a ray beside the sphere (passing 1.5R from the centre) misses the mesh: null
        assertNull(geometries.findGeoIntersections(
                new Ray(CENTER.add(new Vector(3 * RADIUS, 1.5 * RADIUS, 0)), new Vector(-1, 0, 0))),
                "TC02: a ray beside the mesh must miss it");

        // ===== Boundary Values Tests =====
        // Edges and vertices: the renderer's path (the hierarchy) takes triangles as closed, the
        // course's query as open.
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(geometries);
        // TC11: a ray down the axis hits the top pole (1,3,3), a vertex shared by 32 triangles, at t = 2R
        Ray down = new Ray(CENTER.add(new Vector(0, 3 * RADIUS, 0)), new Vector(0, -1, 0));
        GeoPoint pole = bvh.closestHit(down, bvh.newQuery());
        assertNotNull(pole, "TC11: a ray through the pole vertex missed the mesh");
        assertEquals(new Point3D(1, 3, 3), pole.point, "TC11: the top pole is not hit");

        // TC12: a ray toward the centre through the middle of a shared edge on the equator hits the
        // mesh at t in [2R, 2R + SAG] — no seam between the two triangles
        Point3D a = CENTER.add(new Vector(RADIUS, 0, 0));
        Point3D b = CENTER.add(new Vector(RADIUS * Math.cos(2 * Math.PI / SEGMENTS), 0,
                RADIUS * Math.sin(2 * Math.PI / SEGMENTS)));
        Vector out = a.add(b.subtract(a).scale(0.5)).subtract(CENTER).normalized();
        Point3D p0 = CENTER.add(out.scale(3 * RADIUS));
        GeoPoint edge = bvh.closestHit(new Ray(p0, out.scale(-1)), bvh.newQuery());
        assertNotNull(edge, "TC12: a ray through a shared edge fell through the seam");
        assertEquals(2 * RADIUS + SAG / 2, edge.point.distance(p0), SAG / 2 + 1e-9, "TC12: wrong distance to the edge");

        // TC13: the course's query on the axis ray, through the two pole vertices only (null)
        assertNull(geometries.findGeoIntersections(down), "TC13: the course's open triangles are missed at a vertex");
    }

    /**
     * Whether the mesh has a vertex at a point.
     *
     * @param p the point
     * @return true when some triangle has a vertex equal to it
     */
    private boolean hasVertex(Point3D p) {
        return mesh.stream().anyMatch(t -> t.getVertices().contains(p));
    }
}
