package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestMeshes.cube;
import static testutil.TestMeshes.cubeFaces;
import static testutil.TestMeshes.merge;
import static testutil.TestRandom.randomPoint;
import static testutil.TestRandom.randomUnit;

import java.util.Random;

import org.junit.jupiter.api.Test;

import benchmark.SphereMesh;
import geometries.Geometry;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Point3D;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.InnerBall}: which meshes are closed, the ball found inside a closed
 * mesh (none for an open one or when neither centre lies inside), the distance from a point to a
 * triangle, and whether a segment passes through the ball. The key property: every segment from a
 * point of the ball to a point outside the mesh's box is hit by the mesh on the renderer's path.
 */
class InnerBallTest {
    /** Tolerance on exact coordinates and distances. */
    private static final double DELTA = 1e-12;
    /** The part of the distance to the nearest triangle InnerBall keeps off the radius. */
    private static final double SHRINK = 1e-6;
    /** The part of the largest |coordinate| InnerBall keeps off the radius too. */
    private static final double ROUNDING = 1e-12;

    /** The tetrahedron (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), its four faces. */
    private static final double[] TETRAHEDRON_VERTICES = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    private static final int[] TETRAHEDRON_FACES = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };

    /**
     * The inner ball of a cube centred on a point: centred there, its radius a little below half the side.
     *
     * @param centre the cube's centre
     * @param half   half the cube's side
     * @return the ball, asserted found
     */
    static InnerBall cubeBall(Point3D centre, double half) {
        InnerBall ball = InnerBall.of(cube(centre.getX() - half, centre.getY() - half, centre.getZ() - half, 2 * half));
        assertNotNull(ball, "a cube must have an inner ball");
        return ball;
    }

    /**
     * A closed blob: a sphere's mesh whose vertices are moved towards its centre by random factors
     * from a lowest one to 1 (star-shaped around the centre, not convex).
     *
     * @param rnd    the generator
     * @param centre the centre
     * @param radius the sphere's radius
     * @param rings  the sphere's bands
     * @param low    the lowest factor
     * @return the mesh
     */
    static TriangleMesh blob(Random rnd, Point3D centre, double radius, int rings, double low) {
        TriangleMesh sphere = benchmark.SphereMesh.mesh(centre, radius, rings, 2 * rings);
        double[] vertices = new double[3 * sphere.getVerticesCount()];
        for (int v = 0; v < sphere.getVerticesCount(); ++v) {
            Vector out = sphere.getVertex(v).subtract(centre);
            setVertex(vertices, v, centre.add(out.scale(low + (1 - low) * rnd.nextDouble())));
        }
        return new TriangleMesh(vertices, sphere.indices());
    }

    /** Puts a point's coordinates at vertex v of an array. */
    private static void setVertex(double[] vertices, int v, Point3D point) {
        vertices[3 * v] = point.getX();
        vertices[3 * v + 1] = point.getY();
        vertices[3 * v + 2] = point.getZ();
    }

    /**
     * The distance from a point to the surface of a convex mesh around it: the least distance to its
     * triangles' planes, found independently of InnerBall.
     *
     * @param mesh  the mesh, convex
     * @param point the point, inside it
     * @return the distance
     */
    private static double convexDistance(TriangleMesh mesh, Point3D point) {
        double nearest = Double.POSITIVE_INFINITY;
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            Point3D p1 = mesh.getVertex(mesh.getVertexIndex(t, 0));
            Vector normal = mesh.getNormal(t);
            nearest = Math.min(nearest, Math.abs(normal.dotProduct(point.subtract(p1))));
        }
        return nearest;
    }

    /**
     * The least distance from a point to a mesh's triangles by {@link InnerBall#distanceToTriangle}.
     *
     * @param mesh  the mesh
     * @param point the point
     * @return the distance
     */
    private static double nearestTriangle(TriangleMesh mesh, Point3D point) {
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        double[] foot = new double[Triangle.PROJECTION];
        double nearest = Double.POSITIVE_INFINITY;
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            mesh.triangleData(t, data, 0);
            nearest = Math.min(nearest, InnerBall.distanceToTriangle(data, point.getX(), point.getY(), point.getZ(),
                    foot));
        }
        return nearest;
    }

    /** {@return the ball's centre as a point} */
    static Point3D centre(InnerBall ball) {
        return new Point3D(ball.cx, ball.cy, ball.cz);
    }

    /** {@return the radius InnerBall gives a ball whose nearest triangle lies at a distance, in a mesh of a scale} */
    private static double shrunk(double distance, double scale) {
        return distance * (1 - SHRINK) - ROUNDING * scale;
    }

    /**
     * Asserts a ball's centre.
     *
     * @param expected the centre expected
     * @param ball     the ball
     * @param delta    the tolerance on each coordinate
     * @param message  the failure message
     */
    private static void assertCentre(Point3D expected, InnerBall ball, double delta, String message) {
        assertEquals(expected.getX(), ball.cx, delta, message + " (x)");
        assertEquals(expected.getY(), ball.cy, delta, message + " (y)");
        assertEquals(expected.getZ(), ball.cz, delta, message + " (z)");
    }

    /** Test method for {@link InnerBall#isClosed(TriangleMesh)}. */
    @Test
    void testIsClosed() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a sphere's mesh (shared poles) and a cube: closed
        assertTrue(InnerBall.isClosed(benchmark.SphereMesh.mesh(Point3D.ZERO, 5, 8, 12)), "TC01: a sphere is closed");
        assertTrue(InnerBall.isClosed(cube(0, 0, 0, 1)), "TC01: a cube is closed");
        // TC02: a terrain (an open sheet): not closed
        assertFalse(InnerBall.isClosed(benchmark.Terrain.mesh(200)), "TC02: a terrain is open");
        // TC03: a tetrahedron with one face removed: not closed
        assertFalse(InnerBall.isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2 })),
                "TC03: a tetrahedron without a face is open");
        // TC04: two tetrahedra far apart in one mesh: every edge shared twice, closed
        assertTrue(InnerBall.isClosed(merge(tetrahedron(Point3D.ZERO), tetrahedron(new Point3D(10, 0, 0)))),
                "TC04: two separate tetrahedra are closed");
        // TC05: a cube whose x-max face uses a copy of vertex 7 (same position, index 8): open by index
        assertFalse(InnerBall.isClosed(cubeWithCopiedVertex()), "TC05: a copied vertex opens the mesh");

        // ===== Boundary Values Tests =====
        // TC11: a single triangle: open
        assertFalse(InnerBall.isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 1, 2 })),
                "TC11: a single triangle is open");
        // TC12: a tetrahedron plus a copy of one of its faces: three edges used three times, open
        assertFalse(InnerBall.isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, concat(TETRAHEDRON_FACES,
                new int[] { 1, 2, 3 }))), "TC12: a face listed twice leaves edges used three times");
        // TC13: a triangle listed twice, once each way round: every edge used twice, closed (though flat)
        assertTrue(InnerBall.isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 1, 2, 0, 2, 1 })),
                "TC13: a triangle and its reverse share every edge");
        // TC14: the tetrahedron with one face turned the other way round: edges by index, closed
        assertTrue(InnerBall.isClosed(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2,
                1, 3, 2 })), "TC14: the faces' orientation must not matter");
        // TC15: two tetrahedra sharing an edge (a bow tie): that edge used four times, closed
        double[] bowTie = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1 };
        assertTrue(InnerBall.isClosed(new TriangleMesh(bowTie, concat(TETRAHEDRON_FACES,
                new int[] { 0, 1, 4, 0, 5, 1, 0, 4, 5, 1, 5,
                        4 }))), "TC15: an edge shared by four triangles is closed");
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

    /** Test method for {@link InnerBall#of(TriangleMesh)} and {@link InnerBall#box()}. */
    @Test
    void testOf() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a sphere's mesh (radius 5 at (1, −2, 3), 12 rings, 20 segments): the ball lies at the
        // sphere's centre, its radius at most the distance to the nearest triangle and at least 0.99 of it
        Point3D sphereCentre = new Point3D(1, -2, 3);
        TriangleMesh sphere = benchmark.SphereMesh.mesh(sphereCentre, 5, 12, 20);
        InnerBall ball = InnerBall.of(sphere);
        assertNotNull(ball, "TC01: a sphere's mesh must have an inner ball");
        assertCentre(sphereCentre, ball, 1e-9, "TC01: the ball must lie at the sphere's centre");
        double inscribed = convexDistance(sphere, sphereCentre);
        assertTrue(ball.radius <= inscribed && ball.radius >= 0.99 * inscribed,
                "TC01: the radius " + ball.radius + " must be just below the inscribed distance " + inscribed);
        assertEquals(shrunk(inscribed, 8), ball.radius, 1e-9, "TC01: the radius must be the shrunk distance");
        // TC02: a cube from (10, 10, 10) to (14, 14, 14): centred at (12, 12, 12), radius 2 shrunk (scale 14)
        ball = InnerBall.of(cube(10, 10, 10, 4));
        assertNotNull(ball, "TC02: a cube must have an inner ball");
        assertCentre(new Point3D(12, 12, 12), ball, DELTA, "TC02: the ball must lie at the cube's centre");
        assertEquals(shrunk(2, 14), ball.radius, DELTA, "TC02: the radius must be half the side, shrunk");
        double r = ball.radius;
        double[] box = ball.box();
        double[] expectedBox = { 12 - r, 12 - r, 12 - r, 12 + r, 12 + r, 12 + r };
        for (int k = 0; k < 6; ++k)
            assertEquals(expectedBox[k], box[k], DELTA, "TC02: the ball's box, number " + k);
        // TC03: the tetrahedron (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1): the box's centre (½, ½, ½)
        // lies outside, the corners' mean (¼, ¼, ¼) inside, ¼/√3 from the slanted face
        ball = InnerBall.of(new TriangleMesh(TETRAHEDRON_VERTICES, TETRAHEDRON_FACES));
        assertNotNull(ball, "TC03: a tetrahedron must have an inner ball");
        assertCentre(new Point3D(0.25, 0.25, 0.25), ball, DELTA, "TC03: the ball must lie at the corners' mean");
        assertEquals(shrunk(0.25 / Math.sqrt(3), 1), ball.radius, DELTA,
                "TC03: the radius must reach the slanted face");
        // TC04: open meshes (a terrain, a tetrahedron without a face, one triangle): no ball
        assertNull(InnerBall.of(benchmark.Terrain.mesh(200)), "TC04: a terrain has no inner ball");
        assertNull(InnerBall.of(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2 })),
                "TC04: a tetrahedron without a face has no inner ball");
        assertNull(InnerBall.of(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 1, 2 })),
                "TC04: a single triangle has no inner ball");
        // TC05: two tetrahedra 10 apart: closed, but both centres lie between them, outside: no ball
        assertNull(InnerBall.of(merge(tetrahedron(Point3D.ZERO), tetrahedron(new Point3D(10, 0, 0)))),
                "TC05: two tetrahedra far apart have no inner ball");
        // TC06: a cube with a copied vertex (same position, other index): not closed by index, no ball
        assertNull(InnerBall.of(cubeWithCopiedVertex()), "TC06: a copied vertex leaves no inner ball");
        // TC07: a hollow shell (a sphere of radius 5 around one of radius 2, one mesh): both centres lie
        // in the cavity, two crossings from the inside: no ball
        assertNull(InnerBall.of(merge(benchmark.SphereMesh.mesh(Point3D.ZERO, 5, 8, 12),
                benchmark.SphereMesh.mesh(Point3D.ZERO, 2, 8, 12))), "TC07: a hollow shell's cavity is outside");
        // TC08: a sphere of radius 5 at the origin (4 rings, 8 segments) and one of radius 1 at
        // (7.5, 0, 0) (6 rings, 12 segments): the corners' mean (x ≈ 5.36) lies between them, the box's
        // centre (1.75, 0, 0) in the big one: the ball lies there and touches no triangle
        TriangleMesh two = merge(benchmark.SphereMesh.mesh(Point3D.ZERO, 5, 4, 8),
                benchmark.SphereMesh.mesh(new Point3D(7.5, 0, 0), 1, 6, 12));
        ball = InnerBall.of(two);
        assertNotNull(ball, "TC08: the box's centre lies inside the big sphere");
        assertCentre(new Point3D(1.75, 0, 0), ball, DELTA, "TC08: the ball must lie at the box's centre");
        assertEquals(shrunk(nearestTriangle(two, centre(ball)), 8.5), ball.radius, DELTA,
                "TC08: the radius must be the shrunk distance to the nearest triangle");
        // TC09: a sphere of radius 5 at the origin (24 rings, 48 segments) and a coarse one of radius 1
        // at (30, 0, 0): the box's centre (13, 0, 0) lies between them, the corners' mean in the big one
        two = merge(benchmark.SphereMesh.mesh(Point3D.ZERO, 5, 24, 48),
                benchmark.SphereMesh.mesh(new Point3D(30, 0, 0), 1, 4, 6));
        Point3D mean = cornersMean(two);
        ball = InnerBall.of(two);
        assertNotNull(ball, "TC09: the corners' mean lies inside the big sphere");
        assertCentre(mean, ball, DELTA, "TC09: the ball must lie at the corners' mean");
        assertTrue(mean.getX() > 0.1 && ball.radius > 4.5 - mean.getX() && ball.radius < 5 - mean.getX(),
                "TC09: the ball must reach nearly to the big sphere, got radius " + ball.radius + " at " + mean);

        // ===== Boundary Values Tests =====
        // TC11: both centres inside (the sphere of radius 5 at the origin and one of radius 1 at
        // (7, 0, 0), alike: the mean at x 3.5, the box's centre at 1.5): the larger ball, the box's
        two = merge(benchmark.SphereMesh.mesh(Point3D.ZERO, 5, 8, 12), benchmark.SphereMesh.mesh(new Point3D(7, 0, 0),
                1, 8, 12));
        ball = InnerBall.of(two);
        assertNotNull(ball, "TC11: both centres lie inside");
        assertCentre(new Point3D(1.5, 0, 0), ball, DELTA, "TC11: the larger ball, around the box's centre, wins");
        assertTrue(ball.radius > 2.5, "TC11: the larger ball (the mean's reaches 1.5 at most), got " + ball.radius);
        // TC12: a triangle and its reverse (closed by its edges, flat): no inside, no ball
        assertNull(InnerBall.of(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 1, 2, 0, 2, 1 })),
                "TC12: a flat closed mesh has no inner ball");
        // TC13: a tetrahedron with a face turned round: the same ball as the tetrahedron's
        ball = InnerBall.of(new TriangleMesh(TETRAHEDRON_VERTICES, new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 3, 2 }));
        assertNotNull(ball, "TC13: the faces' orientation must not matter");
        assertEquals(shrunk(0.25 / Math.sqrt(3), 1), ball.radius, DELTA, "TC13: the same radius");
        // TC14: a tiny cube far from the origin (side 1e-3 at 1000): the rounding margin 1e-12 × 1000
        // (1e-9) is kept off the radius too (up to the rounding of coordinates near 1000, 1e-13)
        ball = InnerBall.of(cube(1000, 1000, 1000, 1e-3));
        assertNotNull(ball, "TC14: a tiny cube far away must have an inner ball");
        assertEquals(shrunk(5e-4, 1000.001), ball.radius, 1e-12, "TC14: the radius must lose the rounding margin");
    }

    /**
     * The mean of the corners of a mesh's triangles (each vertex counted once per triangle).
     *
     * @param mesh the mesh
     * @return the mean
     */
    private static Point3D cornersMean(TriangleMesh mesh) {
        double[] sum = new double[3];
        for (int t = 0; t < mesh.getTrianglesCount(); ++t)
            for (int k = 0; k < 3; ++k) {
                Point3D p = mesh.getVertex(mesh.getVertexIndex(t, k));
                sum[0] += p.getX();
                sum[1] += p.getY();
                sum[2] += p.getZ();
            }
        double n = 3.0 * mesh.getTrianglesCount();
        return new Point3D(sum[0] / n, sum[1] / n, sum[2] / n);
    }

    /**
     * Test method for {@link InnerBall#of(TriangleMesh)} on seeded random closed meshes (blobs: spheres'
     * meshes with their vertices pulled in by random factors, cubes, pairs of them): a ball touches no
     * triangle, and every segment from a point of the ball to a point outside the mesh's box is hit by
     * the mesh on the renderer's path (its nearest closed triangle hit) — what lets the renderer block
     * a shadow ray through the ball untested.
     */
    @Test
    void testOfRandomMeshes() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 40 random meshes × 180 segments from random points inside the ball to random points
        // outside the box (just outside to the box's extent away)
        // ===== Boundary Values Tests =====
        // TC11: the same meshes × 20 segments from points of the ball's surface (shrunk by 1e-9)
        Random rnd = new Random(20261202);
        int found = 0;
        for (int m = 0; m < 40; ++m) {
            Point3D at = randomPoint(rnd, Point3D.ZERO, 50);
            double size = Math.pow(10, -2 + 4 * rnd.nextDouble());
            TriangleMesh mesh = switch (m % 4) {
                case 0, 1 -> blob(rnd, at, size, 4 + rnd.nextInt(10), 0.5 + 0.5 * rnd.nextDouble());
                case 2 -> cube(at.getX(), at.getY(), at.getZ(), size);
                default -> merge(blob(rnd, at, size, 6, 0.7), cube(at.getX() + 0.3 * size, at.getY(), at.getZ(),
                        size));
            };
            InnerBall ball = InnerBall.of(mesh);
            if (ball == null)
                continue;
            ++found;
            String meshLabel = "mesh " + m + " (ball at " + centre(ball) + ", radius " + ball.radius + ")";
            assertTrue(nearestTriangle(mesh, centre(ball)) > ball.radius, "TC01: " + meshLabel
                    + ": the ball must touch no triangle");
            double[] box = new double[6];
            mesh.bounds(box, 0);
            double extent = Math.max(box[3] - box[0], Math.max(box[4] - box[1], box[5] - box[2]));
            for (int s = 0; s < 200; ++s) {
                boolean surface = s % 10 == 0;
                double reach = surface ? 1 - 1e-9 : Math.cbrt(rnd.nextDouble());
                Point3D from = centre(ball).add(randomUnit(rnd).scale(reach * ball.radius));
                Point3D to = outside(rnd, box, extent);
                Vector d = to.subtract(from);
                double length = d.length();
                d = d.normalize();
                assertTrue(mesh.nearestHit(new RayState().set(from.getX(), from.getY(), from.getZ(), d.getX(),
                        d.getY(), d.getZ(), length)) < Geometry.NO_HIT, () -> (surface ? "TC11: " : "TC01: ") + meshLabel + ": the segment from "
                        + from + " to " + to + " must hit the mesh");
            }
        }
        assertTrue(found >= 30, "TC01: too few meshes with an inner ball: " + found);
    }

    /**
     * A random point outside a box: on one of its faces' planes moved out by up to the box's extent.
     *
     * @param rnd    the generator
     * @param box    {minX, minY, minZ, maxX, maxY, maxZ}
     * @param extent the box's largest extent
     * @return the point
     */
    private static Point3D outside(Random rnd, double[] box, double extent) {
        double[] p = new double[3];
        for (int k = 0; k < 3; ++k)
            p[k] = box[k] + (box[3 + k] - box[k]) * (1.4 * rnd.nextDouble() - 0.2);
        int face = rnd.nextInt(6);
        int k = face % 3;
        double away = extent * (1e-3 + rnd.nextDouble());
        p[k] = face < 3 ? box[k] - away : box[3 + k] + away;
        return new Point3D(p[0], p[1], p[2]);
    }

    /**
     * Test method for {@link InnerBall#distanceToTriangle}: the triangle (10, −20, 5) + (4, 0, 0)·u +
     * (0, 4, 0)·v (data p1, e1, e2), from points whose nearest point of it is inside it, on an edge or
     * at a vertex.
     */
    @Test
    void testDistanceToTriangle() {
        double[] data = { 10, -20, 5, 4, 0, 0, 0, 4, 0, 0 };
        double[] foot = new double[Triangle.PROJECTION];

        // ===== Equivalence Partitions Tests =====
        // TC01: above the inside (relative (1, 1, 3)): 3, the distance to the plane
        assertEquals(3, distance(data, 1, 1, 3, foot), DELTA, "TC01: above the inside");
        // TC02: below the inside (relative (1, 2, −2)): 2
        assertEquals(2, distance(data, 1, 2, -2, foot), DELTA, "TC02: below the inside");
        // TC03: beside the edge p1p2 (relative (2, −3, 4)): to (2, 0, 0), 5
        assertEquals(5, distance(data, 2, -3, 4, foot), DELTA, "TC03: beside the edge along e1");
        // TC04: beside the edge p1p3 (relative (−3, 2, −4)): to (0, 2, 0), 5
        assertEquals(5, distance(data, -3, 2, -4, foot), DELTA, "TC04: beside the edge along e2");
        // TC05: beside the edge p2p3 (relative (3, 3, 1)): to (2, 2, 0), √3
        assertEquals(Math.sqrt(3), distance(data, 3, 3, 1, foot), DELTA, "TC05: beside the slanted edge");
        // TC06: beyond the vertex p1 (relative (−3, −4, 0)): 5
        assertEquals(5, distance(data, -3, -4, 0, foot), DELTA, "TC06: beyond p1");
        // TC07: beyond the vertex p2 (relative (7, −4, 0)): to (4, 0, 0), 5
        assertEquals(5, distance(data, 7, -4, 0, foot), DELTA, "TC07: beyond p2");
        // TC08: beyond the vertex p3 (relative (−1, 6, 2)): to (0, 4, 0), 3
        assertEquals(3, distance(data, -1, 6, 2, foot), DELTA, "TC08: beyond p3");

        // ===== Boundary Values Tests =====
        // TC11: a point of the triangle (relative (1, 1, 0)): 0
        assertEquals(0, distance(data, 1, 1, 0, foot), DELTA, "TC11: on the triangle");
        // TC12: right above an edge's middle (relative (2, 0, 3)) and above a vertex (relative (0, 4, −5))
        assertEquals(3, distance(data, 2, 0, 3, foot), DELTA, "TC12: above an edge");
        assertEquals(5, distance(data, 0, 4, -5, foot), DELTA, "TC12: below a vertex");
        // TC13: in the plane, outside the slanted edge by 1e-9 (relative (2 + ½e-9, 2 + ½e-9, 0)): e-9/√2,
        // up to the rounding of coordinates near 20 (a few 1e-15)
        assertEquals(1e-9 / Math.sqrt(2), distance(data, 2 + 0.5e-9, 2 + 0.5e-9, 0, foot), 1e-14,
                "TC13: just outside the slanted edge");
        // TC14: on the line of an edge, beyond its end (relative (6, 0, 0)): 2 to p2
        assertEquals(2, distance(data, 6, 0, 0, foot), DELTA, "TC14: on an edge's line beyond its end");
    }

    /**
     * The distance from a point, given relative to (10, −20, 5), to a triangle.
     *
     * @param data the triangle's data
     * @param x    the point's x relative to (10, −20, 5)
     * @param y    the same for y
     * @param z    the same for z
     * @param foot scratch space
     * @return {@link InnerBall#distanceToTriangle}'s answer
     */
    private static double distance(double[] data, double x, double y, double z, double[] foot) {
        return InnerBall.distanceToTriangle(data, 10 + x, -20 + y, 5 + z, foot);
    }

    /**
     * Test method for {@link InnerBall#crossedBy}: the ball of the cube from (−1, −1, −1) to (1, 1, 1)
     * (centre the origin, radius r just below 1), segments along x at a height h off the centre.
     */
    @Test
    void testCrossedBy() {
        InnerBall ball = cubeBall(Point3D.ZERO, 1);
        double r = ball.radius;

        // ===== Equivalence Partitions Tests =====
        // TC01: through the centre, from (−5, 0, 0) 10 long: true
        assertTrue(ball.crossedBy(-5, 0, 0, 1, 0, 0, 10), "TC01: a segment through the centre");
        // TC02: 0.5 off the centre: true; 1.5 off: false
        assertTrue(ball.crossedBy(-5, 0.5, 0, 1, 0, 0, 10), "TC02: a segment 0.5 off the centre");
        assertFalse(ball.crossedBy(-5, 0, 1.5, 1, 0, 0, 10), "TC02: a segment beside the ball");
        // TC03: towards the ball but too short (3 of the 5 − r to its surface): false
        assertFalse(ball.crossedBy(-5, 0, 0, 1, 0, 0, 3), "TC03: a segment ending before the ball");
        // TC04: starting inside (at (0.5, 0, 0)), going away: true
        assertTrue(ball.crossedBy(0.5, 0, 0, 1, 0, 0, 10), "TC04: a segment from inside the ball");
        // TC05: the ball behind the start ((5, 0, 0) going +x): false
        assertFalse(ball.crossedBy(5, 0, 0, 1, 0, 0, 10), "TC05: a ball behind the segment's start");
        // TC06: a slanted segment through the ball, direction (1, 1, 1)/√3 from (−3, −3, −3): true
        double s = 1 / Math.sqrt(3);
        assertTrue(ball.crossedBy(-3, -3, -3, s, s, s, 10), "TC06: a slanted segment through the centre");

        // ===== Boundary Values Tests =====
        // TC11: ending just inside the ball (5 − r + 1e-9): true; just short of it (5 − r − 1e-9): false
        assertTrue(ball.crossedBy(-5, 0, 0, 1, 0, 0, 5 - r + 1e-9), "TC11: a segment ending just inside");
        assertFalse(ball.crossedBy(-5, 0, 0, 1, 0, 0, 5 - r - 1e-9), "TC11: a segment ending just outside");
        // TC12: tangent (h = r): false; h = r·(1 − 1e-9): true
        assertFalse(ball.crossedBy(-5, r, 0, 1, 0, 0, 10), "TC12: a tangent segment touches only");
        assertTrue(ball.crossedBy(-5, r * (1 - 1e-9), 0, 1, 0, 0, 10), "TC12: a segment just inside the tangent");
        // TC13: a segment of length 0 inside the ball: true; outside it: false
        assertTrue(ball.crossedBy(0.2, 0.2, 0.2, 1, 0, 0, 0), "TC13: a point inside the ball");
        assertFalse(ball.crossedBy(-2, 0, 0, 1, 0, 0, 0), "TC13: a point outside the ball");
        // TC14: starting on the surface, going away ((r, 0, 0) going +x): false; going in: true
        assertFalse(ball.crossedBy(r, 0, 0, 1, 0, 0, 10), "TC14: from the surface, away");
        assertTrue(ball.crossedBy(r, 0, 0, -1, 0, 0, 1e-6), "TC14: from the surface, inwards");
    }
}
