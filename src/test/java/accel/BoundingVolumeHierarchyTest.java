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
import geometries.Geometry;
import geometries.Geometries;
import geometries.Instance;
import geometries.Intersectable.GeoPoint;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import geometries.Tube;
import primitives.Point3D;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import testutil.TestBundles;
import testutil.TestInstances;
import testutil.TestMeshes;
import testutil.TestRandom;
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

    /**
     * Test method for {@link BoundingVolumeHierarchy#closestHit(Ray, Query)} and
     * {@link BoundingVolumeHierarchy#transmittance(Query, double)} through instances: the answers of the
     * scene built in place ({@link TestInstances#scene}).
     */
    @Test
    void testInstancesClosestHitAndTransmittance() {
        Random rnd = new Random(28);
        TestInstances.InstanceScene scene = TestInstances.scene(rnd);
        BoundingVolumeHierarchy instanced = BoundingVolumeHierarchy.build(scene.instanced(), 2);
        BoundingVolumeHierarchy inPlace = BoundingVolumeHierarchy.build(scene.inPlace());
        Query query = instanced.newQuery();
        Query copyQuery = inPlace.newQuery();

        // ===== Equivalence Partitions Tests =====
        // TC01: each instance is one body of the outer tree (4 + 1 + 1 + 1 + 48 instances and 5 spheres: 60)
        assertEquals(60, instanced.getBoundedCount(), "TC01: an instance must be one body of the tree");
        // TC02: 2000 random rays: the closest hit of the copy (point, normal and material)
        for (int i = 0; i < 2000; ++i) {
            Ray ray = TestInstances.randomRay(rnd);
            TestInstances.assertSameHit(inPlace.closestHit(ray, copyQuery), instanced.closestHit(ray, query),
                    "TC02: ray " + i + " " + ray);
        }
        // TC03: 2000 random rays to random distances: the copy's transmittance, with the cut-off and without
        for (int i = 0; i < 2000; ++i) {
            Ray ray = TestInstances.randomRay(rnd);
            double maxT = 80 * rnd.nextDouble() + 1e-3;
            for (double minK : new double[] { MIN_K, 0 })
                assertEquals(transmittance(inPlace, ray, maxT, minK, copyQuery),
                        transmittance(instanced, ray, maxT, minK, query), TestInstances.DELTA,
                        "TC03: ray " + i + " " + ray + " to " + maxT + " (minK " + minK + ")");
        }

        // ===== Boundary Values Tests =====
        // TC11: rays that start inside the bodies' boxes (and inside the bodies): the copy's answers
        for (int i = 0; i < 1000; ++i) {
            Point3D start = TestRandom.randomPoint(rnd, Point3D.ZERO, 10);
            Ray ray = new Ray(start, TestRandom.randomUnit(rnd));
            TestInstances.assertSameHit(inPlace.closestHit(ray, copyQuery), instanced.closestHit(ray, query),
                    "TC11: ray " + i + " " + ray);
            assertEquals(transmittance(inPlace, ray, 30, 0, copyQuery), transmittance(instanced, ray, 30, 0, query),
                    TestInstances.DELTA, "TC11: transmittance of ray " + i + " " + ray);
        }
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather(Query)},
     * {@link BoundingVolumeHierarchy#bundleRayTransmittance(Query, double)} and
     * {@link BoundingVolumeHierarchy#packetTransmittances(Query, double)} through instances: each ray of a
     * bundle gets the transmittance the scene built in place gives it alone.
     */
    @Test
    void testInstancesBundles() {
        Random rnd = new Random(280);
        TestInstances.InstanceScene scene = TestInstances.scene(rnd);
        BoundingVolumeHierarchy instanced = BoundingVolumeHierarchy.build(scene.instanced());
        BoundingVolumeHierarchy inPlace = BoundingVolumeHierarchy.build(scene.inPlace());
        Query query = instanced.newQuery();
        Query copyQuery = inPlace.newQuery();
        int subtrees = 0;
        int instancePackets = 0;

        // ===== Equivalence Partitions Tests =====
        // TC01: 300 bundles from random points toward the light's square over the crowd of instances, 16
        // rays each: one by one after the gather, and as a packet, the copy's transmittance of each ray
        // TC02: a bundle found open lets each ray through the copy whole (transmittance 1)
        for (int bundle = 0; bundle < 300; ++bundle) {
            Point3D apex = TestRandom.randomPoint(rnd, new Point3D(0, 0, 0), 8);
            List<Double> distances = new java.util.ArrayList<>();
            List<Ray> rays = TestInstances.raysToLight(rnd, apex, 16, distances);
            if (!TestBundles.gather(instanced, query, apex, TestInstances.LIGHT, TestInstances.LIGHT_A,
                    TestInstances.LIGHT_B)) {
                for (int r = 0; r < rays.size(); ++r)
                    assertEquals(1, transmittance(inPlace, rays.get(r), distances.get(r), MIN_K, copyQuery),
                            "TC02: open bundle " + bundle + " ray " + r + " " + rays.get(r));
                continue;
            }
            if (query.isSubtreeGathered())
                ++subtrees;
            else if (query.isPacketTraced())
                ++instancePackets;
            for (int r = 0; r < rays.size(); ++r)
                assertEquals(transmittance(inPlace, rays.get(r), distances.get(r), MIN_K, copyQuery),
                        TestBundles.gathered(instanced, rays.get(r), distances.get(r), MIN_K, query),
                        TestInstances.DELTA, "TC01: bundle " + bundle + " ray " + r + " " + rays.get(r));
            int number = bundle;
            TestBundles.assertPacket(instanced, query, inPlace, copyQuery, rays, distances, TestInstances.DELTA,
                    () -> "TC01: bundle " + number);
        }

        // ===== Boundary Values Tests =====
        // TC11: some bundles meet more instances than a gather keeps one by one: their packets walk a subtree
        assertTrue(subtrees > 0, "TC11: no bundle kept a subtree of instances");
        // TC13: some bundles keep a few instances one by one: their rays are a packet all the same
        assertTrue(instancePackets > 0, "TC13: no bundle traced its gathered instances as a packet");
        // TC12: a cube turned 45° about z: a thin bundle up through a corner of its box, past the cube,
        // is open; the same bundle up through the cube's middle is not
        TriangleMesh cube = TestMeshes.cube(-0.5, -0.5, -0.5, 1);
        BoundingVolumeHierarchy turned = BoundingVolumeHierarchy.build(new Geometries(new Instance(cube,
                Transform.rotateZ(45))));
        Query turnedQuery = turned.newQuery();
        Vector a = new Vector(0.01, 0, 0);
        Vector b = new Vector(0, 0.01, 0);
        assertFalse(TestBundles.gather(turned, turnedQuery, new Point3D(0.65, 0.65, -5), new Point3D(0.65, 0.65, 5), a,
                b), "TC12: a bundle past the turned cube, through its box, must be open");
        assertTrue(TestBundles.gather(turned, turnedQuery, new Point3D(0, 0, -5), new Point3D(0, 0, 5), a, b),
                "TC12: a bundle through the turned cube must not be open");
    }

    /**
     * Test method for the queries of an instance's body: {@link BoundingVolumeHierarchy#threadQuery()},
     * {@link BoundingVolumeHierarchy#bounds(double[])} and
     * {@link BoundingVolumeHierarchy#nearestHit(RayState, double[])}.
     */
    @Test
    void testInstanceQueries() throws InterruptedException {
        Sphere sphere = new Sphere(Point3D.ZERO, 1);
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(sphere);
        // into the body's space: x halved, then moved by -5 along x (the world's sphere: x in [8, 12])
        double[] toBody = Transform.translate(new Vector(-10, 0, 0)).then(Transform.scale(0.5, 1, 1)).toArray();
        RayState ray = new RayState().set(0, 0, 0, 1, 0, 0, Geometry.NO_HIT);

        // ===== Equivalence Partitions Tests =====
        // TC01: a ray along x from the origin meets the stretched sphere at x = 8 (distance 8)
        assertEquals(8, bvh.nearestHit(ray, toBody), 1e-12, "TC01: wrong distance through the map");
        // TC02: the body's box: the sphere's, padded a little
        double[] box = new double[6];
        assertTrue(bvh.bounds(box), "TC02: a sphere is bounded");
        assertEquals(-1, box[0], 1e-6, "TC02: wrong box");
        assertEquals(1, box[5], 1e-6, "TC02: wrong box");
        // TC03: one query per thread: the same on one thread, another on another thread
        assertSame(bvh.threadQuery(), bvh.threadQuery(), "TC03: a thread must keep its query");
        Query[] other = new Query[1];
        Thread thread = new Thread(() -> other[0] = bvh.threadQuery());
        thread.start();
        thread.join();
        assertNotNull(other[0], "TC03: another thread must get a query");
        assertFalse(other[0] == bvh.threadQuery(), "TC03: another thread must get its own query");

        // ===== Boundary Values Tests =====
        // TC11: the hit beyond the ray's distance (7.9): none
        assertEquals(Geometry.NO_HIT, bvh.nearestHit(ray.set(0, 0, 0, 1, 0, 0, 7.9), toBody), "TC11: hit beyond maxT");
        // TC12: an unbounded body and an empty composite have no box (false)
        assertFalse(BoundingVolumeHierarchy.build(new Plane(Point3D.ZERO, new Vector(0, 0, 1))).bounds(box),
                "TC12: a plane has no box");
        assertFalse(BoundingVolumeHierarchy.build(new Geometries()).bounds(box), "TC12: nothing has no box");
        // TC13: a body that is not a geometry (a wrapped sphere): no box, and still hit through the map (8),
        // not beyond the ray's distance
        BoundingVolumeHierarchy wrapped = BoundingVolumeHierarchy.build(new testutil.TestScenes.Wrapper(sphere));
        assertFalse(wrapped.bounds(box), "TC13: an intersectable that is not a geometry has no box");
        assertEquals(8, wrapped.nearestHit(ray.set(0, 0, 0, 1, 0, 0, Geometry.NO_HIT), toBody), 1e-12,
                "TC13: wrong distance to the wrapped sphere");
        assertEquals(Geometry.NO_HIT, wrapped.nearestHit(ray.set(0, 0, 0, 1, 0, 0, 7.9), toBody),
                "TC13: the wrapped sphere's hit beyond maxT");
    }
}
