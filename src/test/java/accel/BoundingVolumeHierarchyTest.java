package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.assertPoint;
import static testutil.BruteForce.transmittance;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestScenes.emptyComposites;
import static testutil.TestScenes.randomScene;
import static testutil.TestScenes.randomSphere;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Cylinder;
import geometries.Geometries;
import geometries.Intersectable.GeoPoint;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import geometries.Tube;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.TestScenes.TestScene;

/**
 * Unit tests for {@link BoundingVolumeHierarchy}, the facade: building and scanning a composite, the
 * counts of the tree's shape, and whether it is still built from its composite. The walks behind it are
 * tested in their own classes (ClosestHitWalkTest, TransmittanceWalkTest, BundleGatherTest, ...).
 */
class BoundingVolumeHierarchyTest {
    /**
     * Test method for the shape of the tree: {@link BoundingVolumeHierarchy#getNodesCount()},
     * {@link BoundingVolumeHierarchy#getDepth()} and {@link BoundingVolumeHierarchy#getBoundedCount()}.
     */
    @Test
    void testGetNodesCount() {
        Random rnd = new Random(5);
        Ray anyRay = new Ray(new Point3D(0, 0, 100), new Vector(0, 0, -1));

        // ===== Equivalence Partitions Tests =====
        // TC01: 1000 spread spheres: one node per body at most (2n − 1), an odd count (every inner
        // node has two children), depth well below the limit of 64
        Geometries spread = new Geometries();
        for (int i = 0; i < 1000; ++i)
            spread.add(randomSphere(rnd, 100, 0.1, 1));
        BoundingVolumeHierarchy big = BoundingVolumeHierarchy.build(spread);
        assertEquals(1000, big.getBoundedCount(), "TC01: wrong bounded count");
        assertTrue(big.getNodesCount() > 1 && big.getNodesCount() <= 2 * 1000 - 1,
                "TC01: wrong nodes count " + big.getNodesCount());
        assertEquals(1, big.getNodesCount() % 2, "TC01: a full binary tree has an odd nodes count");
        assertTrue(big.getDepth() >= 2 && big.getDepth() <= 32, "TC01: depth " + big.getDepth()
                + " is not well below 64");

        // TC02: planes and tubes stay outside the tree and are not counted; a cylinder is bounded
        Geometries mixed = new Geometries(new Sphere(new Point3D(0, 0, 0), 1),
                new Triangle(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)),
                new Plane(new Point3D(0, 0, -1), new Vector(0, 0, 1)),
                new Tube(new Ray(Point3D.ZERO, new Vector(1, 0, 0)), 1),
                new Cylinder(new Ray(Point3D.ZERO, new Vector(0, 1, 0)), 1, 2),
                new Geometries(new Plane(new Point3D(0, 0, -3), new Vector(0, 1, 1))));
        BoundingVolumeHierarchy mixedBvh = BoundingVolumeHierarchy.build(mixed);
        assertEquals(3, mixedBvh.getBoundedCount(), "TC02: planes and tubes must not be counted");
        assertEquals(1, mixedBvh.getNodesCount(), "TC02: 3 bodies make one leaf");

        // TC03: 5 spheres far apart along x: splitting pays, so more than one node
        Geometries five = new Geometries();
        for (int i = 0; i < 5; ++i)
            five.add(new Sphere(new Point3D(100 * i, 0, 0), 1));
        BoundingVolumeHierarchy fiveBvh = BoundingVolumeHierarchy.build(five);
        assertTrue(fiveBvh.getNodesCount() >= 3, "TC03: 5 spread spheres must be split");
        assertTrue(fiveBvh.getDepth() >= 2, "TC03: 5 spread spheres must be split");

        // TC04: the scan has no tree: 0 nodes, depth 0, nothing in a tree
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(spread);
        assertEquals(0, scan.getNodesCount(), "TC04: the scan has no nodes");
        assertEquals(0, scan.getDepth(), "TC04: the scan has no depth");
        assertEquals(0, scan.getBoundedCount(), "TC04: the scan has nothing in a tree");

        // ===== Boundary Values Tests =====
        // TC11: an empty composite (also one of empty composites): 0 nodes, depth 0, no hit, transmittance 1
        for (Geometries empty : emptyComposites()) {
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(empty);
            assertEquals(0, bvh.getNodesCount(), "TC11: an empty composite has no nodes");
            assertEquals(0, bvh.getDepth(), "TC11: an empty composite has depth 0");
            assertEquals(0, bvh.getBoundedCount(), "TC11: an empty composite has no bodies");
            assertNull(bvh.closestHit(anyRay, bvh.newQuery()), "TC11: an empty composite is never hit");
            assertEquals(1, transmittance(bvh, anyRay, 1000, MIN_K, bvh.newQuery()), 0,
                    "TC11: nothing blocks the light");
        }

        // TC12: one body (also given bare, not in a composite): 1 node, depth 1, found
        Sphere lone = new Sphere(new Point3D(0, 0, 0), 1);
        for (Intersectable single : List.of(new Geometries(lone), lone)) {
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(single);
            assertEquals(1, bvh.getNodesCount(), "TC12: one body makes one node");
            assertEquals(1, bvh.getDepth(), "TC12: one body makes depth 1");
            assertEquals(1, bvh.getBoundedCount(), "TC12: one body in the tree");
            GeoPoint hit = bvh.closestHit(anyRay, bvh.newQuery());
            assertSame(lone, hit.geometry, "TC12: the body must be hit");
            assertPoint(new Point3D(0, 0, 1), hit.point, "TC12: wrong hit point");
        }

        // TC13: 2, 3 and 4 bodies, even far apart: one leaf
        for (int n = 2; n <= 4; ++n) {
            Geometries few = new Geometries();
            for (int i = 0; i < n; ++i)
                few.add(new Sphere(new Point3D(100 * i, 0, 0), 1));
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(few);
            assertEquals(1, bvh.getNodesCount(), "TC13: " + n + " bodies make one leaf");
            assertEquals(1, bvh.getDepth(), "TC13: " + n + " bodies make depth 1");
        }

        // TC14: only unbounded bodies: no tree, yet the plane is hit
        BoundingVolumeHierarchy planes = BoundingVolumeHierarchy.build(
                new Geometries(new Plane(new Point3D(0, 0, -1), new Vector(0, 0, 1))));
        assertEquals(0, planes.getNodesCount(), "TC14: a plane makes no node");
        assertEquals(0, planes.getBoundedCount(), "TC14: a plane is not bounded");
        assertPoint(new Point3D(0, 0, -1), planes.closestHit(anyRay, planes.newQuery()).point,
                "TC14: the plane must be hit");

        // TC15: 2000 bodies whose boxes share one centre cannot be split apart usefully: the tree
        // stays within the limits and every body is kept
        TestScene sameCentre = randomScene(rnd, 14);
        BoundingVolumeHierarchy centred = BoundingVolumeHierarchy.build(sameCentre.geometries());
        assertEquals(sameCentre.bodies().size(), centred.getBoundedCount(), "TC15: every body must be in the tree");
        assertTrue(centred.getDepth() <= 64, "TC15: depth over the limit");
        assertTrue(centred.getNodesCount() <= 2 * centred.getBoundedCount() - 1, "TC15: too many nodes");

        // TC16: the hierarchy is built once: a body added to the composite afterwards is not seen
        // (build a new hierarchy after changing the scene)
        Geometries growing = new Geometries(new Sphere(new Point3D(10, 0, 0), 1));
        BoundingVolumeHierarchy before = BoundingVolumeHierarchy.build(growing);
        growing.add(new Sphere(new Point3D(0, 0, 0), 1));
        assertNotNull(growing.findGeoIntersections(anyRay), "TC16: the composite itself sees the new body");
        assertNull(before.closestHit(anyRay, before.newQuery()),
                "TC16: the hierarchy must not see a body added after it");
        assertEquals(1, transmittance(before, anyRay, 1000, MIN_K, before.newQuery()), 0,
                "TC16: the new body must not block the old hierarchy's light");
        assertEquals(1, before.getBoundedCount(), "TC16: the count must stay as built");
        BoundingVolumeHierarchy after = BoundingVolumeHierarchy.build(growing);
        assertPoint(new Point3D(0, 0, 1), after.closestHit(anyRay, after.newQuery()).point,
                "TC16: a new hierarchy must see the new body");
    }

    /** Test method for {@link BoundingVolumeHierarchy#isBuiltFrom(Intersectable)}. */
    @Test
    void testIsBuiltFrom() {
        Geometries inner = new Geometries(new Sphere(new Point3D(5, 0, 0), 1));
        Geometries scene = new Geometries(new Sphere(new Point3D(0, 0, 0), 1), inner);
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene, 2);

        // ===== Equivalence Partitions Tests =====
        // TC01: the same composite, unchanged: up to date (true)
        assertTrue(bvh.isBuiltFrom(scene), "TC01: an unchanged composite must be up to date");
        // TC02: another composite with the same bodies: out of date (false)
        assertFalse(bvh.isBuiltFrom(new Geometries(scene.getGeometries().toArray(new Intersectable[0]))),
                "TC02: another composite must be out of date");
        // TC03: a body added to a nested composite: out of date (false), and a new build is up to date
        inner.add(new Sphere(new Point3D(10, 0, 0), 1));
        assertFalse(bvh.isBuiltFrom(scene), "TC03: a body added to a nested composite must be seen");
        bvh = BoundingVolumeHierarchy.build(scene);
        assertTrue(bvh.isBuiltFrom(scene), "TC03: a new build must be up to date");
        // TC04: a body added to the composite itself: out of date (false)
        scene.add(new Triangle(new Point3D(0, 0, 0), new Point3D(1, 0, 0), new Point3D(0, 1, 0)));
        assertFalse(bvh.isBuiltFrom(scene), "TC04: a body added to the composite must be seen");
        // TC05: the brute-force scan knows the same (true, then false after an addition)
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene);
        assertTrue(scan.isBuiltFrom(scene), "TC05: an unchanged composite must be up to date for the scan");
        inner.add(new Plane(new Point3D(0, 0, -1), new Vector(0, 0, 1)));
        assertFalse(scan.isBuiltFrom(scene), "TC05: a body added must be seen by the scan");

        // ===== Boundary Values Tests =====
        // TC11: a composite nested after the build, then a body added to it: out of date both times (false)
        Geometries late = new Geometries();
        bvh = BoundingVolumeHierarchy.build(scene);
        scene.add(late);
        assertFalse(bvh.isBuiltFrom(scene), "TC11: a composite nested after the build must be seen");
        bvh = BoundingVolumeHierarchy.build(scene);
        late.add(new Sphere(new Point3D(0, 5, 0), 1));
        assertFalse(bvh.isBuiltFrom(scene), "TC11: a body added to a late nested composite must be seen");
        // TC12: a single body, not a composite: up to date for itself (true), not for another body (false)
        Sphere lone = new Sphere(new Point3D(0, 0, 0), 1);
        BoundingVolumeHierarchy single = BoundingVolumeHierarchy.build(lone);
        assertTrue(single.isBuiltFrom(lone), "TC12: a single body must be up to date");
        assertFalse(single.isBuiltFrom(new Sphere(new Point3D(0, 0, 0), 1)), "TC12: another body must be out of date");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#build(Intersectable)},
     * {@link BoundingVolumeHierarchy#build(Intersectable, int)} and
     * {@link BoundingVolumeHierarchy#scan(Intersectable)} with bad input.
     */
    @Test
    void testBuildBadInput() {
        // ===== Boundary Values Tests =====
        // TC11: a null composite
        assertMessage(assertThrows(IllegalArgumentException.class, () -> BoundingVolumeHierarchy.build(null),
                "TC11: build(null) must throw"), "geometries", "TC11");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> BoundingVolumeHierarchy.scan(null),
                "TC11: scan(null) must throw"), "geometries", "TC11");
        // TC12: no thread to build on (0 threads)
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> BoundingVolumeHierarchy.build(new Geometries(), 0), "TC12: 0 threads must throw"),
                "threads", "TC12");
    }
}
