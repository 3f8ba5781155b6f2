package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.assertHitEverywhere;
import static testutil.BruteForce.assertPoint;
import static testutil.BruteForce.assertSameHit;
import static testutil.BruteForce.reference;
import static testutil.BruteForce.transmittance;
import static testutil.TestRandom.randomPoint;
import static testutil.TestScenes.randomRay;
import static testutil.TestScenes.randomScene;

import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Intersectable.GeoPoint;
import geometries.Sphere;
import geometries.Triangle;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.TestScenes.TestScene;

/**
 * Unit tests for {@link ClosestHitWalk}, through {@link BoundingVolumeHierarchy#closestHit}: the closest
 * hit equals the brute force's on seeded random scenes, and meshes have no seams.
 */
class ClosestHitWalkTest {

    /**
     * Test method for {@link BoundingVolumeHierarchy#closestHit(Ray, Query)}
     * against the brute force, on 20 random scenes × 500 random rays.
     */
    @Test
    void testClosestHit() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 20 seeded scenes of 1..2000 spheres and triangles (with planes, a tube, cylinders,
        // squares, bodies that are not Geometry, nested composites, many tiny triangles, all boxes
        // about one centre): the hierarchy and the scan give the brute-force closest hit of each ray
        Random rnd = new Random(20240611);
        int hits = 0;
        for (int s = 0; s < 20; ++s) {
            TestScene scene = randomScene(rnd, s);
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries());
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene.geometries());
            Query query = bvh.newQuery();
            Query scanQuery = scan.newQuery();
            for (int r = 0; r < 500; ++r) {
                Ray ray = randomRay(rnd, scene);
                GeoPoint expected = reference(scene.geometries(), ray);
                if (expected != null)
                    ++hits;
                assertSameHit(expected, bvh.closestHit(ray, query), ray, "TC01: scene " + s + " ray " + r + " (tree)");
                assertSameHit(expected, scan.closestHit(ray, scanQuery), ray, "TC01: scene " + s + " ray " + r
                        + " (scan)");
            }
        }
        // the rays are aimed so that most of them hit something: the comparison is not vacuous
        assertTrue(hits > 20 * 500 / 2, "TC01: too few rays hit anything (" + hits + ")");
        // TC02: two rows of 8 spheres of radius 1 along z, at z = 0..70 and z = 1000..1070 (the root
        // splits them, and both children are met): a ray along +z from z = −50 hits the near row's
        // first sphere at 49, one along −z from z = 2000 the far row's last at 929; once that hit is
        // found, the other row, set aside on the stack, lies beyond it
        Geometries rows = new Geometries();
        for (int i = 0; i < 8; ++i)
            rows.add(new Sphere(new Point3D(0, 0, 10 * i), 1), new Sphere(new Point3D(0, 0, 1000 + 10 * i), 1));
        BoundingVolumeHierarchy rowsTree = BoundingVolumeHierarchy.build(rows);
        Query rowsQuery = rowsTree.newQuery();
        Ray forward = new Ray(new Point3D(0, 0, -50), new Vector(0, 0, 1));
        Ray backward = new Ray(new Point3D(0, 0, 2000), new Vector(0, 0, -1));
        assertPoint(new Point3D(0, 0, -1), rowsTree.closestHit(forward, rowsQuery).point, "TC02: forward");
        assertPoint(new Point3D(0, 0, 1071), rowsTree.closestHit(backward, rowsQuery).point, "TC02: backward");
        assertSameHit(reference(rows, forward), rowsTree.closestHit(forward, rowsQuery), forward, "TC02: forward");
        assertSameHit(reference(rows, backward), rowsTree.closestHit(backward, rowsQuery), backward, "TC02: backward");

        // ===== Boundary Values Tests =====
        // TC11: 8 spheres of radius 0.5 at x = 2^24 + 1 + 3i (no float holds these numbers: the tree's
        // boxes, in floats, are rounded outward), rays along −z through points 1e-7 inside each sphere's
        // outline at its lowest and highest x: every one hits, as the brute-force search finds
        Geometries far = new Geometries();
        double x0 = (1 << 24) + 1;
        for (int i = 0; i < 8; ++i)
            far.add(new Sphere(new Point3D(x0 + 3 * i, 0.3, 0), 0.5));
        BoundingVolumeHierarchy farTree = BoundingVolumeHierarchy.build(far);
        assertTrue(farTree.getNodesCount() > 1, "TC11: the spheres must be split into several nodes");
        Query farQuery = farTree.newQuery();
        for (int i = 0; i < 8; ++i)
            for (double side : new double[] { -1, 1 }) {
                Ray ray = new Ray(new Point3D(x0 + 3 * i + side * (0.5 - 1e-7), 0.3, 10), new Vector(0, 0, -1));
                GeoPoint expected = reference(far, ray);
                assertTrue(expected != null, "TC11: sphere " + i + " must be hit near its outline");
                assertSameHit(expected, farTree.closestHit(ray, farQuery), ray, "TC11: sphere " + i + " side " + side);
            }
    }

    /**
     * Test method for rays through edges and vertices shared by triangles: on the renderer's path
     * polygons are closed, so a mesh has no seams, with or without the tree (the course's query on the
     * composite takes them as open).
     */
    @Test
    void testClosestHitSharedEdges() {
        // ===== Equivalence Partitions Tests =====
        // TC01: two triangles making the square [-1, 1]² at z = 0, split along the diagonal: a ray
        // straight down through (0.3, 0.3) on the diagonal hits one of them there
        Triangle lower = new Triangle(new Point3D(-1, -1, 0), new Point3D(1, -1, 0), new Point3D(1, 1, 0));
        Triangle upper = new Triangle(new Point3D(-1, -1, 0), new Point3D(1, 1, 0), new Point3D(-1, 1, 0));
        Geometries square = new Geometries(lower, upper);
        Ray diagonal = new Ray(new Point3D(0.3, 0.3, 5), new Vector(0, 0, -1));
        assertHitEverywhere(square, diagonal, new Point3D(0.3, 0.3, 0), "TC01");
        GeoPoint hit = BoundingVolumeHierarchy.build(square).closestHit(diagonal,
                BoundingVolumeHierarchy.build(square).newQuery());
        assertTrue(hit.geometry == lower || hit.geometry == upper, "TC01: one of the two triangles must be hit");
        // TC02: the course's query on the composite, for the same ray through the shared edge (null)
        assertNull(square.findGeoIntersections(diagonal), "TC02: the course's open triangles are missed on their edge");

        // ===== Boundary Values Tests =====
        // TC11: a 20 × 20 grid of squares over [-5, 5]² at z = 0 (800 triangles, diagonals alternating):
        // rays from above and below, slanted, aimed at random points of the grid lines, of the
        // diagonals and at the vertices, all hit the mesh there
        int n = 20;
        double h = 10.0 / n;
        Geometries mesh = new Geometries();
        Point3D[][] v = new Point3D[n + 1][n + 1];
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                v[i][j] = new Point3D(-5 + i * h, -5 + j * h, 0);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                if ((i + j) % 2 == 0)
                    mesh.add(new Triangle(v[i][j], v[i + 1][j], v[i + 1][j + 1]),
                            new Triangle(v[i][j], v[i + 1][j + 1], v[i][j + 1]));
                else
                    mesh.add(new Triangle(v[i][j], v[i + 1][j], v[i][j + 1]),
                            new Triangle(v[i + 1][j], v[i + 1][j + 1], v[i][j + 1]));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(mesh);
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(mesh);
        Query query = bvh.newQuery();
        Random rnd = new Random(12);
        for (int r = 0; r < 1500; ++r) {
            int i = rnd.nextInt(n);
            int j = rnd.nextInt(n);
            double s = rnd.nextDouble();
            Point3D target = switch (r % 4) {
            case 0 -> new Point3D(v[i][j].getX(), -5 + (j + s) * h, 0); // a line x = const
            case 1 -> new Point3D(-5 + (i + s) * h, v[i][j].getY(), 0); // a line y = const
            case 2 -> (i + j) % 2 == 0 // the cell's diagonal
                    ? new Point3D(-5 + (i + s) * h, -5 + (j + s) * h, 0)
                    : new Point3D(-5 + (i + 1 - s) * h, -5 + (j + s) * h, 0);
            default -> v[i][j]; // a vertex
            };
            Point3D origin = randomPoint(rnd, new Point3D(0, 0, rnd.nextBoolean() ? 8 : -8), 5);
            Ray ray = r % 5 == 0 ? new Ray(new Point3D(target.getX(), target.getY(), origin.getZ()),
                    new Vector(0, 0, -Math.signum(origin.getZ()))) : new Ray(origin, target.subtract(origin));
            String tc = "TC11: ray " + r + " at " + target;
            GeoPoint treeHit = bvh.closestHit(ray, query);
            GeoPoint scanHit = scan.closestHit(ray, scan.newQuery());
            assertNotNull(treeHit, tc + ": the mesh has a seam (tree)");
            assertNotNull(scanHit, tc + ": the mesh has a seam (scan)");
            assertPoint(target, treeHit.point, tc + ": wrong hit point (tree)");
            assertPoint(target, scanHit.point, tc + ": wrong hit point (scan)");
            assertEquals(0, transmittance(bvh, ray, 100, MIN_K, query), 0, tc + ": the light leaks through a seam");
        }
    }
}
