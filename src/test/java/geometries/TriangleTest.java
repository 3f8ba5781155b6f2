package geometries;

import accel.ShadowFrustum;
import accel.BoundingVolumeHierarchy;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import accel.Query;
import accel.RayState;
import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.Bytecode;

/**
 * Unit tests for {@link geometries.Triangle}: the course's open edges on its own queries, and
 * watertightness of triangles sharing an edge on the renderer's path.
 */
class TriangleTest {
    /** Tolerance on exact barycentric coordinates, distances and normals. */
    private static final double DELTA = 1e-12;
    private static final Point3D P1 = new Point3D(1, 0, 0);
    private static final Point3D P2 = new Point3D(0, 1, 0);
    private static final Point3D P3 = new Point3D(0, 0, 1);

    /**
     * The triangle in the plane x + y + z = 1; seen along z its projection is (1,0), (0,1), (0,0), and a
     * point (x, y) of the projection lies on the triangle at (x, y, 1 - x - y).
     */
    private final Triangle triangle = new Triangle(P1, P2, P3);

    /**
     * A ray straight down (along -z) from above the point (x, y) of the projection.
     *
     * @param x projected x
     * @param y projected y
     * @return the ray from (x, y, 5) toward (0, 0, -1)
     */
    private static Ray down(double x, double y) {
        return new Ray(new Point3D(x, y, 5), new Vector(0, 0, -1));
    }

    /**
     * Test method for {@link geometries.Triangle#Triangle(primitives.Point3D, primitives.Point3D, primitives.Point3D)}.
     */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a correct triangle is accepted and keeps its vertices in order
        Triangle t = assertDoesNotThrow(() -> new Triangle(P1, P2, P3), "TC01: failed constructing a correct triangle");
        assertEquals(List.of(P1, P2, P3), t.getVertices(), "TC01: wrong vertices");

        // TC02: a null vertex is rejected
        assertThrows(IllegalArgumentException.class, () -> new Triangle(P1, null, P3), "TC02: null vertex must throw");

        // ===== Boundary Values Tests =====
        // TC11: three distinct collinear vertices (the middle one on the edge of the others)
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Triangle(new Point3D(0, 0, 0), new Point3D(1, 1, 1), new Point3D(2, 2, 2)),
                "TC11: collinear vertices must throw"), "collinear", "TC11");

        // TC12: collinear vertices with the middle one given last
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Triangle(new Point3D(0, 0, 0), new Point3D(4, 0, 0), new Point3D(1, 0, 0)),
                "TC12: collinear vertices must throw"), "collinear", "TC12");

        // TC13: first and second vertices coincide
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Triangle(P1, new Point3D(1, 0, 0), P3), "TC13: coincident vertices must throw"),
                "coincide", "TC13");

        // TC14: first and third vertices coincide
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Triangle(P1, P2, new Point3D(1, 0, 0)), "TC14: coincident vertices must throw"),
                "coincide", "TC14");
    }

    /**
     * Test method for {@link geometries.Triangle#getNormal(primitives.Point3D)}.
     */
    @Test
    void testGetNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: unit normal ±(1,1,1)/sqrt3, orthogonal to every edge
        Vector n = triangle.getNormal(new Point3D(1d / 3, 1d / 3, 1d / 3));
        assertEquals(1, n.length(), 1e-10, "TC01: normal is not a unit vector");
        assertEquals(0, n.dotProduct(P2.subtract(P1)), 1e-10, "TC01: normal not orthogonal to edge P1P2");
        assertEquals(0, n.dotProduct(P3.subtract(P2)), 1e-10, "TC01: normal not orthogonal to edge P2P3");
        assertEquals(0, n.dotProduct(P1.subtract(P3)), 1e-10, "TC01: normal not orthogonal to edge P3P1");
        double s = 1 / Math.sqrt(3);
        assertTrue(n.equals(new Vector(s, s, s)) || n.equals(new Vector(-s, -s, -s)), "TC01: wrong normal " + n);
        // TC02: a null point is refused, naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> triangle.getNormal(null),
                "TC02: a null point must be refused"), "point must not be null", "TC02");
    }

    /**
     * Test method for {@link geometries.Triangle#findIntersections(primitives.Ray)}.
     */
    @Test
    void testFindIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: ray hits inside the triangle (1 point (0.25,0.25,0.5))
        assertEquals(List.of(new Point3D(0.25, 0.25, 0.5)), triangle.findIntersections(down(0.25, 0.25)),
                "TC01: wrong intersection point inside the triangle");

        // TC02: ray passes outside, against edge P1P2 (0 points)
        assertNull(triangle.findIntersections(down(0.75, 0.75)), "TC02: ray outside against an edge must give null");

        // TC03: ray passes outside, against vertex P3 (0 points)
        assertNull(triangle.findIntersections(down(-0.5, -0.5)), "TC03: ray outside against a vertex must give null");

        // TC04: triangle behind the ray (0 points)
        assertNull(triangle.findIntersections(new Ray(new Point3D(0.25, 0.25, -5), new Vector(0, 0, -1))),
                "TC04: triangle behind the ray must give null");

        // TC05: ray from the other side hits inside (1 point (0.25,0.25,0.5))
        assertEquals(List.of(new Point3D(0.25, 0.25, 0.5)),
                triangle.findIntersections(new Ray(new Point3D(0.25, 0.25, -5), new Vector(0, 0, 1))),
                "TC05: wrong intersection point from the other side");

        // TC06: oblique ray hits inside (1 point (0.2,0.3,0.5))
        assertEquals(List.of(new Point3D(0.2, 0.3, 0.5)),
                triangle.findIntersections(new Ray(new Point3D(-1, 2, 3), new Vector(1.2, -1.7, -2.5))),
                "TC06: wrong intersection point for an oblique ray");

        // ===== Boundary Values Tests =====
        // The course's query takes the triangle as open: edges and vertices are not hit.
        // TC11: ray through the middle of edge P1P2 (0 points)
        assertNull(triangle.findIntersections(down(0.5, 0.5)), "TC11: a ray through an edge must miss the open triangle");

        // TC12: ray through edge P3P1 (0 points)
        assertNull(triangle.findIntersections(down(0.3, 0)), "TC12: a ray through an edge must miss the open triangle");

        // TC13: ray through vertex P1 (0 points)
        assertNull(triangle.findIntersections(down(1, 0)), "TC13: a ray through a vertex must miss the open triangle");

        // TC14: ray through vertex P3 (0 points)
        assertNull(triangle.findIntersections(down(0, 0)), "TC14: a ray through a vertex must miss the open triangle");

        // TC15: ray on the continuation of edge P3P1 beyond P1 (0 points)
        assertNull(triangle.findIntersections(down(2, 0)), "TC15: a ray on an edge's continuation must give null");

        // TC16: ray on the continuation of edge P1P2 beyond P2 (0 points)
        assertNull(triangle.findIntersections(down(-1, 2)), "TC16: a ray on an edge's continuation must give null");

        // TC17: ray parallel to the triangle, off its plane (0 points)
        assertNull(triangle.findIntersections(new Ray(new Point3D(0, 0, 5), new Vector(1, -1, 0))),
                "TC17: a ray parallel to the triangle must give null");

        // TC18: ray lying in the triangle's plane and crossing the triangle (0 points)
        assertNull(triangle.findIntersections(new Ray(new Point3D(2, -0.5, -0.5), new Vector(-1.75, 0.75, 1))),
                "TC18: a ray inside the triangle's plane must give null");

        // TC19: ray starting on the triangle (0 points)
        assertNull(triangle.findIntersections(new Ray(new Point3D(0.25, 0.25, 0.5), new Vector(0, 0, 1))),
                "TC19: a ray starting on the triangle must give null");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray, double)} on a triangle.
     */
    @Test
    void testFindGeoIntersectionsMaxDistance() {
        // an axis-aligned triangle at z = 0, hit by a ray from (0.5,0.5,3) straight down at distance 3
        Triangle t = new Triangle(new Point3D(0, 0, 0), new Point3D(2, 0, 0), new Point3D(0, 2, 0));
        Ray ray = new Ray(new Point3D(0.5, 0.5, 3), new Vector(0, 0, -1));

        // ===== Equivalence Partitions Tests =====
        // TC01: max distance beyond the point (1 point (0.5,0.5,0), the triangle named)
        List<GeoPoint> result = t.findGeoIntersections(ray, 10);
        assertEquals(List.of(new GeoPoint(t, new Point3D(0.5, 0.5, 0))), result, "TC01: wrong intersection");
        assertSame(t, result.get(0).geometry, "TC01: wrong geometry in the GeoPoint");

        // TC02: max distance before the point (null)
        assertNull(t.findGeoIntersections(ray, 2), "TC02: a point beyond the max distance must be excluded");

        // ===== Boundary Values Tests =====
        // TC11: max distance exactly at the point (1 point)
        assertEquals(List.of(new GeoPoint(t, new Point3D(0.5, 0.5, 0))), t.findGeoIntersections(ray, 3),
                "TC11: a point exactly at the max distance must be included");
    }

    /**
     * Casts every ray of a grid from an eye at the square split into two triangles along a diagonal and
     * asserts that the renderer's path hits each of them.
     *
     * @param label  the case label
     * @param pair   the renderer's path over the two triangles
     * @param eye    the rays' start
     * @param corner the square's corner at grid (0,0)
     * @param u      the square's edge from the corner along the grid's first index
     * @param v      the square's edge from the corner along the grid's second index
     * @param n      the number of cells along each edge (the grid has (n+1)^2 targets)
     */
    private static void assertNoSeam(String label, BoundingVolumeHierarchy pair, Point3D eye, Point3D corner, Vector u,
            Vector v, int n) {
        Query query = pair.newQuery();
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                Point3D target = corner;
                if (i > 0)
                    target = target.add(u.scale((double) i / n));
                if (j > 0)
                    target = target.add(v.scale((double) j / n));
                assertNotNull(pair.closestHit(new Ray(eye, target.subtract(eye)), query),
                        label + ": no triangle hit at grid (" + i + "," + j + "), target " + target);
            }
    }

    /**
     * Two triangles sharing a diagonal of a square are watertight on the renderer's path (a
     * {@link BoundingVolumeHierarchy} over them): no ray aimed at the square slips between them.
     */
    @Test
    void testWatertightSharedDiagonal() {
        // the unit square at z = 0 split along its diagonal y = x
        Point3D a = new Point3D(0, 0, 0);
        Point3D b = new Point3D(1, 0, 0);
        Point3D c = new Point3D(1, 1, 0);
        Point3D d = new Point3D(0, 1, 0);
        Triangle t1 = new Triangle(a, b, c);
        Triangle t2 = new Triangle(a, c, d);
        BoundingVolumeHierarchy pair = BoundingVolumeHierarchy.build(new Geometries(t1, t2));
        Query query = pair.newQuery();
        Vector u = new Vector(1, 0, 0);
        Vector v = new Vector(0, 1, 0);

        // ===== Equivalence Partitions Tests =====
        // TC01: a 200x200 grid (201x201 targets, diagonal and border included) from an oblique eye: every ray hits
        assertNoSeam("TC01", pair, new Point3D(0.3137, -0.7071, 2.4142), a, u, v, 200);

        // TC02: the same grid seen from below the square: every ray hits
        assertNoSeam("TC02", pair, new Point3D(1.7, 0.2, -3.3), a, u, v, 200);

        // TC03: a tilted square in space with irrational edges, split along its diagonal: every ray hits
        Vector tu = new Vector(Math.sqrt(2), Math.sqrt(3), -Math.PI).normalized().scale(3.7);
        Vector tv = tu.crossProduct(new Vector(0.3, -1.1, 0.7)).normalized().scale(3.7);
        Point3D ta = new Point3D(-12.345, 6.789, -40.4);
        Point3D tb = ta.add(tu);
        Point3D tc = tb.add(tv);
        Point3D td = ta.add(tv);
        BoundingVolumeHierarchy tilted = BoundingVolumeHierarchy.build(
                new Geometries(new Triangle(ta, tb, tc), new Triangle(ta, tc, td)));
        Point3D eye = ta.add(tu.crossProduct(tv).normalized().scale(17)).add(new Vector(1.1, -2.3, 0.7));
        assertNoSeam("TC03", tilted, eye, ta, tu, tv, 200);

        // TC04: rays aimed at points strictly outside the square miss both triangles, on both paths (0 points)
        Point3D eye4 = new Point3D(0.3137, -0.7071, 2.4142);
        for (Point3D target : List.of(new Point3D(1.01, 0.5, 0), new Point3D(-0.01, 0.5, 0), new Point3D(0.5, 1.01, 0),
                new Point3D(0.5, -0.01, 0), new Point3D(1.01, 1.01, 0))) {
            Ray ray = new Ray(eye4, target.subtract(eye4));
            assertNull(pair.closestHit(ray, query), "TC04: ray to " + target + " must miss the pair");
            assertNull(t1.findIntersections(ray), "TC04: ray to " + target + " must miss the first triangle");
            assertNull(t2.findIntersections(ray), "TC04: ray to " + target + " must miss the second triangle");
        }

        // ===== Boundary Values Tests =====
        // TC11: 20000 seeded random rays from random eyes on both sides aimed exactly at points of the shared
        // diagonal: the renderer's path hits at the diagonal point; the course's query misses both triangles
        Random random = new Random(20240611L);
        for (int k = 0; k < 20000; ++k) {
            double s = random.nextDouble();
            Point3D target = new Point3D(s, s, 0);
            Point3D from = new Point3D(random.nextDouble() * 6 - 3, random.nextDouble() * 6 - 3,
                    (random.nextBoolean() ? 1 : -1) * (0.1 + random.nextDouble() * 5));
            Ray ray = new Ray(from, target.subtract(from));
            GeoPoint hit = pair.closestHit(ray, query);
            assertNotNull(hit, "TC11: seam on the diagonal at " + target + " from " + from);
            assertEquals(s, hit.point.getX(), 1e-9, "TC11: wrong hit x on the diagonal from " + from);
            assertEquals(s, hit.point.getY(), 1e-9, "TC11: wrong hit y on the diagonal from " + from);
            assertEquals(0, hit.point.getZ(), 1e-9, "TC11: wrong hit z on the diagonal from " + from);
            assertTrue(t1.findIntersections(ray) == null && t2.findIntersections(ray) == null,
                    "TC11: the course's query must miss the shared edge at " + target + " from " + from);
        }

        // TC12: straight-down rays exactly above the diagonal (the direction has no x, y part): every ray hits
        for (int k = 0; k <= 1000; ++k) {
            double s = k / 1000.0;
            assertNotNull(pair.closestHit(new Ray(new Point3D(s, s, 1), new Vector(0, 0, -1)), query),
                    "TC12: seam on the diagonal at (" + s + "," + s + ",0)");
        }
    }

    /**
     * The two edge rules on triangles of several shapes and sizes (see {@link PolygonTest#assertEdgeRules}):
     * the course's query misses edges, vertices and continuations; the renderer's path, by the
     * Möller–Trumbore test, hits edges and vertices.
     */
    @Test
    void testEdgeRules() {
        // ===== Boundary Values Tests =====
        // TC11: the triangle P1P2P3 seen from an oblique eye
        PolygonTest.assertEdgeRules(triangle, new Point3D(-0.4, 2.3, 3.1), "TC11");
        // TC12: the report's first triangle, seen from its camera
        PolygonTest.assertEdgeRules(new Triangle(new Point3D(-150, -150, -115), new Point3D(150, -150, -135),
                new Point3D(75, 75, -150)), new Point3D(0, 0, 1000), "TC12");
        // TC13: a needle 10 long and 0.01 wide, seen from below
        PolygonTest.assertEdgeRules(new Triangle(new Point3D(0, 0, 0), new Point3D(10, 0.005, 1), new Point3D(10, -0.005, 1)),
                new Point3D(4, 0.3, -5), "TC13");
        // TC14: a right triangle 1e-4 across, far from the origin
        PolygonTest.assertEdgeRules(new Triangle(new Point3D(50, 50, 50), new Point3D(50 + 1e-4, 50, 50),
                new Point3D(50, 50 + 1e-4, 50)), new Point3D(50.00003, 49.99997, 50.0002), "TC14");
    }

    /**
     * A triangle and the polygon with the same three vertices agree on hit or miss, and on the point, for
     * thousands of seeded random rays, on the course's query (the same test) and on the renderer's path
     * (Möller–Trumbore against the polygon's edge test).
     */
    @Test
    void testAgreesWithPolygon() {
        List<Point3D[]> triangles = List.of(
                new Point3D[] { P1, P2, P3 },
                new Point3D[] { new Point3D(-150, -150, -115), new Point3D(150, -150, -135), new Point3D(75, 75, -150) },
                new Point3D[] { new Point3D(0.1, -2, 3), new Point3D(4.2, 1.3, -0.7), new Point3D(-1.9, 2.6, 1.1) });
        Random random = new Random(77L);

        // ===== Equivalence Partitions Tests =====
        // TC01: 3 x 2000 rays from random points aimed around each triangle (about a third hit):
        // Triangle and Polygon give the same result, and the same point when they hit
        int hits = 0;
        int misses = 0;
        for (Point3D[] v : triangles) {
            Triangle t = new Triangle(v[0], v[1], v[2]);
            Polygon p = new Polygon(v[0], v[1], v[2]);
            double scale = v[0].distance(v[1]) + v[1].distance(v[2]);
            Vector e1 = v[1].subtract(v[0]);
            Vector e2 = v[2].subtract(v[0]);
            for (int k = 0; k < 2000; ++k) {
                // a target with barycentric weights in [-0.2, 1.0): inside or outside the triangle
                double wu = random.nextDouble() * 1.2 - 0.2;
                double wv = random.nextDouble() * 1.2 - 0.2;
                Point3D target = v[0].add(e1.scale(wu == 0 ? 1e-3 : wu)).add(e2.scale(wv == 0 ? 1e-3 : wv));
                Point3D from = target.add(new Vector(random.nextDouble() - 0.5, random.nextDouble() - 0.5,
                        random.nextDouble() - 0.5).scale(4 * scale));
                Ray ray = new Ray(from, target.subtract(from));
                List<Point3D> rt = t.findIntersections(ray);
                List<Point3D> rp = p.findIntersections(ray);
                assertEquals(rp == null, rt == null, "TC01: Triangle and Polygon disagree on hit/miss for " + ray);
                double nt = nearestHit(t, ray);
                double np = nearestHit(p, ray);
                assertEquals(np == Geometry.NO_HIT, nt == Geometry.NO_HIT,
                        "TC01: Triangle and Polygon disagree on hit/miss on the renderer's path for " + ray);
                if (rt != null) {
                    ++hits;
                    assertEquals(1, rt.size(), "TC01: a triangle is hit at most once");
                    assertEquals(0, rp.get(0).distance(rt.get(0)), 1e-9 * scale,
                            "TC01: Triangle and Polygon disagree on the point for " + ray);
                    assertEquals(np, nt, 1e-9 * scale, "TC01: Triangle and Polygon disagree on the distance for " + ray);
                } else
                    ++misses;
            }
        }
        assertTrue(hits > 1000 && misses > 1000, "TC01: the random rays must both hit and miss: " + hits + "/" + misses);
    }

    /**
     * The renderer's distance to a body along a ray.
     *
     * @param body the body
     * @param ray  the ray
     * @return the distance, or {@link Geometry#NO_HIT}
     */
    private static double nearestHit(Geometry body, Ray ray) {
        return body.nearestHit(Geometry.toRayState(ray, Double.POSITIVE_INFINITY));
    }

    /**
     * Test method for {@link Triangle#mayMeet(ShadowFrustum)}: a triangle can meet a shadow bundle only
     * when its plane crosses the bundle's pyramid and it is not outside one of the pyramid's faces.
     */
    @Test
    void testMayMeet() {
        // the pyramid from (0, 0, 0) to the square (±2, ±2, 10): its sides x = ±z/5 and y = ±z/5
        ShadowFrustum frustum = new ShadowFrustum();
        assertTrue(frustum.set(new double[] { 0, 0, 0 }, new double[] { 0, 0, 10, 2, 0, 0, 0, 2, 0 }, 0),
                "the pyramid must be set");
        // ===== Equivalence Partitions Tests =====
        // TC01: a triangle across the pyramid's axis, (−1, −1, 5), (1, −1, 5), (0, 1, 5): true
        assertTrue(new Triangle(new Point3D(-1, -1, 5), new Point3D(1, -1, 5), new Point3D(0, 1, 5)).mayMeet(frustum),
                "TC01: a triangle across the pyramid must meet it");
        // TC02: in the plane y = 0 (which crosses the pyramid), (1.1, 0, 0), (2.5, 0, 10), (5, 0, 10):
        // its box meets the pyramid, but it lies outside the side x = z/5: false
        Triangle beside = new Triangle(new Point3D(1.1, 0, 0), new Point3D(2.5, 0, 10), new Point3D(5, 0, 10));
        assertTrue(frustum.meetsBox(new double[] { 1.1, 0, 0, 5, 0, 10 }, 0), "TC02: the pyramid must meet the box");
        assertFalse(beside.mayMeet(frustum), "TC02: a triangle beside the pyramid must not meet it");
        // TC03: the plane z = 20, beyond the square, its triangle over the axis: false (the plane test)
        assertFalse(new Triangle(new Point3D(-1, -1, 20), new Point3D(1, -1, 20), new Point3D(0, 1, 20))
                .mayMeet(frustum), "TC03: a triangle beyond the light must not meet the pyramid");

        // ===== Boundary Values Tests =====
        // TC11: its first vertex (1, 0, 5) on the side x = z/5, the rest outside: true
        assertTrue(new Triangle(new Point3D(1, 0, 5), new Point3D(2.5, 0, 10), new Point3D(5, 0, 10)).mayMeet(frustum),
                "TC11: a triangle touching a side of the pyramid must meet it");
    }

    /**
     * A triangle's data as {@link Triangle#project} takes them: p1, e1 = p2 − p1, e2 = p3 − p1.
     *
     * @param p1 the first vertex
     * @param p2 the second vertex
     * @param p3 the third vertex
     * @return the nine numbers
     */
    private static double[] data(Point3D p1, Point3D p2, Point3D p3) {
        Vector e1 = p2.subtract(p1);
        Vector e2 = p3.subtract(p1);
        return new double[] { p1.getX(), p1.getY(), p1.getZ(), e1.getX(), e1.getY(), e1.getZ(), e2.getX(), e2.getY(),
                e2.getZ() };
    }

    /**
     * Asserts what {@link Triangle#project} writes for a point.
     *
     * @param expected u, v, the signed distance and the unit normal, six numbers
     * @param data     the triangle's data
     * @param point    the point
     * @param delta    the tolerance
     * @param message  the failure message
     */
    private static void assertProjection(double[] expected, double[] data, Point3D point, double delta,
                                         String message) {
        double[] target = new double[Triangle.PROJECTION];
        Triangle.project(data, point.getX(), point.getY(), point.getZ(), target);
        String[] names = { "u", "v", "distance", "normal x", "normal y", "normal z" };
        for (int k = 0; k < Triangle.PROJECTION; ++k)
            assertEquals(expected[k], target[k], delta, message + " (" + names[k] + ")");
    }

    /**
     * Test method for {@link Triangle#project}: the barycentric u (along e1), v (along e2) of a point's
     * foot on the plane of P1 = (1, 0, 0), P2 = (0, 1, 0), P3 = (0, 0, 1) (e1 = (−1, 1, 0),
     * e2 = (−1, 0, 1), unit normal e1 × e2 / |e1 × e2| = (1, 1, 1)/√3), its signed distance and the normal.
     */
    @Test
    void testProject() {
        double[] data = data(P1, P2, P3);
        double s = 1 / Math.sqrt(3);
        double third = 1.0 / 3;

        // ===== Equivalence Partitions Tests =====
        // TC01: (2, 2, 2), above the triangle's centre (⅓, ⅓, ⅓) by 5/√3 along the normal
        assertProjection(new double[] { third, third, 5 * s, s, s, s }, data, new Point3D(2, 2, 2), DELTA,
                "TC01: a point above the inside");
        // TC02: the origin, below the centre by 1/√3: a negative distance
        assertProjection(new double[] { third, third, -s, s, s, s }, data, Point3D.ZERO, DELTA,
                "TC02: a point below the inside");
        // TC03: (1, 1, −1) + 2·n, above the point p1 + e1 − e2 of the plane, outside the triangle: u 1, v −1
        assertProjection(new double[] { 1, -1, 2, s, s, s }, data, new Point3D(1 + 2 * s, 1 + 2 * s, -1 + 2 * s),
                DELTA, "TC03: a point whose foot lies outside");
        // TC04: the edges given the other way round (p1, p3, p2): u and v swap, the normal and the
        // distance turn round
        assertProjection(new double[] { 0.25, 0.5, -2, -s, -s, -s }, data(P1, P3, P2),
                pointAbove(data, 0.5, 0.25, 2), DELTA, "TC04: the edges swapped");

        // ===== Boundary Values Tests =====
        // TC11: the vertices: (0, 0), (1, 0), (0, 1), at distance 0
        assertProjection(new double[] { 0, 0, 0, s, s, s }, data, P1, DELTA, "TC11: p1");
        assertProjection(new double[] { 1, 0, 0, s, s, s }, data, P2, DELTA, "TC11: p2");
        assertProjection(new double[] { 0, 1, 0, s, s, s }, data, P3, DELTA, "TC11: p3");
        // TC12: the middle of the edge p2p3, 1 below it: u = v = ½, u + v = 1
        assertProjection(new double[] { 0.5, 0.5, -1, s, s, s }, data, pointAbove(data, 0.5, 0.5, -1), DELTA,
                "TC12: below the middle of the edge p2p3");
        // TC13: a tiny triangle far away (p1 (1000, 1000, 1000), e1 (1e-3, 0, 0), e2 (0, 1e-3, 0)): the
        // point (½, ¼) of it, 2e-3 above: the same numbers, up to the rounding of coordinates near 1000
        double[] tiny = { 1000, 1000, 1000, 1e-3, 0, 0, 0, 1e-3, 0 };
        assertProjection(new double[] { 0.5, 0.25, 2e-3, 0, 0, 1 }, tiny, new Point3D(1000 + 0.5e-3, 1000 + 0.25e-3,
                1000 + 2e-3), 1e-9, "TC13: a tiny triangle far away");
        // TC14: only the six numbers are written: the target's seventh is left as it was
        double[] target = { 9, 9, 9, 9, 9, 9, -7 };
        Triangle.project(data, 2, 2, 2, target);
        assertEquals(-7, target[Triangle.PROJECTION], 0, "TC14: a number past the projection must be left alone");
        assertEquals(5 * s, target[2], DELTA, "TC14: the distance must be written");
    }

    /**
     * The point p1 + u·e1 + v·e2 + h·n of a triangle's data (n the unit normal e1 × e2 / |e1 × e2|).
     *
     * @param data the triangle's data
     * @param u    along e1
     * @param v    along e2
     * @param h    along the normal
     * @return the point
     */
    private static Point3D pointAbove(double[] data, double u, double v, double h) {
        Vector e1 = new Vector(data[3], data[4], data[5]);
        Vector e2 = new Vector(data[6], data[7], data[8]);
        Vector n = e1.crossProduct(e2).normalize();
        return new Point3D(data[0], data[1], data[2]).add(e1.scale(u)).add(e2.scale(v)).add(n.scale(h));
    }

    /**
     * Test method for {@link Triangle#intersect}: the renderer's closed Möller–Trumbore test on the
     * data of P1, P2, P3, whose one comparison decides as the four barycentric tests do.
     */
    @Test
    void testIntersect() {
        double[] data = data(P1, P2, P3);
        double limit = Triangle.parallelLimit(data[3], data[4], data[5], data[6], data[7], data[8]);
        double third = 1.0 / 3;
        RayState ray = new RayState();

        // ===== Equivalence Partitions Tests =====
        // TC01: down from (⅓, ⅓, 5) through the inside, to (⅓, ⅓, ⅓): t = 14/3
        ray.set(third, third, 5, 0, 0, -1, 10);
        assertEquals(14.0 / 3, Triangle.intersect(ray, data, 0, limit), DELTA, "TC01: through the inside");
        // TC02: down beside the triangle, at (0.8, 0.8): a miss
        ray.set(0.8, 0.8, 5, 0, 0, -1, 10);
        assertEquals(Geometry.NO_HIT, Triangle.intersect(ray, data, 0, limit), "TC02: beside it");
        // TC03: the triangle beyond the distance that counts, and behind the ray: misses
        ray.set(third, third, 5, 0, 0, -1, 4);
        assertEquals(Geometry.NO_HIT, Triangle.intersect(ray, data, 0, limit), "TC03: beyond maxT");
        ray.set(third, third, 5, 0, 0, 1, 10);
        assertEquals(Geometry.NO_HIT, Triangle.intersect(ray, data, 0, limit), "TC03: behind the origin");
        // TC04: 4000 rays from random points to points around the triangle's edges, within a few
        // tolerances of u = 0, v = 0 and u + v = 1, the data placed at an offset: the answer of the
        // four comparisons (expects both hits and misses)
        Random rnd = new Random(4242);
        double[] shifted = new double[13];
        System.arraycopy(data, 0, shifted, 4, 9);
        int hits = 0;
        for (int r = 0; r < 4000; ++r) {
            double u = edgeWeight(rnd, r % 3 == 0);
            double v = r % 3 == 1 ? edgeWeight(rnd, true) : r % 3 == 2 ? 1 - u + edgeWeight(rnd, true) : rnd.nextDouble();
            Point3D target = new Point3D(1 - u - v, u, v);
            Point3D from = new Point3D(rnd.nextDouble() * 4 - 2, rnd.nextDouble() * 4 - 2, rnd.nextDouble() * 4 - 2);
            if (from.distance(target) < 0.1)
                continue;
            Vector d = target.subtract(from).normalize();
            ray.set(from.getX(), from.getY(), from.getZ(), d.getX(), d.getY(), d.getZ(), 10);
            double t = Triangle.intersect(ray, shifted, 4, limit);
            assertEquals(fourComparisons(data, limit, ray), t, 0, "TC04: ray " + r);
            if (t < Geometry.NO_HIT)
                ++hits;
        }
        assertTrue(hits > 400 && hits < 3600, "TC04: hits and misses both (" + hits + " hits)");

        // ===== Boundary Values Tests =====
        // TC11: through the middle of edge P2P3 and through the vertex P1: hits (the test is closed)
        ray.set(0, 0.5, 5, 0, 0, -1, 10);
        assertEquals(4.5, Triangle.intersect(ray, data, 0, limit), DELTA, "TC11: through an edge");
        ray.set(1, 0, 5, 0, 0, -1, 10);
        assertEquals(5, Triangle.intersect(ray, data, 0, limit), DELTA, "TC11: through a vertex");
        // TC12: a ray in the triangle's plane, through its inside: parallel, a miss
        Vector along = new Vector(-1, 1, 0).normalize();
        ray.set(2, -1, 0, along.getX(), along.getY(), along.getZ(), 10);
        assertEquals(Geometry.NO_HIT, Triangle.intersect(ray, data, 0, limit), "TC12: in the plane");
        // TC13: the hit at exactly the distance that counts: a hit, the same distance
        ray.set(third, third, 5, 0, 0, -1, 10);
        double t = Triangle.intersect(ray, data, 0, limit);
        ray.set(third, third, 5, 0, 0, -1, t);
        assertEquals(t, Triangle.intersect(ray, data, 0, limit), 0, "TC13: a hit at maxT counts");
        // TC14: the kernel's bytecode within C2's limit for inlining hot methods (FreqInlineSize, 325)
        int size = Bytecode.codeLength(Triangle.class, "intersect", "(Laccel/RayState;[DID)D");
        assertTrue(size <= 325, "TC14: Triangle.intersect has " + size + " bytes of bytecode, too many to be inlined");
    }

    /**
     * {@return a barycentric weight: within a few tolerances of 0 when near, else anywhere in [0, 1]}
     */
    private static double edgeWeight(Random rnd, boolean near) {
        return near ? (rnd.nextDouble() * 6 - 3) * Triangle.BARYCENTRIC_TOLERANCE : rnd.nextDouble();
    }

    /**
     * The Möller–Trumbore test with its four barycentric comparisons one by one, the reference for
     * {@link Triangle#intersect}'s single comparison.
     */
    private static double fourComparisons(double[] data, double limit, RayState ray) {
        double tau = Triangle.BARYCENTRIC_TOLERANCE;
        double px = ray.dy() * data[8] - ray.dz() * data[7];
        double py = ray.dz() * data[6] - ray.dx() * data[8];
        double pz = ray.dx() * data[7] - ray.dy() * data[6];
        double det = data[3] * px + data[4] * py + data[5] * pz;
        double inv = 1.0 / det;
        double tx = ray.ox() - data[0];
        double ty = ray.oy() - data[1];
        double tz = ray.oz() - data[2];
        double u = (tx * px + ty * py + tz * pz) * inv;
        double qx = ty * data[5] - tz * data[4];
        double qy = tz * data[3] - tx * data[5];
        double qz = tx * data[4] - ty * data[3];
        double v = (ray.dx() * qx + ray.dy() * qy + ray.dz() * qz) * inv;
        if (Math.abs(det) < limit || u < -tau || u > 1 + tau || v < -tau || u + v > 1 + tau)
            return Geometry.NO_HIT;
        double t = primitives.Util.alignZero((data[6] * qx + data[7] * qy + data[8] * qz) * inv);
        return t > 0 && t <= ray.maxT() ? t : Geometry.NO_HIT;
    }
}
