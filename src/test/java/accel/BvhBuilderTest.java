package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.assertHitEverywhere;
import static testutil.BruteForce.assertPoint;
import static testutil.BruteForce.assertSameHit;
import static testutil.BruteForce.reference;
import static testutil.BruteForce.transmittance;
import static testutil.TestScenes.randomRay;
import static testutil.TestScenes.randomScene;
import static testutil.TestScenes.setKt;

import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Intersectable.GeoPoint;
import geometries.Intersectable;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.TestScenes.TestScene;

/**
 * Unit tests for {@link BvhBuilder}, through {@link BoundingVolumeHierarchy#build(Intersectable, int)}: a
 * build shared out among threads, and the padding of the bodies' boxes.
 */
class BvhBuilderTest {
    /**
     * Test method for {@link BoundingVolumeHierarchy#build(Intersectable, int)}: a build shared out
     * among threads answers every query as the one built on one thread and as the brute force.
     */
    @Test
    void testBuildParallel() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 20 seeded scenes (1..2000 bodies, some transparent), built on 2, 3 and 8 threads: the
        // same shape (nodes, depth, bodies) as on one thread, the same closest hit (the same body at
        // the same point) and the same transmittance of each ray, and the brute force's answers
        Random rnd = new Random(16);
        double[] kts = { 0, 0, 0.5, 0.9 };
        int hits = 0;
        for (int s = 0; s < 20; ++s) {
            TestScene scene = randomScene(rnd, s);
            for (Intersectable body : scene.bodies())
                setKt(body, kts, rnd);
            BoundingVolumeHierarchy single = BoundingVolumeHierarchy.build(scene.geometries());
            for (int threads : new int[] { 2, 3, 8 }) {
                BoundingVolumeHierarchy parallel = BoundingVolumeHierarchy.build(scene.geometries(), threads);
                String tc = "TC01: scene " + s + ", " + threads + " threads";
                assertEquals(single.getNodesCount(), parallel.getNodesCount(), tc + ": wrong nodes count");
                assertEquals(single.getDepth(), parallel.getDepth(), tc + ": wrong depth");
                assertEquals(single.getBoundedCount(), parallel.getBoundedCount(), tc + ": wrong bounded count");
                for (int r = 0; r < 100; ++r) {
                    Ray ray = randomRay(rnd, scene);
                    GeoPoint expected = single.closestHit(ray, single.newQuery());
                    GeoPoint actual = parallel.closestHit(ray, parallel.newQuery());
                    assertSameHit(reference(scene.geometries(), ray), actual, ray, tc + " ray " + r + " (brute force)");
                    if (expected != null) {
                        ++hits;
                        assertSame(expected.geometry, actual.geometry, tc + " ray " + r + ": another body hit");
                        assertPoint(expected.point, actual.point, tc + " ray " + r);
                    }
                    double d = 60 * rnd.nextDouble();
                    assertEquals(transmittance(single, ray, d, 0, single.newQuery()),
                            transmittance(parallel, ray, d, 0, parallel.newQuery()), 1e-12,
                            tc + " ray " + r + ": wrong transmittance");
                }
            }
        }
        assertTrue(hits > 3 * 20 * 100 / 2, "TC01: too few rays hit anything (" + hits + ")");

        // ===== Boundary Values Tests =====
        // TC11: more threads than bodies (1, 2 and 5 bodies on 8 threads): the same tree as on one thread
        Ray down = new Ray(new Point3D(0, 0, 100), new Vector(0, 0, -1));
        for (int n : new int[] { 1, 2, 5 }) {
            Geometries few = new Geometries();
            for (int i = 0; i < n; ++i)
                few.add(new Sphere(new Point3D(100 * i, 0, 0), 1));
            BoundingVolumeHierarchy parallel = BoundingVolumeHierarchy.build(few, 8);
            assertEquals(BoundingVolumeHierarchy.build(few).getNodesCount(), parallel.getNodesCount(),
                    "TC11: " + n + " bodies: wrong nodes count");
            assertPoint(new Point3D(0, 0, 1), parallel.closestHit(down, parallel.newQuery()).point,
                    "TC11: " + n + " bodies: the first sphere must be hit");
        }
        // TC12: an empty composite on 2 threads: no nodes, no hit
        BoundingVolumeHierarchy empty = BoundingVolumeHierarchy.build(new Geometries(), 2);
        assertEquals(0, empty.getNodesCount(), "TC12: an empty composite has no nodes");
        assertNull(empty.closestHit(down, empty.newQuery()), "TC12: an empty composite is never hit");
    }

    /**
     * Test method for hits inside a body's tolerance just outside its exact shape: the closed
     * polygons' edge tolerance and the cylinder's cap tolerance reach past the exact bounding box,
     * and the tree must find what the brute force finds.
     */
    @Test
    void testPadBoxes() {
        // ===== Boundary Values Tests =====
        // TC11: a sharp triangle (tip at x = −1) hit 3.5e-9 beyond its tip (barycentric tolerance 1e-9)
        Geometries sharp = new Geometries(new Triangle(new Point3D(-1, 0, 0), new Point3D(1, -0.01, 0),
                new Point3D(1, 0.01, 0)));
        Ray pastTip = new Ray(new Point3D(-1 - 3.5e-9, 0, 5), new Vector(0, 0, -1));
        assertNotNull(reference(sharp, pastTip), "TC11: the triangle's tolerance must take this ray");
        assertHitEverywhere(sharp, pastTip, new Point3D(-1 - 3.5e-9, 0, 0), "TC11");

        // TC12: the same sliver as a Polygon (edge tolerance 1e-9 of its size): hit 1e-7 beyond its tip
        Geometries sliver = new Geometries(new Polygon(new Point3D(-1, 0, 0), new Point3D(1, -0.01, 0),
                new Point3D(1, 0.01, 0)));
        Ray pastSliver = new Ray(new Point3D(-1 - 1e-7, 0, 5), new Vector(0, 0, -1));
        assertNotNull(reference(sliver, pastSliver), "TC12: the polygon's tolerance must take this ray");
        assertHitEverywhere(sliver, pastSliver, new Point3D(-1 - 1e-7, 0, 0), "TC12");

        // TC13: a thin cylinder (radius 1e-3): a ray along its axis 3e-8 outside the rim hits the top cap
        Geometries thin = new Geometries(new Cylinder(new Ray(Point3D.ZERO, new Vector(0, 0, 1)), 1e-3, 1));
        Ray pastRim = new Ray(new Point3D(1e-3 + 3e-8, 0, 5), new Vector(0, 0, -1));
        assertNotNull(reference(thin, pastRim), "TC13: the cap's tolerance must take this ray");
        assertHitEverywhere(thin, pastRim, new Point3D(1e-3 + 3e-8, 0, 1), "TC13");
    }
}
