package accel;

import static accel.BvhFixtures.IDENTITY_MAP;
import static accel.BvhFixtures.UP;
import static accel.BvhFixtures.assertCounts;
import static accel.BvhFixtures.bumpyMesh;
import static accel.BvhFixtures.checkBundles;
import static accel.BvhFixtures.checkLeaving;
import static accel.BvhFixtures.kind;
import static accel.BvhFixtures.ridge;
import static accel.BvhFixtures.shelves;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.transmittance;
import static testutil.TestBundles.MAX_GATHERED;
import static testutil.TestBundles.ROW_ALL;
import static testutil.TestBundles.ROW_MIDDLE;
import static testutil.TestBundles.ROW_START;
import static testutil.TestBundles.THICK;
import static testutil.TestBundles.assertForgetsSubtree;
import static testutil.TestBundles.assertGathersRowSubtree;
import static testutil.TestBundles.assertKeepsSubtree;
import static testutil.TestBundles.boxesMeeting;
import static testutil.TestBundles.gather;
import static testutil.TestBundles.gatherLeaving;
import static testutil.TestBundles.gathered;
import static testutil.TestBundles.gatheredRay;
import static testutil.TestBundles.pointOnTriangle;
import static testutil.TestBundles.rayFromTo;
import static testutil.TestBundles.rayState;
import static testutil.TestBundles.rayTransmittance;
import static testutil.TestBundles.setPyramid;
import static testutil.TestBundles.shadowRays;
import static testutil.TestBundles.squarePoint;
import static testutil.TestBundles.stray;
import static testutil.TestBundles.triangleData;
import static testutil.TestRandom.randomUnit;
import static testutil.TestScenes.centroid;
import static testutil.TestScenes.emptyComposites;
import static testutil.TestScenes.meshScene;
import static testutil.TestScenes.perpendicular;
import static testutil.TestScenes.randomScene;
import static testutil.TestScenes.setKt;
import static testutil.TestScenes.triangle;
import static testutil.TestScenes.triangleRow;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import accel.BvhFixtures.GatherCounts;
import accel.BvhFixtures.OriginCounts;
import accel.BvhFixtures.Straddling;
import accel.BvhFixtures.Surface;
import benchmark.SphereMesh;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.TestBundles.Pyramid;
import testutil.TestScenes.TestScene;
import testutil.TestScenes.Wrapper;

/**
 * Unit tests for {@link BundleGather}, through {@link BoundingVolumeHierarchy#gather} and
 * {@link BoundingVolumeHierarchy#bundleRayTransmittance}: what a bundle gathers, open bundles, and the rays
 * of a gathered bundle, also from either of its ray origins ({@link ShadowFrustum#setOrigins}).
 */
class BundleGatherTest {
    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} and
     * {@link BoundingVolumeHierarchy#bundleRayTransmittance}: on seeded random scenes, every ray of a
     * bundle has the transmittance the tree gives it, whether gather found nothing, a few bodies or
     * (more than 32 of them) a subtree.
     */
    @Test
    void testRayTransmittanceRandomScenes() {
        // ===== Equivalence Partitions Tests =====
        // TC01: opaque random scenes (with planes, a tube, cylinders, squares, bodies that are not
        // Geometry, nested composites, a dense mesh): 60 bundles each from random apexes on (thick), in,
        // near and away from the bodies to random narrow and wide squares, 40 rays each:
        // bundleRayTransmittance = transmittance, 0 or 1, and so is the answer of each ray of the
        // bundle traced as one packet (packetTransmittances), also when the bundle kept the subtree of the
        // bundle before it, whose walk branched at the same node, and it is open only when nothing meets it
        Random rnd = new Random(7031);
        GatherCounts opaque = new GatherCounts();
        for (int s : new int[] { 0, 2, 3, 5, 6, 7, 8, 9, 13, 15, 17, 19 })
            checkBundles(rnd, randomScene(rnd, s), true, 1, opaque, "TC01: scene " + s);
        for (int m = 0; m < 2; ++m)
            checkBundles(rnd, meshScene(rnd), true, 1, opaque, "TC01: mesh scene " + m);
        assertCounts(opaque, "TC01");
        // TC02: the same with random kT (0.5, 0.9, 0.25, 1, some opaque), the hierarchy built on 3
        // threads: equal within 1e-12, one by one and as a packet
        double[] kts = { 0.5, 0.9, 0.25, 1, 0.75, 0.999, 0.5, 0.9, 0 };
        GatherCounts transparent = new GatherCounts();
        for (int s : new int[] { 0, 2, 4, 5, 6, 8, 9, 13, 15, 18, 19, -1, -1 }) {
            TestScene scene = s < 0 ? meshScene(rnd) : randomScene(rnd, s);
            for (Intersectable body : scene.bodies())
                setKt(body, kts, rnd);
            checkBundles(rnd, scene, false, 3, transparent, "TC02: " + (s < 0 ? "mesh scene" : "scene " + s));
        }
        assertCounts(transparent, "TC02");

        // TC03: the dense mesh as one TriangleMesh, whose gathered triangles are tested from their own
        // copies of the mesh's numbers: the same answers, opaque and with random kT
        GatherCounts mesh = new GatherCounts();
        for (int m = 0; m < 6; ++m) {
            TestScene scene = meshScene(rnd, true);
            if (m % 2 == 1)
                setKt(scene.geometries(), kts, rnd);
            checkBundles(rnd, scene, m % 2 == 0, 1 + m % 3, mesh, "TC03: TriangleMesh scene " + m);
        }
        assertTrue(mesh.few >= 50 && mesh.subtree >= 20 && mesh.none >= 20, "TC03: too few bundles of each kind ("
                + mesh.none + " none, " + mesh.few + " few, " + mesh.subtree + " subtrees)");
    }

    /**
     * Asserts that 200 random rays of the last gathered bundle have the tree's transmittance: from the
     * apex to a random point of the square, both ends moved by up to the thickness.
     *
     * @param bvh       the hierarchy
     * @param query     the scratch space, as the gather left it
     * @param apex      the apex
     * @param c         the centre of the square
     * @param a         half of one side
     * @param b         half of the other side
     * @param thickness how far the rays' ends may be moved
     * @param rnd       the generator
     * @param tc        the test-case label
     * @return how many of the rays were blocked
     */
    private static int assertBundle(BoundingVolumeHierarchy bvh, Query query, Point3D apex, Point3D c, Vector a,
                                    Vector b, double thickness, Random rnd, String tc) {
        Query treeQuery = bvh.newQuery();
        int blocked = 0;
        for (int r = 0; r < 200; ++r) {
            Point3D start = stray(rnd, apex, thickness);
            Point3D target = stray(rnd, squarePoint(rnd, c, a, b), thickness);
            Ray ray = new Ray(start, target.subtract(start));
            double distance = target.distance(start);
            double expected = transmittance(bvh, ray, distance, MIN_K, treeQuery);
            int number = r;
            assertEquals(expected, gathered(bvh, ray, distance, MIN_K, query), 0,
                    () -> tc + ": ray " + number + " from " + start + " to " + target);
            if (expected == 0)
                ++blocked;
        }
        return blocked;
    }

    /**
     * Asserts that the ray from one point to another has a given transmittance, both through the tree
     * and through the bodies the last gather kept.
     *
     * @param expected the transmittance
     * @param bvh      the hierarchy
     * @param query    the scratch space, as the gather left it
     * @param from     the ray's start
     * @param to       the ray's end
     * @param message  the failure message
     */
    private static void assertRay(double expected, BoundingVolumeHierarchy bvh, Query query, Point3D from, Point3D to,
                                  String message) {
        Ray ray = new Ray(from, to.subtract(from));
        double distance = from.distance(to);
        assertEquals(expected, transmittance(bvh, ray, distance, MIN_K, bvh.newQuery()), 0, message + " (tree)");
        assertEquals(expected, gathered(bvh, ray, distance, MIN_K, query), 0, message + " (gathered)");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} after a gather that kept a subtree: a bundle
     * whose walk first branches where that one's did keeps the subtree again, up to
     * {@link BundleGather#MAX_KEPT} in a row; any other gathers anew. On the row of 40 triangles
     * ({@code triangleRow}) under the pyramids over all of them, over triangles 19 and 20 (across the
     * root's split) and over triangles 2 and 3.
     */
    @Test
    void testGatherAfterSubtree() {
        Random rnd = new Random(4019);
        BoundingVolumeHierarchy rowBvh = BoundingVolumeHierarchy.build(triangleRow());
        Pyramid middle = ROW_MIDDLE;

        // ===== Equivalence Partitions Tests =====
        // TC01: a new query gathers the 2 triangles under the middle pyramid one by one: true, no subtree
        Query fresh = rowBvh.newQuery();
        assertTrue(middle.gather(rowBvh, fresh), "TC01: triangles 19 and 20 must be gathered");
        assertFalse(fresh.isSubtreeGathered(), "TC01: 2 triangles are kept one by one");
        // TC02: after the pyramid over all 40 (a subtree kept at the root), the middle pyramid, which
        // branches at the root too: true, the subtree kept again, and its rays agree with the tree, those
        // through triangles 19 and 20 blocked and those beside them open
        Query query = rowBvh.newQuery();
        assertKeepsSubtree(rowBvh, query, "TC02");
        assertBundle(rowBvh, query, middle.apex(), middle.c(), middle.a(), middle.b(), 0, rnd, "TC02");
        for (int i = 19; i <= 20; ++i) {
            assertRay(0, rowBvh, query, middle.apex(), new Point3D(2 * i - 19.5, 0, -10), "TC02: through triangle " + i);
            assertRay(1, rowBvh, query, middle.apex(), new Point3D(2 * i - 18.5, 0, -10), "TC02: past triangle " + i);
        }
        // TC03: then the pyramid over triangles 2 and 3, which branches below the root: gathered one by
        // one; and after it the middle pyramid is gathered one by one again
        assertTrue(ROW_START.gather(rowBvh, query), "TC03: triangles 2 and 3 must be gathered");
        assertFalse(query.isSubtreeGathered(), "TC03: a walk branching elsewhere gathers anew");
        assertTrue(middle.gather(rowBvh, query), "TC03: triangles 19 and 20 must be gathered");
        assertFalse(query.isSubtreeGathered(), "TC03: no subtree kept since the last gather's");
        // TC04: a subtree, then the middle pyramid carried into the row's space by an identity map (as an
        // instance carries its bundles): gathered one by one, since a body's tree serves every instance
        Query shared = rowBvh.threadQuery();
        assertGathersRowSubtree(rowBvh, shared, "TC04");
        ShadowFrustum carried = new ShadowFrustum();
        assertTrue(middle.set(carried), "TC04: the middle pyramid must not be flat");
        assertTrue(rowBvh.mayMeet(carried, IDENTITY_MAP, IDENTITY_MAP), "TC04: triangles 19 and 20 must be met");
        assertFalse(shared.isSubtreeGathered(), "TC04: a carried gather keeps no earlier subtree");

        // ===== Boundary Values Tests =====
        // TC11: after a subtree, a pyramid beside the row: false, and it is forgotten: the middle pyramid
        // is gathered one by one
        assertForgetsSubtree(rowBvh, query, () -> assertFalse(gather(rowBvh, query, new Point3D(20, 5, 10),
                new Point3D(20, 5, -10), ROW_ALL.a(), ROW_ALL.b()), "TC11: a pyramid beside the row must give false"),
                "TC11");
        // TC12: after a subtree, the middle pyramid keeps it MAX_KEPT (4) times in a row, then gathers in
        // full, its 2 triangles one by one
        assertGathersRowSubtree(rowBvh, query, "TC12");
        for (int k = 1; k <= BundleGather.MAX_KEPT; ++k) {
            assertTrue(middle.gather(rowBvh, query), "TC12: triangles 19 and 20, time " + k);
            assertTrue(query.isSubtreeGathered(), "TC12: the subtree kept again, time " + k);
        }
        assertTrue(middle.gather(rowBvh, query), "TC12: triangles 19 and 20 must be gathered");
        assertFalse(query.isSubtreeGathered(), "TC12: gathered in full after " + BundleGather.MAX_KEPT + " kept");
        assertBundle(rowBvh, query, middle.apex(), middle.c(), middle.a(), middle.b(), 0, rnd, "TC12");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} on its boundaries: the scan, empty
     * composites, the limit of 32 bodies (a subtree kept beyond it), a dense mesh under a big light,
     * thick bundles starting on a surface, a refused frustum, planes and bodies that are not geometries.
     */
    @Test
    void testGather() {
        Random rnd = new Random(32);
        Point3D up = new Point3D(0, 0, 5);
        Vector a = new Vector(1, 0, 0);
        Vector b = new Vector(0, 1, 0);
        Point3D below = new Point3D(0, 0, -1);
        Point3D above = new Point3D(0, 0, 1);

        // ===== Equivalence Partitions Tests =====
        // TC01: one sphere in the pyramid from (0, 0, 5) down to (±1, ±1, −1): true, and the rays
        // through it are blocked as through the tree
        Geometries ball = new Geometries(new Sphere(new Point3D(0, 0, 2), 0.5));
        BoundingVolumeHierarchy ballBvh = BoundingVolumeHierarchy.build(ball);
        Query ballQuery = ballBvh.newQuery();
        assertTrue(gather(ballBvh, ballQuery, up, below, a, b), "TC01: the sphere in the pyramid must be gathered");
        assertTrue(assertBundle(ballBvh, ballQuery, up, below, a, b, 0, rnd, "TC01") > 0,
                "TC01: some rays must be blocked");
        // TC02: the same sphere beside the pyramid (at x = 3): false, every ray open
        Geometries aside = new Geometries(new Sphere(new Point3D(3, 0, 2), 0.5));
        BoundingVolumeHierarchy asideBvh = BoundingVolumeHierarchy.build(aside);
        Query asideQuery = asideBvh.newQuery();
        assertFalse(gather(asideBvh, asideQuery, up, below, a, b),
                "TC02: a sphere beside the pyramid must not be gathered");
        assertEquals(0, assertBundle(asideBvh, asideQuery, up, below, a, b, 0, rnd, "TC02"),
                "TC02: no ray may be blocked");
        // TC03: the 40 triangles of a row under a pyramid covering all of them: true (a subtree is kept),
        // and the rays agree with the tree, through each triangle blocked, between them open
        BoundingVolumeHierarchy rowBvh = BoundingVolumeHierarchy.build(triangleRow());
        Query rowQuery = rowBvh.newQuery();
        Point3D apexRow = new Point3D(20, 0, 10);
        Point3D cRow = new Point3D(20, 0, -10);
        Vector aRow = new Vector(50, 0, 0);
        assertTrue(gather(rowBvh, rowQuery, apexRow, cRow, aRow, b),
                "TC03: a pyramid over 40 triangles must give true");
        assertBundle(rowBvh, rowQuery, apexRow, cRow, aRow, b, 0, rnd, "TC03");
        for (int i = 0; i < 40; ++i) {
            assertRay(0, rowBvh, rowQuery, apexRow, new Point3D(2 * i - 20, 0, -10), "TC03: through triangle " + i);
            assertRay(1, rowBvh, rowQuery, apexRow, new Point3D(2 * i - 19, 0, -10), "TC03: past triangle " + i);
        }
        // TC04: a body that is not a Geometry is always gathered, even far from the pyramid: true
        Geometries wrapped = new Geometries(new Wrapper(new Sphere(new Point3D(50, 50, 50), 1)));
        BoundingVolumeHierarchy wrappedBvh = BoundingVolumeHierarchy.build(wrapped);
        assertTrue(gather(wrappedBvh, wrappedBvh.newQuery(), up, below, a, b),
                "TC04: a body that is not a Geometry must be gathered");
        // TC05: a dense mesh (a sphere of radius 5 in 2208 triangles) and a big light square (edge 40) at
        // y = 12 above it, seen from the centre of a triangle at the equator with thickness 0.1, as the
        // renderer sees a point near the terminator: hundreds of boxes meet the pyramid, true, and the
        // rays (into the mesh blocked, away from it open) agree with the tree
        List<Triangle> mesh = SphereMesh.triangles(Point3D.ZERO, 5, 24, 48);
        BoundingVolumeHierarchy meshBvh =
                BoundingVolumeHierarchy.build(new Geometries(mesh.toArray(new Intersectable[0])));
        Query meshQuery = meshBvh.newQuery();
        Point3D equator = new Point3D(5, 0, 0);
        Triangle nearest = mesh.get(0);
        for (Triangle triangle : mesh)
            if (centroid(triangle).distance(equator) < centroid(nearest).distance(equator))
                nearest = triangle;
        Point3D onMesh = centroid(nearest);
        Point3D light = new Point3D(0, 12, 0);
        Vector aLight = new Vector(20, 0, 0);
        Vector bLight = new Vector(0, 0, 20);
        assertTrue(gather(meshBvh, meshQuery, onMesh, light, aLight, bLight, THICK), "TC05: the mesh must be gathered");
        int meeting = boxesMeeting(new Geometries(mesh.toArray(new Intersectable[0])), meshQuery.getFrustum());
        assertTrue(meeting > 10 * MAX_GATHERED, "TC05: the pyramid must meet hundreds of boxes, met " + meeting);
        int blockedOnMesh = assertBundle(meshBvh, meshQuery, onMesh, light, aLight, bLight, THICK, rnd, "TC05");
        assertTrue(blockedOnMesh > 20 && blockedOnMesh < 180,
                "TC05: rays into the mesh must be blocked, the others open: " + blockedOnMesh + " of 200 blocked");
        // TC06: a thick bundle (0.1) from the centre (5, 0, 0) of triangle 5 of the row, to a square
        // across the row's plane (z from −0.5 to 2.5): true (the triangle holds the apex), and rays that
        // start below it or end below the plane through it are blocked
        Point3D onRow = new Point3D(5, 0, 0);
        Point3D cAcross = new Point3D(5, 0, 1);
        Vector bAcross = new Vector(0, 0.3, 1.5);
        assertTrue(gather(rowBvh, rowQuery, onRow, cAcross, a, bAcross, THICK), "TC06: the triangle under the apex");
        int blockedOnRow = assertBundle(rowBvh, rowQuery, onRow, cAcross, a, bAcross, THICK, rnd, "TC06");
        assertTrue(blockedOnRow > 0 && blockedOnRow < 200, "TC06: some rays blocked, some open: " + blockedOnRow);
        // the ray from the apex to the square's centre (5, 0, 1), moved 0.1 down: blocked; moved 0.1 up: open
        assertRay(0, rowBvh, rowQuery, new Point3D(5, 0, -0.1), new Point3D(5, 0, 0.9),
                "TC06: from below the triangle");
        assertRay(1, rowBvh, rowQuery, new Point3D(5, 0, 0.1), new Point3D(5, 0, 1.1), "TC06: from above the triangle");

        // ===== Boundary Values Tests =====
        // TC11: the scan with bodies (a plane among them) gives true, even for a pyramid meeting nothing,
        // and its rays agree with its transmittance; an empty scan (also of empty composites) gives false
        for (Geometries scene : List.of(ball, aside, triangleRow(), new Geometries(new Plane(Point3D.ZERO,
                new Vector(0, 0, 1))))) {
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene);
            Query scanQuery = scan.newQuery();
            assertTrue(gather(scan, scanQuery, up, below, a, b), "TC11: the scan of bodies must give true");
            assertBundle(scan, scanQuery, up, below, a, b, 0, rnd, "TC11");
            assertTrue(gather(scan, scanQuery, new Point3D(100, 100, 100), new Point3D(100, 100, 110), a, b),
                    "TC11: the scan of bodies must give true even where nothing is");
        }
        for (Geometries empty : emptyComposites()) {
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(empty);
            Query scanQuery = scan.newQuery();
            assertFalse(gather(scan, scanQuery, up, below, a, b), "TC11: an empty scan must give false");
            assertEquals(1, gathered(scan, new Ray(up, new Vector(0, 0, -1)), 6, MIN_K, scanQuery), 0,
                    "TC11: nothing may block in an empty scan");
        }
        // TC12: an empty composite (also one of empty composites): false, and every ray is open
        for (Geometries empty : emptyComposites()) {
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(empty);
            Query query = bvh.newQuery();
            assertFalse(gather(bvh, query, up, below, a, b), "TC12: an empty composite gathers nothing");
            assertEquals(1, gathered(bvh, new Ray(up, new Vector(0, 0, -1)), 6, MIN_K, query), 0,
                    "TC12: nothing may block");
        }
        // TC13: a pyramid whose section at z = 0 is x ∈ [−0.5, 31.5]: exactly 32 triangles, true, and
        // the rays through each of them blocked (random rays of the row's bundles seldom meet a triangle:
        // they are compared with the tree, the rays through the triangles are aimed)
        Point3D apex32 = new Point3D(15.5, 0, 10);
        Point3D c32 = new Point3D(15.5, 0, -10);
        Vector a32 = new Vector(32, 0, 0);
        assertTrue(gather(rowBvh, rowQuery, apex32, c32, a32, b), "TC13: 32 triangles must be gathered");
        assertEquals(32, boxesMeeting(triangleRow(), rowQuery.getFrustum()), "TC13: 32 boxes must meet the pyramid");
        assertBundle(rowBvh, rowQuery, apex32, c32, a32, b, 0, rnd, "TC13");
        for (int i = 0; i < 32; ++i)
            assertRay(0, rowBvh, rowQuery, apex32, new Point3D(2 * i - 15.5, 0, -10), "TC13: through triangle " + i);
        // TC14: its section widened to x ∈ [−0.5, 32.5]: 33 triangles, more than 32: true, and the ray
        // through each of the 33 is blocked, the rays between them open
        Point3D apex33 = new Point3D(16, 0, 10);
        Point3D c33 = new Point3D(16, 0, -10);
        Vector a33 = new Vector(33, 0, 0);
        assertTrue(gather(rowBvh, rowQuery, apex33, c33, a33, b), "TC14: 33 triangles must give true");
        assertEquals(33, boxesMeeting(triangleRow(), rowQuery.getFrustum()), "TC14: 33 boxes must meet the pyramid");
        for (int i = 0; i < 33; ++i) {
            assertRay(0, rowBvh, rowQuery, apex33, new Point3D(2 * i - 16, 0, -10), "TC14: through triangle " + i);
            assertRay(1, rowBvh, rowQuery, apex33, new Point3D(2 * i - 15, 0, -10), "TC14: past triangle " + i);
        }
        assertBundle(rowBvh, rowQuery, apex33, c33, a33, b, 0, rnd, "TC14");
        // TC15: the same query gathers again after a subtree: a pyramid over the triangles 0..3 only
        // (x ∈ [−0.5, 3.5]): true, the rays agree and those through the 4 are blocked; then one beside the
        // row: false
        Point3D apex4 = new Point3D(1.5, 0, 10);
        Point3D c4 = new Point3D(1.5, 0, -10);
        Vector a4 = new Vector(4, 0, 0);
        assertTrue(gather(rowBvh, rowQuery, apex4, c4, a4, b), "TC15: 4 triangles must be gathered");
        assertBundle(rowBvh, rowQuery, apex4, c4, a4, b, 0, rnd, "TC15");
        for (int i = 0; i < 4; ++i)
            assertRay(0, rowBvh, rowQuery, apex4, new Point3D(2 * i - 1.5, 0, -10), "TC15: through triangle " + i);
        assertTrue(gather(rowBvh, rowQuery, apex33, c33, a33, b), "TC15: 33 triangles again");
        assertFalse(gather(rowBvh, rowQuery, new Point3D(20, 5, 10), new Point3D(20, 5, -10), a, b),
                "TC15: a pyramid beside the row after a subtree must give false");
        assertEquals(0, assertBundle(rowBvh, rowQuery, new Point3D(20, 5, 10), new Point3D(20, 5, -10), a, b, 0, rnd,
                "TC15"), "TC15: no ray beside the row may be blocked");

        // TC16: a plane z = 0 alone: the pyramid from (0, 0, 5) to z = 1 does not meet it (false, every
        // ray open); to z = −1 it crosses it (true, every ray blocked)
        Geometries floor = new Geometries(new Plane(Point3D.ZERO, new Vector(0, 0, 1)));
        BoundingVolumeHierarchy floorBvh = BoundingVolumeHierarchy.build(floor);
        Query floorQuery = floorBvh.newQuery();
        assertFalse(gather(floorBvh, floorQuery, up, above, a, b), "TC16: a plane the pyramid does not reach");
        assertEquals(0, assertBundle(floorBvh, floorQuery, up, above, a, b, 0, rnd, "TC16"),
                "TC16: no ray may be blocked");
        assertTrue(gather(floorBvh, floorQuery, up, below, a, b), "TC16: a plane the pyramid crosses");
        assertEquals(200, assertBundle(floorBvh, floorQuery, up, below, a, b, 0, rnd, "TC16"),
                "TC16: every ray must be blocked");
        // TC17: the pyramid's base on the plane (z = 0): true, every ray ends on it and is blocked
        assertTrue(gather(floorBvh, floorQuery, up, Point3D.ZERO, a, b), "TC17: a plane touching the base");
        assertEquals(200, assertBundle(floorBvh, floorQuery, up, Point3D.ZERO, a, b, 0, rnd, "TC17"),
                "TC17: a hit at the ray's end blocks it");
        // TC18: the plane behind the apex (the pyramid from (0, 0, 5) up to z = 10): false
        assertFalse(gather(floorBvh, floorQuery, up, new Point3D(0, 0, 10), a, b), "TC18: a plane behind the apex");
        // TC19: two planes, the pyramid crossing only z = 0: true, and the rays blocked by it
        Geometries two = new Geometries(new Plane(Point3D.ZERO, new Vector(0, 0, 1)),
                new Plane(new Point3D(0, 0, 20), new Vector(0, 0, 1)));
        BoundingVolumeHierarchy twoBvh = BoundingVolumeHierarchy.build(two);
        Query twoQuery = twoBvh.newQuery();
        assertTrue(gather(twoBvh, twoQuery, up, below, a, b), "TC19: only the crossed plane must be gathered");
        assertEquals(200, assertBundle(twoBvh, twoQuery, up, below, a, b, 0, rnd, "TC19"),
                "TC19: every ray must be blocked");
        // TC20: the plane z = −0.05 just below an apex (0, 0, 0) whose pyramid goes up to z = 5: set aside
        // by a thin pyramid (false), kept by one 0.1 thick (true), whose rays starting below it are blocked
        Geometries low = new Geometries(new Plane(new Point3D(0, 0, -0.05), new Vector(0, 0, 1)));
        BoundingVolumeHierarchy lowBvh = BoundingVolumeHierarchy.build(low);
        Query lowQuery = lowBvh.newQuery();
        Point3D top = new Point3D(0, 0, 5);
        assertFalse(gather(lowBvh, lowQuery, Point3D.ZERO, top, a, b), "TC20: the plane 0.05 behind a thin pyramid");
        assertTrue(gather(lowBvh, lowQuery, Point3D.ZERO, top, a, b, THICK),
                "TC20: the plane 0.05 behind a thick pyramid");
        int blockedLow = assertBundle(lowBvh, lowQuery, Point3D.ZERO, top, a, b, THICK, rnd, "TC20");
        assertTrue(blockedLow > 0 && blockedLow < 200, "TC20: rays from below blocked, from above open: " + blockedLow);
        // TC21: a refused (flat) frustum sets nothing aside: gather gives true over the row (a subtree), and
        // rays through each triangle are blocked, between them open
        assertFalse(rowQuery.getFrustum().set(new double[] { 5, 0, 0 }, new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, 0),
                "TC21: a flat pyramid is refused");
        assertTrue(rowBvh.gather(rowQuery), "TC21: after a refused set everything must be gathered");
        for (int i = 0; i < 40; ++i) {
            assertRay(0, rowBvh, rowQuery, new Point3D(i, 0, 5), new Point3D(i, 0, -5), "TC21: through triangle " + i);
            assertRay(1, rowBvh, rowQuery, new Point3D(i + 0.5, 0, 5), new Point3D(i + 0.5, 0, -5),
                    "TC21: past triangle " + i);
        }
        // TC22: a refused frustum over the ball (one body, kept one by one): true, the ray through it blocked
        assertFalse(ballQuery.getFrustum().set(new double[] { 0, 0, 7 }, new double[] { 0, 0, 7, 1, 0, 0, 0, 1, 0 }, 0),
                "TC22: a flat pyramid is refused");
        assertTrue(ballBvh.gather(ballQuery), "TC22: after a refused set the ball must be gathered");
        assertRay(0, ballBvh, ballQuery, up, below, "TC22: the ray through the ball");
        assertRay(1, ballBvh, ballQuery, new Point3D(3, 0, 5), new Point3D(3, 0, -1), "TC22: a ray past the ball");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} and
     * {@link BoundingVolumeHierarchy#bundleRayTransmittance} on bundles that leave a mesh's surface, set
     * as the renderer sets them ({@link ShadowFrustum#setBackFace}, {@link ShadowFrustum#setOrigins}):
     * every ray's answer equals the brute-force scan's, though gathered triangles behind a ray's origin
     * are skipped, and a bundle leaving a convex mesh gathers nothing.
     */
    @Test
    void testRayTransmittanceLeavingSurface() {
        Random rnd = new Random(20261202);
        double[] halves = { 0.5 };

        // ===== Equivalence Partitions Tests =====
        // TC01: a tessellated sphere (radius 6, 960 triangles, one TriangleMesh) with 4 small spheres
        // around, and a bumpy height field (1152 triangles) with a sphere over it; opaque, and with kT
        // 0.5 everywhere (its products are exact in any order): 200 bundles each from random points of
        // the meshes, half of them straddling the tangent plane, 30 rays each: bundleRayTransmittance
        // (and the packet's answer) = the scan's transmittance, exactly
        OriginCounts counts = new OriginCounts();
        for (int scene = 0; scene < 4; ++scene) {
            TriangleMesh mesh = scene % 2 == 0 ? SphereMesh.mesh(Point3D.ZERO, 6, 16, 32) : bumpyMesh();
            Geometries geometries = new Geometries(mesh);
            if (scene % 2 == 0)
                for (int i = 0; i < 4; ++i)
                    geometries.add(new Sphere(Point3D.ZERO.add(randomUnit(rnd).scale(8 + rnd.nextDouble())),
                            0.5 + rnd.nextDouble()));
            else
                geometries.add(new Sphere(new Point3D(1, -1, 3), 1.5));
            if (scene >= 2)
                setKt(geometries, halves, rnd);
            checkLeaving(rnd, mesh, geometries, 200, false, counts, "TC01: scene " + scene);
        }
        // both kinds of bundles are common, some rays are darkened and some open, and gathered triangles
        // of straddling bundles are skipped often: the comparison is not vacuous
        counts.assertBothKinds(300, "TC01");
        assertTrue(counts.darkened >= 3000 && counts.rays - counts.darkened >= 3000, "TC01: too few darkened ("
                + counts.darkened + ") or open (" + (counts.rays - counts.darkened) + ") rays of " + counts.rays);
        assertTrue(counts.straddlingSkipping >= 200 && counts.skipped >= 20000, "TC01: too few straddling bundles "
                + "skipping triangles (" + counts.straddlingSkipping + "), or skips (" + counts.skipped + ")");

        // TC02: the tessellated sphere alone, low lights over random points of it (the square on the normal's
        // side): the back face sets the whole convex mesh aside (gather false, every ray open as the scan
        // says), where without it the same pyramid keeps, in about a fifth of the bundles, triangles behind
        // its apex whose planes it meets and that lie outside none of its five faces
        TriangleMesh sphere = SphereMesh.mesh(Point3D.ZERO, 6, 16, 32);
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(new Geometries(sphere));
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(new Geometries(sphere));
        Query query = bvh.newQuery();
        Query scanQuery = scan.newQuery();
        int withoutBackFace = 0;
        for (int bundle = 0; bundle < 100; ++bundle) {
            int t = rnd.nextInt(sphere.getTrianglesCount());
            Point3D p = pointOnTriangle(sphere, t, 0.1 + 0.4 * rnd.nextDouble(), 0.1 + 0.4 * rnd.nextDouble());
            Vector normal = sphere.getNormal(t);
            Vector n = normal.scale(Ray.DELTA / normal.length());
            // a low light: 2 to 22 away, 0.05 to 0.3 of that over the tangent plane
            double distance = 2 + 20 * rnd.nextDouble();
            double height = 0.05 + 0.25 * rnd.nextDouble();
            Point3D c = p.add(perpendicular(rnd, normal).scale(distance)).add(normal.scale(height * distance));
            Vector a = perpendicular(rnd, c.subtract(p)).scale(distance * height * (0.05 + 0.4 * rnd.nextDouble()));
            Vector b = a.crossProduct(c.subtract(p)).normalize().scale(a.length());
            int[] gathered = gatherLeaving(bvh, query, p, n, c, a, b);
            assertNotNull(gathered, "TC02: the pyramid must not be flat");
            int number = bundle;
            assertEquals(1, gathered[0], () -> "TC02: bundle " + number + " must leave on the normal's side");
            assertEquals(0, gathered[1], () -> "TC02: bundle " + number + " from " + p + " must gather nothing");
            for (double[] ray : shadowRays(rnd, p, n, c, a, b, 20)) {
                assertEquals(1, rayTransmittance(scan, scanQuery, ray, MIN_K), 0,
                        "TC02: a ray leaving a convex mesh is open");
                assertEquals(1, gatheredRay(bvh, query, ray, MIN_K), 0,
                        "TC02: a ray leaving a convex mesh is open (gathered)");
            }
            // the same pyramid without the back face
            Point3D apex = p.add(n);
            Point3D base = c.add(n);
            assertTrue(setPyramid(query.getFrustum(), apex, base, a, b, 0), "TC02: set again");
            if (bvh.gather(query))
                ++withoutBackFace;
        }
        assertTrue(withoutBackFace >= 10, "TC02: without the back face too few bundles gathered the surface ("
                + withoutBackFace + " of 100)");

        // ===== Boundary Values Tests =====
        // TC11: bundles leaving the meshes' vertices, each shared by several triangles whose planes pass
        // through the point: every ray's answer is the scan's, exactly
        OriginCounts atVertices = new OriginCounts();
        for (TriangleMesh mesh : List.of(sphere, bumpyMesh()))
            checkLeaving(rnd, mesh, new Geometries(mesh, new Sphere(new Point3D(1, 9, 3), 1.5)), 100, true,
                    atVertices, "TC11: " + mesh);
        atVertices.assertBothKinds(50, "TC11");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#bundleRayTransmittance} on a ray from neither origin
     * ({@link ShadowFrustum#setOrigins}): the gather left out the triangles between the origins, and such a
     * ray is traced through the whole hierarchy, with exactly the scan's answer, also when a left-out
     * triangle blocks it.
     * <p>
     * An opaque ridge surface ({@link BvhFixtures#ridge}), as a mesh and as Triangle objects, and a sphere (8, 0.3, 0),
     * radius 0.5, kT 0.5; the bundle leaves p = (0.5, 0.3, 0), n = (0, 0, 0.1), to the square centred
     * (10, 0.3, 0), half-sides (0, 0, 1) and (0, 1, 0), which straddles the surface.
     */
    @Test
    void testRayTransmittanceFromNeitherOrigin() {
        Random rnd = new Random(20261204);
        Point3D p = new Point3D(0.5, 0.3, 0);
        List<double[]> ridge = ridge();
        for (boolean asMesh : new boolean[] { true, false }) {
            String kind = kind(asMesh);
            Straddling bundle = Straddling.of(Surface.of(ridge, asMesh, 0), p, 1, kind);
            Point3D c = bundle.c();
            Surface surface = bundle.surface();
            ShadowFrustum frustum = bundle.query().getFrustum();
            // every triangle of the ridge lies behind both origins and is left out
            for (int t = 0; t < ridge.size(); ++t) {
                assertTrue(frustum.behindOrigins(ridge.get(t), 0, 3, 6), kind + ": triangle " + t + " behind both");
                assertFalse(surface.mayMeet(t, frustum), kind + ": triangle " + t + " must be left out");
            }
            double[] along = rayFromTo(p, c);
            // the left-out triangle that the ray from p along the surface hits: the slope up, at x = 2.5
            double[] slope = ridge.get(4);
            assertTrue(triangle(slope).nearestHit(rayState(along)) < Geometry.NO_HIT,
                    kind + ": the ray along the surface must hit the left-out slope");

            // ===== Equivalence Partitions Tests =====
            // TC01: from p along the surface into the rising slope: origin 0 (expects 0, the scan's answer)
            assertEquals(0, frustum.originOf(along[0], along[1], along[2], along[3], along[4], along[5]),
                    "TC01: " + kind + ": a ray from p starts at neither");
            assertEquals(0, bundle.assertAsScan(along, "TC01: " + kind + ": from p along"), 0,
                    "TC01: " + kind + ": the left-out slope blocks the ray from p");
            // TC02: from p up to (10, 0.3, 0.5), over the ridge, into and out of the sphere (expects 0.25, the
            // scan's)
            assertEquals(0.25, bundle.assertAsScan(rayFromTo(p, new Point3D(10, 0.3, 0.5)),
                    "TC02: " + kind + ": from p up"), 0, "TC02: " + kind + ": only the sphere dims it");
            // TC03: from p + 0.3n (off both origins) along x, into the slope at x = 2.8 (expects 0, the scan's)
            Point3D off = p.add(UP.scale(0.3));
            assertEquals(0, bundle.assertAsScan(rayFromTo(off, c.add(UP.scale(0.3))),
                    "TC03: " + kind + ": from off both origins"), 0, "TC03: " + kind + ": the slope blocks it");
            // TC04: 100 rays from random points off both origins (within 0.1 of p) to the square: the scan's answers
            int blocked = 0;
            for (int r = 0; r < 100; ++r) {
                double[] ray = rayFromTo(stray(rnd, p, Ray.DELTA), squarePoint(rnd, c, bundle.a(), bundle.b()));
                assertEquals(0, frustum.originOf(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5]), "TC04: origin 0");
                if (bundle.assertAsScan(ray, "TC04: " + kind + ": from off the origins") == 0)
                    ++blocked;
            }
            assertTrue(blocked >= 5 && blocked <= 95, "TC04: " + kind + ": blocked " + blocked + " of 100");
            // TC05: rays from the origins, as the renderer traces them: the scan's answers
            for (double[] ray : bundle.shadowRays(rnd, 100))
                bundle.assertAsScan(ray, "TC05: " + kind + ": from an origin");

            // ===== Boundary Values Tests =====
            // TC11: from p + n exactly along the surface (d·n = 0): origin 0, over the ridge, through the
            // sphere (expects 0.25, the scan's)
            double[] above = rayFromTo(p.add(UP), c.add(UP));
            assertEquals(0, frustum.originOf(above[0], above[1], above[2], above[3], above[4], above[5]),
                    "TC11: along the surface from p + n starts at neither");
            assertEquals(0.25, bundle.assertAsScan(above, "TC11: " + kind), 0,
                    "TC11: " + kind + ": only the sphere dims it");
        }
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#gather} and
     * {@link BoundingVolumeHierarchy#bundleRayTransmittance} with the ray origins set: a gathered triangle
     * behind one origin only is kept for the rays from the other, and every ray gets exactly the scan's
     * answer, transparent bodies multiplying; the surface between the origins is left out. The same for
     * one mesh and for course-style Triangle objects.
     * <p>
     * The {@link BvhFixtures#shelves} all kT 0.5, and a sphere (8, 0, 0), radius 0.5, kT 0.5, across the surface; the
     * bundle leaves p = (0, 0, 0), n = (0, 0, 0.1), to the square centred (10, 0, 0), half-sides
     * (0, 0, 2) and (0, 2, 0).
     */
    @Test
    void testRayTransmittancePerOrigin() {
        Random rnd = new Random(20261205);
        Point3D p = Point3D.ZERO;
        List<double[]> shelves = shelves();
        for (boolean asMesh : new boolean[] { true, false }) {
            String kind = kind(asMesh);
            Straddling bundle = Straddling.of(Surface.of(shelves, asMesh, 0.5), p, 2, kind);
            ShadowFrustum frustum = bundle.query().getFrustum();
            Surface surface = bundle.surface();

            // ===== Equivalence Partitions Tests =====
            // TC01: the floor's triangles lie behind both origins (expects left out)
            for (int t = 0; t < 2; ++t) {
                assertTrue(frustum.behindOrigins(shelves.get(t), 0, 3, 6), "TC01: " + kind + ": floor behind both");
                assertFalse(surface.mayMeet(t, frustum), "TC01: " + kind + ": the floor must be left out");
            }
            // TC02: the shelves over the surface lie behind p − n only, those under it behind p + n only
            // (expects kept)
            for (int t = 2; t < shelves.size(); ++t) {
                double[] v = shelves.get(t);
                assertEquals(v[2] > 0 ? ShadowFrustum.BELOW : ShadowFrustum.ABOVE, frustum.originsBehind(triangleData(0, v), 0),
                        "TC02: " + kind + ": shelf triangle " + t + " behind one origin");
                assertFalse(frustum.behindOrigins(v, 0, 3, 6), "TC02: " + kind + ": shelf " + t + " not behind both");
                assertTrue(surface.mayMeet(t, frustum), "TC02: " + kind + ": shelf " + t + " must be kept");
            }
            // TC03: 400 rays from the origins to random points of the square, as the renderer traces them: the
            // scan's answers, exactly; per origin some are dimmed twice or more (two shelves, or into and out of
            // the sphere: ≤ 0.25) and some open
            int[] dimmedTwice = new int[3];
            int[] open = new int[3];
            for (double[] ray : bundle.shadowRays(rnd, 400)) {
                int origin = frustum.originOf(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5]);
                double answer = bundle.assertAsScan(ray, "TC03: " + kind + ": origin " + origin);
                if (answer <= 0.25)
                    ++dimmedTwice[origin];
                else if (answer == 1)
                    ++open[origin];
            }
            for (int origin = ShadowFrustum.ABOVE; origin <= ShadowFrustum.BELOW; ++origin)
                assertTrue(dimmedTwice[origin] >= 20 && open[origin] >= 20, "TC03: " + kind + ": from origin " + origin
                        + " too few rays dimmed twice (" + dimmedTwice[origin] + ") or open (" + open[origin] + ")");
            // TC04: from p + n through the shelf at 0.3 (x 5) and the one at 0.6 (x 6.67) to (10, 0, 1): origin
            // ABOVE (expects 0.25); its mirror from p − n (expects 0.25)
            double[] up = rayFromTo(p.add(UP), new Point3D(10, 0, 1));
            assertEquals(ShadowFrustum.ABOVE, frustum.originOf(up[0], up[1], up[2], up[3], up[4], up[5]), "TC04");
            assertEquals(0.25, bundle.assertAsScan(up, "TC04: " + kind + ": up"), 0,
                    "TC04: " + kind + ": two shelves over the surface");
            double[] down = rayFromTo(p.add(UP.scale(-1)), new Point3D(10, 0, -1));
            assertEquals(ShadowFrustum.BELOW, frustum.originOf(down[0], down[1], down[2], down[3], down[4], down[5]),
                    "TC04");
            assertEquals(0.25, bundle.assertAsScan(down, "TC04: " + kind + ": down"), 0,
                    "TC04: " + kind + ": two shelves under the surface");

            // ===== Boundary Values Tests =====
            // TC11: from p + n to the square's lowest edge (10, 0, −2): it leaves to the other side, origin 0,
            // traced alone through the lower shelves (expects the scan's answer)
            bundle.assertAsScan(rayFromTo(p.add(UP), new Point3D(10, 0, -2)),
                    "TC11: " + kind + ": from p + n downwards");
            // TC12: the floor alone: every triangle left out behind the origins, yet the bundle is not open, as
            // a ray from neither origin may meet them (expects true, and a ray from an origin lets all through)
            Surface floor = Surface.of(shelves.subList(0, 2), asMesh, 0.5);
            BoundingVolumeHierarchy floorBvh = BoundingVolumeHierarchy.build(new Geometries(floor.body()));
            Query floorQuery = floorBvh.newQuery();
            int[] floorGathered = gatherLeaving(floorBvh, floorQuery, p, UP, bundle.c(), bundle.a(), bundle.b());
            assertNotNull(floorGathered, "TC12: the pyramid must not be flat");
            assertTrue(floorQuery.getFrustum().leftBehindOrigins(),
                    "TC12: " + kind + ": the floor between the origins must be left out");
            assertEquals(1, floorGathered[1], "TC12: " + kind + ": a bundle that left triangles out must not be open");
            assertEquals(1, gatheredRay(floorBvh, floorQuery, up, 0), 0, "TC12: " + kind
                    + ": a ray from an origin over the floor");
        }
    }
}
