package geometries;

import accel.ShadowFrustum;
import accel.BoundingVolumeHierarchy;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.Polygon}.
 */
class PolygonTest {
    /** Vertices of the course's parallelogram in the plane x + y + z = 1. */
    private static final Point3D A = new Point3D(0, 0, 1);
    private static final Point3D B = new Point3D(1, 0, 0);
    private static final Point3D C = new Point3D(0, 1, 0);
    private static final Point3D D = new Point3D(-1, 1, 1);

    /**
     * The parallelogram ABCD; seen along z its projection is (0,0), (1,0), (0,1), (-1,1), and a point
     * (x, y) of the projection lies on the polygon at (x, y, 1 - x - y).
     */
    private final Polygon polygon = new Polygon(A, B, C, D);

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
     * Test method for {@link geometries.Polygon#Polygon(primitives.Point3D...)}.
     */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a correct convex quadrangle is accepted and keeps its vertices in order
        Polygon p = assertDoesNotThrow(() -> new Polygon(A, B, C, D), "TC01: failed constructing a correct polygon");
        assertEquals(List.of(A, B, C, D), p.getVertices(), "TC01: wrong vertices");

        // TC02: a regular pentagon is accepted
        Point3D[] pentagon = new Point3D[5];
        for (int k = 0; k < 5; ++k) {
            double angle = Math.PI / 2 + k * 2 * Math.PI / 5;
            pentagon[k] = new Point3D(Math.cos(angle), Math.sin(angle), 2);
        }
        assertDoesNotThrow(() -> new Polygon(pentagon), "TC02: failed constructing a regular pentagon");

        // TC03: vertices not in one plane
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(A, B, C, new Point3D(-2, 1, 1)), "TC03: non-coplanar vertices must throw"),
                "coplanar", "TC03");

        // TC04: a concave quadrangle (a dent at (1,1,0))
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(new Point3D(0, 0, 0), new Point3D(4, 0, 0), new Point3D(1, 1, 0), new Point3D(0, 4, 0)),
                "TC04: a concave quadrangle must throw"), "convex", "TC04");

        // TC05: a self-crossing bow-tie quadrangle
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(new Point3D(0, 0, 0), new Point3D(1, 1, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)),
                "TC05: a bow-tie must throw"), "convex", "TC05");

        // TC06: a pentagram (a star whose turns all go the same way)
        Point3D[] star = new Point3D[5];
        for (int k = 0; k < 5; ++k) {
            double angle = Math.PI / 2 + k * 4 * Math.PI / 5;
            star[k] = new Point3D(Math.cos(angle), Math.sin(angle), 0);
        }
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(star), "TC06: a pentagram must throw"), "convex", "TC06");

        // TC07: a concave quadrangle whose dent is the second vertex (the first turn goes the wrong way)
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(new Point3D(4, 0, 0), new Point3D(1, 1, 0), new Point3D(0, 4, 0), new Point3D(0, 0, 0)),
                "TC07: a concave quadrangle must throw"), "convex", "TC07");

        // TC08: a null vertex is rejected
        assertThrows(IllegalArgumentException.class, () -> new Polygon(A, B, null, D), "TC08: null vertex must throw");

        // ===== Boundary Values Tests =====
        // TC11: fewer than 3 vertices (2, none, a null array)
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(A, B), "TC11: 2 vertices must throw"), "3 vertices", "TC11");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(), "TC11: no vertices must throw"), "3 vertices", "TC11");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon((Point3D[]) null), "TC11: a null vertex array must throw"), "3 vertices", "TC11");

        // TC12: the last vertex (0,0.5,0.5) lies on the edge from its neighbour C to its neighbour A
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(A, B, C, new Point3D(0, 0.5, 0.5)), "TC12: vertex on an edge must throw"),
                "edge", "TC12");

        // TC13: three consecutive collinear vertices in the middle of the list
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(2, 0, 0), new Point3D(0, 2, 0)),
                "TC13: vertex on an edge must throw"), "collinear", "TC13");

        // TC14: two consecutive vertices coincide
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(A, B, C, C), "TC14: coincident vertices must throw"), "coincide", "TC14");

        // TC15: the last vertex coincides with the first
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Polygon(A, B, C, D, A), "TC15: closing vertex equal to the first must throw"),
                "coincide", "TC15");

        // TC16: the tolerance is relative: a triangle 1e-12 across is a triangle, with a unit normal (0,0,1)
        Polygon tiny = assertDoesNotThrow(() -> new Polygon(new Point3D(5, 5, 5), new Point3D(5 + 1e-12, 5, 5),
                new Point3D(5, 5 + 1e-12, 5)), "TC16: a tiny triangle must be accepted");
        assertEquals(1, tiny.getNormal(new Point3D(5, 5, 5)).length(), 1e-12, "TC16: the normal must be a unit vector");
        assertEquals(1, Math.abs(tiny.getNormal(new Point3D(5, 5, 5)).getZ()), 1e-9, "TC16: wrong normal");

        // TC17: in a polygon whose longest edge is about 1414, two vertices 1e-5 apart do not coincide, and
        // 1e-7 apart (less than 1e-9 of that edge) they do
        assertDoesNotThrow(() -> new Polygon(new Point3D(0, 0, 0), new Point3D(1000, 0, 0), new Point3D(1000, 1000, 0),
                new Point3D(1000 - 1e-5, 1000, 0)), "TC17: vertices 1e-5 apart must count as two");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new Polygon(new Point3D(0, 0, 0),
                new Point3D(1000, 0, 0), new Point3D(1000, 1000, 0), new Point3D(1000 - 1e-7, 1000, 0)),
                "TC17: vertices 1e-7 apart in a polygon 1414 across must coincide"), "coincide", "TC17");
    }

    /**
     * Test method for {@link geometries.Polygon#getNormal(primitives.Point3D)}.
     */
    @Test
    void testGetNormal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: unit normal ±(1,1,1)/sqrt3, orthogonal to every edge
        Vector n = polygon.getNormal(new Point3D(0, 0, 1));
        assertEquals(1, n.length(), 1e-10, "TC01: normal is not a unit vector");
        Point3D[] v = { A, B, C, D };
        for (int i = 0; i < 4; ++i)
            assertEquals(0, n.dotProduct(v[(i + 1) % 4].subtract(v[i])), 1e-10,
                    "TC01: normal not orthogonal to edge " + i);
        double s = 1 / Math.sqrt(3);
        assertTrue(n.equals(new Vector(s, s, s)) || n.equals(new Vector(-s, -s, -s)), "TC01: wrong normal " + n);

        // TC02: the normal is the same at every point and equals the plane's normal
        assertEquals(n, polygon.getNormal(new Point3D(0.25, 0.25, 0.5)), "TC02: normal differs across the polygon");
        assertEquals(n, polygon.getPlane().getNormal(), "TC02: normal differs from the plane's");
        // TC03: a null point is refused, naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> polygon.getNormal(null),
                "TC03: a null point must be refused"), "point must not be null", "TC03");
    }

    /**
     * Test method for {@link geometries.Polygon#getUV(primitives.Point3D)}: the position in its plane from
     * the first vertex, u along the first edge, v along normal × u.
     */
    @Test
    void testGetUV() {
        // a square of edge 100 in z = 0, counter-clockwise seen from +z: u along x, v along y
        Polygon square = new Polygon(new Point3D(0, 0, 0), new Point3D(100, 0, 0), new Point3D(100, 100, 0),
                new Point3D(0, 100, 0));
        // ===== Equivalence Partitions Tests =====
        // TC01: a point inside: its x and y
        assertArrayEquals(new double[] { 25, 75 }, square.getUV(new Point3D(25, 75, 0)), 1e-12, "TC01: inside");
        // TC02: the same square from its second vertex on: u along +y, v along −x, from (100, 0)
        Polygon turned = new Polygon(new Point3D(100, 0, 0), new Point3D(100, 100, 0), new Point3D(0, 100, 0),
                new Point3D(0, 0, 0));
        assertArrayEquals(new double[] { 75, 75 }, turned.getUV(new Point3D(25, 75, 0)), 1e-12, "TC02: turned");
        // ===== Boundary Values Tests =====
        // TC11: the first vertex is (0, 0), the opposite corner (100, 100)
        assertArrayEquals(new double[] { 0, 0 }, square.getUV(Point3D.ZERO), 0, "TC11: the first vertex");
        assertArrayEquals(new double[] { 100, 100 }, square.getUV(new Point3D(100, 100, 0)), 1e-12,
                "TC11: the opposite corner");
    }

    /**
     * Test method for {@link geometries.Polygon#findIntersections(primitives.Ray)}.
     */
    @Test
    void testFindIntersections() {
        // ===== Equivalence Partitions Tests =====
        // TC01: ray hits inside the polygon (1 point (0.25,0.25,0.5))
        assertEquals(List.of(new Point3D(0.25, 0.25, 0.5)), polygon.findIntersections(down(0.25, 0.25)),
                "TC01: wrong intersection point inside the polygon");

        // TC02: ray passes outside, against an edge (0 points)
        assertNull(polygon.findIntersections(down(1, 0.5)), "TC02: ray outside against an edge must give null");

        // TC03: ray passes outside, against a vertex (0 points)
        assertNull(polygon.findIntersections(down(2, -0.5)), "TC03: ray outside against a vertex must give null");

        // TC04: polygon behind the ray (0 points)
        assertNull(polygon.findIntersections(new Ray(new Point3D(0.25, 0.25, -5), new Vector(0, 0, -1))),
                "TC04: polygon behind the ray must give null");

        // TC05: oblique ray from the other side hits inside (1 point (0.25,0.25,0.5))
        assertEquals(List.of(new Point3D(0.25, 0.25, 0.5)),
                polygon.findIntersections(new Ray(new Point3D(0, 0, -1), new Vector(0.25, 0.25, 1.5))),
                "TC05: wrong intersection point for an oblique ray");

        // ===== Boundary Values Tests =====
        // The course's query takes the polygon as open: edges and vertices are not hit.
        // TC11: ray through the middle of edge AB (0 points)
        assertNull(polygon.findIntersections(down(0.5, 0)), "TC11: a ray through an edge must miss the open polygon");

        // TC12: ray through the middle of edge CD (0 points)
        assertNull(polygon.findIntersections(down(-0.5, 1)), "TC12: a ray through an edge must miss the open polygon");

        // TC13: ray through vertex B (0 points)
        assertNull(polygon.findIntersections(down(1, 0)), "TC13: a ray through a vertex must miss the open polygon");

        // TC14: ray through vertex D (0 points)
        assertNull(polygon.findIntersections(down(-1, 1)), "TC14: a ray through a vertex must miss the open polygon");

        // TC15: ray on the continuation of edge AB beyond B (0 points)
        assertNull(polygon.findIntersections(down(2, 0)), "TC15: a ray on an edge's continuation must give null");

        // TC16: ray on the continuation of edge AB beyond A (0 points)
        assertNull(polygon.findIntersections(down(-1, 0)), "TC16: a ray on an edge's continuation must give null");

        // TC17: ray parallel to the polygon, off its plane (0 points)
        assertNull(polygon.findIntersections(new Ray(new Point3D(0, 0, 5), new Vector(1, -1, 0))),
                "TC17: a ray parallel to the polygon must give null");

        // TC18: ray lying in the polygon's plane and crossing the polygon (0 points)
        assertNull(polygon.findIntersections(new Ray(new Point3D(2, -0.5, -0.5), new Vector(-1.75, 0.75, 1))),
                "TC18: a ray inside the polygon's plane must give null");

        // TC19: ray starting on the polygon (0 points)
        assertNull(polygon.findIntersections(new Ray(new Point3D(0.25, 0.25, 0.5), new Vector(0, 0, 1))),
                "TC19: a ray starting on the polygon must give null");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray, double)} on a polygon.
     */
    @Test
    void testFindGeoIntersectionsMaxDistance() {
        // an axis-aligned square at z = 0, hit by a ray from (1,1,3) straight down at distance 3
        Polygon square = new Polygon(new Point3D(0, 0, 0), new Point3D(2, 0, 0), new Point3D(2, 2, 0),
                new Point3D(0, 2, 0));
        Ray ray = new Ray(new Point3D(1, 1, 3), new Vector(0, 0, -1));

        // ===== Equivalence Partitions Tests =====
        // TC01: max distance beyond the point (1 point (1,1,0), the polygon named)
        List<GeoPoint> result = square.findGeoIntersections(ray, 10);
        assertEquals(List.of(new GeoPoint(square, new Point3D(1, 1, 0))), result, "TC01: wrong intersection");
        assertSame(square, result.get(0).geometry, "TC01: wrong geometry in the GeoPoint");

        // TC02: max distance before the point (null)
        assertNull(square.findGeoIntersections(ray, 2), "TC02: a point beyond the max distance must be excluded");

        // ===== Boundary Values Tests =====
        // TC11: max distance exactly at the point (1 point)
        assertEquals(List.of(new GeoPoint(square, new Point3D(1, 1, 0))), square.findGeoIntersections(ray, 3),
                "TC11: a point exactly at the max distance must be included");
    }

    /**
     * Two quadrangles sharing an edge leave no seam on the renderer's path: every ray aimed at the
     * shared edge hits one of them there, while the course's query misses both.
     */
    @Test
    void testSharedEdgeNoSeam() {
        Polygon left = new Polygon(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(1, 1, 0), new Point3D(0, 1, 0));
        Polygon right = new Polygon(new Point3D(1, 0, 0), new Point3D(2.5, 0, 0), new Point3D(2.5, 1, 0),
                new Point3D(1, 1, 0));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(new Geometries(left, right));
        Point3D eye = new Point3D(0.31, -0.77, 2.9);

        // ===== Boundary Values Tests =====
        // TC11: rays from an oblique eye at 1001 points along the shared edge x = 1: the renderer's path
        // hits one of the polygons at the point, the course's query hits neither (null)
        for (int k = 0; k <= 1000; ++k) {
            Point3D target = new Point3D(1, k / 1000.0, 0);
            Ray ray = new Ray(eye, target.subtract(eye));
            GeoPoint hit = bvh.closestHit(ray, bvh.newQuery());
            assertNotNull(hit, "TC11: seam between the polygons at " + target);
            assertEquals(target.getX(), hit.point.getX(), 1e-9, "TC11: wrong hit point x at " + target);
            assertEquals(target.getY(), hit.point.getY(), 1e-9, "TC11: wrong hit point y at " + target);
            assertEquals(0, hit.point.getZ(), 1e-9, "TC11: wrong hit point z at " + target);
            assertNull(left.findIntersections(ray), "TC11: the course's query must miss the left edge at " + target);
            assertNull(right.findIntersections(ray), "TC11: the course's query must miss the right edge at " + target);
        }
    }

    /**
     * The two edge rules on polygons of several shapes and sizes: the course's query misses a ray
     * through an edge, a vertex or an edge's continuation, and hits one just inside; the renderer's
     * path hits the edges and vertices too.
     */
    @Test
    void testEdgeRules() {
        Point3D[] pentagon = new Point3D[5];
        for (int k = 0; k < 5; ++k) {
            double angle = 2 * Math.PI * k / 5;
            pentagon[k] = new Point3D(3 + 2 * Math.cos(angle), -1 + 2 * Math.sin(angle), 0.5 * Math.cos(angle));
        }
        Point3D[] hexagon = new Point3D[6];
        for (int k = 0; k < 6; ++k) {
            double angle = 2 * Math.PI * k / 6 + 0.3;
            hexagon[k] = new Point3D(1000 * Math.cos(angle), 250, 1000 * Math.sin(angle));
        }

        // ===== Boundary Values Tests =====
        // TC11: the course's parallelogram ABCD seen from an oblique eye
        assertEdgeRules(polygon, new Point3D(0.7, -2.1, 4.4), "TC11");
        // TC12: a tilted regular pentagon of radius 2, seen from the other side
        assertEdgeRules(new Polygon(pentagon), new Point3D(2.2, -0.3, -6.1), "TC12");
        // TC13: a regular hexagon of radius 1000, seen from far above
        assertEdgeRules(new Polygon(hexagon), new Point3D(123, 4000, -77), "TC13");
        // TC14: a thin kite 1e-3 across
        assertEdgeRules(new Polygon(new Point3D(0, 0, 0), new Point3D(1e-3, 2e-4, 0), new Point3D(1.5e-3, 1e-3, 0),
                new Point3D(2e-4, 1e-3, 0)), new Point3D(3e-4, -1e-3, 2e-3), "TC14");
    }

    /**
     * Asserts both edge rules of a polygon, with oblique rays from an eye off its plane: for every
     * edge, rays through its two vertices, a point of it and its continuation beyond both ends miss
     * on the course's query; the vertices and the point are hit on the renderer's path (a
     * {@link BoundingVolumeHierarchy} over the polygon) and the continuations are not; a ray a
     * millionth of the polygon's size inside the edge's point is hit by both.
     *
     * @param polygon the polygon
     * @param eye     where the rays start, off the polygon's plane
     * @param tc      the test-case label
     */
    static void assertEdgeRules(Polygon polygon, Point3D eye, String tc) {
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(polygon);
        List<Point3D> v = polygon.getVertices();
        double size = 0;
        for (int k = 0; k < v.size(); ++k)
            size = Math.max(size, v.get(k).distance(v.get((k + 1) % v.size())));
        Vector normal = polygon.getNormal(v.get(0));
        for (int k = 0; k < v.size(); ++k) {
            Point3D from = v.get(k);
            Vector edge = v.get((k + 1) % v.size()).subtract(from);
            Point3D onEdge = from.add(edge.scale(0.3183));
            String at = tc + ": edge " + k;
            for (Point3D target : List.of(from, onEdge)) {
                Ray ray = new Ray(eye, target.subtract(eye));
                assertNull(polygon.findIntersections(ray), at + ": the course's query must miss " + target);
                GeoPoint hit = bvh.closestHit(ray, bvh.newQuery());
                assertNotNull(hit, at + ": the renderer's path must hit " + target);
                assertEquals(0, hit.point.distance(target), 1e-9 * edge.length(), at + ": wrong hit point");
            }
            for (Point3D target : List.of(from.add(edge.scale(-0.5)), from.add(edge.scale(1.7)))) {
                Ray ray = new Ray(eye, target.subtract(eye));
                assertNull(polygon.findIntersections(ray), at + ": a ray on the continuation must miss " + target);
                assertNull(bvh.closestHit(ray, bvh.newQuery()), at + ": a ray on the continuation must miss " + target);
            }
            Vector inward = normal.crossProduct(edge).normalized();
            if (inward.dotProduct(v.get((k + 2) % v.size()).subtract(from)) < 0)
                inward = inward.scale(-1);
            Point3D inside = onEdge.add(inward.scale(1e-6 * size));
            Ray ray = new Ray(eye, inside.subtract(eye));
            assertNotNull(polygon.findIntersections(ray), at + ": the course's query must hit just inside " + inside);
            assertNotNull(bvh.closestHit(ray, bvh.newQuery()), at + ": the renderer's path must hit just inside " + inside);
        }
    }
    /**
     * Sets a frustum from an apex to a square of half-side 1 around a centre, in the x–y plane.
     *
     * @param apex      the apex
     * @param cz        the height of the square's centre (at x = y = 0)
     * @param thickness the thickness
     * @return the frustum
     */
    static ShadowFrustum pyramid(Point3D apex, double cz, double thickness) {
        ShadowFrustum frustum = new ShadowFrustum();
        assertTrue(frustum.set(new double[] { apex.getX(), apex.getY(), apex.getZ() },
                new double[] { 0, 0, cz, 1, 0, 0, 0, 1, 0 }, thickness),
                "the pyramid must be set");
        return frustum;
    }

    /**
     * Test method for {@link Polygon#mayMeet}: a polygon can meet a shadow bundle only when its plane
     * crosses the bundle's pyramid.
     */
    @Test
    void testMayMeet() {
        // the square [−2, 2]² at z = 0, and a triangle in the same plane
        Polygon square = new Polygon(new Point3D(-2, -2, 0), new Point3D(2, -2, 0), new Point3D(2, 2, 0),
                new Point3D(-2, 2, 0));
        Triangle triangle = new Triangle(new Point3D(-2, -2, 0), new Point3D(2, -2, 0), new Point3D(0, 2, 0));
        // ===== Equivalence Partitions Tests =====
        // TC01: the pyramid above the plane (apex at z = 0.1, square at z = 5): false, for both
        ShadowFrustum above = pyramid(new Point3D(0, 0, 0.1), 5, 0);
        assertFalse(square.mayMeet(above), "TC01: the pyramid lies above the polygon's plane");
        assertFalse(triangle.mayMeet(above), "TC01: the pyramid lies above the triangle's plane");
        // TC02: the pyramid crosses the plane (apex at z = −1): true
        ShadowFrustum crossing = pyramid(new Point3D(0, 0, -1), 5, 0);
        assertTrue(square.mayMeet(crossing), "TC02: the pyramid crosses the polygon");
        assertTrue(triangle.mayMeet(crossing), "TC02: the pyramid crosses the triangle");
        // TC03: the pyramid crosses the plane away from the polygon (apex at x = 50): true, the plane
        // test leaves the sides to the polygon's box
        assertTrue(square.mayMeet(pyramid(new Point3D(50, 0, -1), 5, 0)), "TC03: the plane is crossed beside the polygon");

        // ===== Boundary Values Tests =====
        // TC11: the apex on the plane: true
        assertTrue(square.mayMeet(pyramid(new Point3D(0, 0, 0), 5, 0)), "TC11: the apex on the polygon's plane");
        // TC12: the apex 0.05 above the plane, in a pyramid 0.1 thick: true (the rays may stray below)
        assertTrue(square.mayMeet(pyramid(new Point3D(0, 0, 0.05), 5, 0.1)), "TC12: within the thickness");
        // TC13: a flat pyramid (the set refused): true
        ShadowFrustum flat = new ShadowFrustum();
        assertFalse(flat.set(new double[] { 0, 0, 1 }, new double[] { 0, 0, 1, 1, 0, 0, 0, 1, 0 }, 0),
                "TC13: a flat pyramid is refused");
        assertTrue(square.mayMeet(flat), "TC13: a refused pyramid sets nothing aside");
    }
}
