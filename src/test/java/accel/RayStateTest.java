package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.assertHitEverywhere;
import static testutil.BruteForce.pointOrNull;
import static testutil.BruteForce.reference;
import static testutil.BruteForce.transmittance;
import static testutil.TestRandom.randomPoint;
import static testutil.TestRandom.randomUnit;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Intersectable;
import geometries.Sphere;
import geometries.Triangle;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link RayState}'s slab test ({@link RayState#boxEntry(double[], int, double)}): its
 * distances, and through the hierarchy's closest hits, rays along the axes (zero direction
 * components), rays starting on box faces and rays starting inside a body's box.
 */
class RayStateTest {
    /**
     * Test method for rays along a coordinate axis: zero direction components make the slab test
     * divide by zero (±∞, and 0·∞ = NaN on a slab's face).
     */
    @Test
    void testBoxEntryAxisRays() {
        // a 7×7×7 grid of spheres of radius 0.4 at integer points, and triangles in the planes x = ±3.5
        Geometries grid = new Geometries();
        for (int i = -3; i <= 3; ++i)
            for (int j = -3; j <= 3; ++j)
                for (int k = -3; k <= 3; ++k)
                    grid.add(new Sphere(new Point3D(i, j, k), 0.4));
        grid.add(new Triangle(new Point3D(3.5, -4, -4), new Point3D(3.5, 4, -4), new Point3D(3.5, 0, 4)),
                new Triangle(new Point3D(-3.5, -4, -4), new Point3D(-3.5, 4, -4), new Point3D(-3.5, 0, 4)));

        // ===== Equivalence Partitions Tests =====
        // TC01: down the z axis through a column of spheres: the top sphere at (i, j, 3.4)
        assertHitEverywhere(grid, new Ray(new Point3D(1, -2, 10), new Vector(0, 0, -1)), new Point3D(1, -2, 3.4),
                "TC01");
        // TC02: along −x, direction components −0.0: the triangle at x = 3.5 first, at (3.5, 0, 0)
        assertHitEverywhere(grid, new Ray(new Point3D(10, 0, 0), new Vector(-1, -0.0, -0.0)), new Point3D(3.5, 0, 0),
                "TC02");
        // TC03: along +y between the spheres' columns: no hit
        assertHitEverywhere(grid, new Ray(new Point3D(0.5, -10, 0.5), new Vector(0, 1, 0)), null, "TC03");
        // TC04: random rays along the axes, ±0.0 components, from grid points and half-grid points
        Random rnd = new Random(9);
        for (int r = 0; r < 600; ++r) {
            double[] o = new double[3];
            for (int k = 0; k < 3; ++k)
                o[k] = rnd.nextInt(3) == 0 ? rnd.nextInt(21) / 2.0 - 5 : 10 * rnd.nextDouble() - 5;
            int axis = rnd.nextInt(3);
            double sign = rnd.nextBoolean() ? 1 : -1;
            double zero = rnd.nextBoolean() ? 0.0 : -0.0;
            Ray ray = new Ray(new Point3D(o[0], o[1], o[2]),
                    new Vector(axis == 0 ? sign : zero, axis == 1 ? sign : zero, axis == 2 ? sign : zero));
            assertHitEverywhere(grid, ray, pointOrNull(reference(grid, ray)), "TC04: ray " + r);
        }

        // ===== Boundary Values Tests =====
        // TC11: a ray along z touching the spheres of the column x = 0, y = 0 (x = 0.4): tangent, no hit
        assertHitEverywhere(grid, new Ray(new Point3D(0.4, 0, 10), new Vector(0, 0, -1)), null, "TC11");
        // TC12: a ray down z starting exactly on the top of the grid's box (z = 3.4), on the top of a
        // sphere: the start does not count, so the sphere's bottom at (0, 0, 2.6)
        assertHitEverywhere(grid, new Ray(new Point3D(0, 0, 3.4), new Vector(0, 0, -1)), new Point3D(0, 0, 2.6),
                "TC12");
        // TC13: the same ray up: it leaves the grid, no hit
        assertHitEverywhere(grid, new Ray(new Point3D(0, 0, 3.4), new Vector(0, 0, 1)), null, "TC13");
    }

    /**
     * Test method for rays starting exactly on a box face: a closed unit cube of 12 triangles (its box
     * is the cube) with a sphere inside.
     */
    @Test
    void testBoxEntryOnBoxFaces() {
        Geometries cube = new Geometries(cube(0, 1));
        Geometries withBall = new Geometries(cube(0, 1));
        withBall.add(new Sphere(new Point3D(0.5, 0.5, 0.5), 0.25));

        // ===== Equivalence Partitions Tests =====
        // TC01: from the middle of face x = 0 into the cube: the opposite face at (1, 0.5, 0.5)
        assertHitEverywhere(cube, new Ray(new Point3D(0, 0.5, 0.5), new Vector(1, 0, 0)), new Point3D(1, 0.5, 0.5),
                "TC01");
        // TC02: the same with the ball inside: the ball at (0.25, 0.5, 0.5)
        assertHitEverywhere(withBall, new Ray(new Point3D(0, 0.5, 0.5), new Vector(1, 0, 0)),
                new Point3D(0.25, 0.5, 0.5), "TC02");
        // TC03: from the face out of the cube: no hit
        assertHitEverywhere(withBall, new Ray(new Point3D(0, 0.5, 0.5), new Vector(-1, 0, 0)), null, "TC03");

        // ===== Boundary Values Tests =====
        // TC11: from face x = 0 along it (x component 0): the edge of face y = 1 at (0, 1, 0.5)
        assertHitEverywhere(cube, new Ray(new Point3D(0, 0.5, 0.5), new Vector(0, 1, 0)), new Point3D(0, 1, 0.5),
                "TC11");
        // TC12: from the plane of face x = 0, outside the cube, along it (−0.0): face y = 1's edge at (0, 1, 0.5)
        assertHitEverywhere(cube, new Ray(new Point3D(0, 2, 0.5), new Vector(-0.0, -1, 0)), new Point3D(0, 1, 0.5),
                "TC12");
        // TC13: from face x = 1 (the box's top in x) along z: the edge of face z = 0 at (1, 0.5, 0)
        assertHitEverywhere(cube, new Ray(new Point3D(1, 0.5, 0.5), new Vector(0, 0, -1)), new Point3D(1, 0.5, 0),
                "TC13");
        // TC14: from a corner of the box along an edge: the other end of the edge, (1, 0, 0)
        assertHitEverywhere(cube, new Ray(new Point3D(0, 0, 0), new Vector(1, 0, 0)), new Point3D(1, 0, 0), "TC14");
        // TC15: random rays from random points of the six faces, random directions and along the faces
        Random rnd = new Random(31);
        for (int r = 0; r < 300; ++r) {
            double[] o = { rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble() };
            int face = rnd.nextInt(3);
            o[face] = rnd.nextInt(2);
            Vector dir = randomUnit(rnd);
            if (rnd.nextBoolean()) {
                double[] d = { dir.getX(), dir.getY(), dir.getZ() };
                d[face] = 0;
                dir = new Vector(d[0], d[1], d[2]);
            }
            Ray ray = new Ray(new Point3D(o[0], o[1], o[2]), dir);
            assertHitEverywhere(withBall, ray, pointOrNull(reference(withBall, ray)), "TC15: ray " + r);
        }
    }

    /**
     * The 12 triangles of a closed axis-aligned cube.
     *
     * @param lo the low corner's coordinates
     * @param hi the high corner's coordinates
     * @return the triangles
     */
    private static Intersectable[] cube(double lo, double hi) {
        Point3D[] c = new Point3D[8];
        for (int i = 0; i < 8; ++i)
            c[i] = new Point3D((i & 1) == 0 ? lo : hi, (i & 2) == 0 ? lo : hi, (i & 4) == 0 ? lo : hi);
        int[][] faces = { { 0, 2, 6, 4 }, { 1, 5, 7, 3 }, { 0, 4, 5, 1 }, { 2, 3, 7, 6 }, { 0, 1, 3, 2 },
                { 4, 6, 7, 5 } };
        List<Intersectable> triangles = new ArrayList<>();
        for (int[] f : faces) {
            triangles.add(new Triangle(c[f[0]], c[f[1]], c[f[2]]));
            triangles.add(new Triangle(c[f[0]], c[f[2]], c[f[3]]));
        }
        return triangles.toArray(new Intersectable[0]);
    }

    /**
     * Test method for rays starting inside a sphere (the box test clamps to the ray's start).
     */
    @Test
    void testBoxEntryFromInside() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a lone sphere of radius 2, the ray from (0.5, 0, 0) along x: (2, 0, 0)
        Sphere big = new Sphere(Point3D.ZERO, 2);
        assertHitEverywhere(new Geometries(big), new Ray(new Point3D(0.5, 0, 0), new Vector(1, 0, 0)),
                new Point3D(2, 0, 0), "TC01");
        // TC02: with a small sphere inside it and 200 small spheres around: the small one at (0.75, 0, 0)
        Random rnd = new Random(3);
        Geometries crowd = new Geometries(big, new Sphere(new Point3D(1, 0, 0), 0.25));
        for (int i = 0; i < 200; ++i)
            crowd.add(new Sphere(randomPoint(rnd, new Point3D(0, 0, 0), 20).add(new Vector(25, 0, 0)), 0.5));
        assertHitEverywhere(crowd, new Ray(Point3D.ZERO, new Vector(1, 0, 0)), new Point3D(0.75, 0, 0), "TC02");
        // TC03: from the centre of the big sphere in random directions: the big sphere at distance 2,
        // or the small one
        for (int r = 0; r < 200; ++r) {
            Ray ray = new Ray(new Point3D(-0.5, 0, 0), randomUnit(rnd));
            assertHitEverywhere(crowd, ray, pointOrNull(reference(crowd, ray)), "TC03: ray " + r);
            assertNotNull(reference(crowd, ray), "TC03: a ray from inside a sphere must hit");
        }

        // ===== Boundary Values Tests =====
        // TC11: from a point on the lone sphere outward: no hit
        Geometries lone = new Geometries(big);
        assertHitEverywhere(lone, new Ray(new Point3D(2, 0, 0), new Vector(1, 0, 0)), null, "TC11");
        // TC12: from a point on the lone sphere inward: the opposite point (−2, 0, 0)
        assertHitEverywhere(lone, new Ray(new Point3D(2, 0, 0), new Vector(-1, 0, 0)), new Point3D(-2, 0, 0), "TC12");
        // TC13: from the centre, the transmittance of an opaque sphere up to 1.9 is 1, up to 2.1 is 0
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(lone);
        Ray fromCentre = new Ray(Point3D.ZERO, new Vector(0, 1, 0));
        assertEquals(1, transmittance(bvh, fromCentre, 1.9, MIN_K, bvh.newQuery()), 0, "TC13: not yet at the sphere");
        assertEquals(0, transmittance(bvh, fromCentre, 2.1, MIN_K, bvh.newQuery()), 0, "TC13: past the sphere");
    }
    /**
     * Test method for {@link RayState#boxEntry(double[], int, double)} itself, on the unit cube: the
     * intervals intersected by min and max, and the rays lying in a face's plane (0·∞ = NaN), tested
     * again with the NaN skipped.
     */
    @Test
    void testBoxEntryDistances() {
        double[] box = { 0, 0, 0, 1, 1, 1 };
        // ===== Equivalence Partitions Tests =====
        // TC01: from (−1, 0.5, 0.5) along x: enters at 1
        assertEquals(1, entry(box, new Point3D(-1, 0.5, 0.5), new Vector(1, 0, 0), 10), 1e-12, "TC01");
        // TC02: from inside: enters at 0
        assertEquals(0, entry(box, new Point3D(0.5, 0.5, 0.5), new Vector(0.6, 0.8, 0), 10), 1e-12, "TC02");
        // TC03: beside the box: misses
        assertEquals(RayState.MISSED, entry(box, new Point3D(-1, 2, 0.5), new Vector(1, 0, 0), 10), 0, "TC03");
        // TC04: towards it, but maxT ends before it: misses
        assertEquals(RayState.MISSED, entry(box, new Point3D(-1, 0.5, 0.5), new Vector(1, 0, 0), 0.5), 0, "TC04");
        // TC05: diagonally from (2, 2, 2) backwards along every axis: enters at the corner (1, 1, 1)
        double s = Math.sqrt(3);
        assertEquals(s, entry(box, new Point3D(2, 2, 2), new Vector(-1 / s, -1 / s, -1 / s), 10), 1e-12, "TC05");
        // ===== Boundary Values Tests =====
        // TC11: in the plane of the high face x = 1 (x component +0): along the face, enters at 1
        assertEquals(1, entry(box, new Point3D(1, -1, 0.5), new Vector(0, 1, 0), 10), 1e-12, "TC11");
        // TC12: in the plane of the low face x = 0 (x component −0.0): enters at 1
        assertEquals(1, entry(box, new Point3D(0, -1, 0.5), new Vector(-0.0, 1, 0), 10), 1e-12, "TC12");
        // TC13: in the plane of face x = 0, going away from the box: misses
        assertEquals(RayState.MISSED, entry(box, new Point3D(0, -1, 0.5), new Vector(0, -1, 0), 10), 0, "TC13");
        // TC14: along the edge x = 0, z = 1 (two components 0): enters at 1
        assertEquals(1, entry(box, new Point3D(0, -1, 1), new Vector(0, 1, 0), 10), 1e-12, "TC14");
        // TC15: in the plane x = 1 of a box turned inside out (x0 > x1): misses
        double[] insideOut = { 1, 0, 0, 0, 1, 1 };
        assertEquals(RayState.MISSED, entry(insideOut, new Point3D(1, -1, 0.5), new Vector(0, 1, 0), 10), 0, "TC15");
        // TC16: touching the box at its corner only, at maxT: enters at 1
        assertEquals(1, entry(box, new Point3D(-1, 0, 0), new Vector(1, 0, 0), 1), 1e-12, "TC16");
    }

    /** {@return where a ray enters a box, by {@link RayState#boxEntry(double[], int, double)}} */
    private static double entry(double[] box, Point3D p0, Vector direction, double maxT) {
        return new RayState().set(p0.getX(), p0.getY(), p0.getZ(), direction.getX(), direction.getY(), direction.getZ(),
                maxT).invert().boxEntry(box, 0, maxT);
    }
}
