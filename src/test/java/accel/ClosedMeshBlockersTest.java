package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MIN_K;
import static testutil.TestBundles.assertPacket;
import static testutil.TestBundles.gather;
import static testutil.TestBundles.gatherLeaving;
import static testutil.TestBundles.gatheredRay;
import static testutil.TestBundles.pointOnTriangle;
import static testutil.TestBundles.rayTransmittance;
import static testutil.TestBundles.shadowRays;
import static testutil.TestMeshes.bowl;
import static testutil.TestMeshes.cuboid;
import static testutil.TestRandom.randomUnit;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;

import benchmark.SphereMesh;
import geometries.Geometries;
import geometries.Instance;
import geometries.Plane;
import geometries.Sphere;
import geometries.TriangleMesh;
import primitives.Material;
import primitives.Point3D;
import primitives.Transform;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link ClosedMeshBlockers}, through {@link BoundingVolumeHierarchy#blocksBundle}: a bundle
 * is said blocked only when every one of its rays is, and packet rays through a closed mesh's core.
 */
class ClosedMeshBlockersTest {

    /** The centre of the light's square over the scenes of closed meshes. */
    private static final Point3D SOLID_LIGHT = new Point3D(0, 0, 30);

    /** The floor z = 0 of the scenes of closed meshes, and its normal. */
    private static final Vector FLOOR_NORMAL = new Vector(0, 0, 1);

    /**
     * A scene of closed sphere meshes over a floor, under a light's square around {@link #SOLID_LIGHT}.
     *
     * @param geometries the composite: the floor, the closed meshes, the open ones, the spheres
     * @param closed     the closed meshes
     * @param open       the open meshes
     * @param spheres    the {@link Sphere} bodies
     */
    private record SolidScene(Geometries geometries, List<TriangleMesh> closed, List<TriangleMesh> open,
                              List<Sphere> spheres) {
        /**
         * Builds a random scene: the opaque floor z = 0; closed sphere meshes (radius 1 to 3, 6 to 11
         * rings, centres over x, y in [−8, 8] at heights 0.5 to 6, some cutting the floor) of a kT, and
         * one more of kT 0.5 when that kT is 0; an open bowl (a sphere's mesh without its top cap) and
         * two spheres, opaque.
         *
         * @param rnd   the generator
         * @param count the number of closed meshes of the kT
         * @param kT    their kT
         * @return the scene
         */
        static SolidScene random(Random rnd, int count, double kT) {
            Geometries geometries = new Geometries(new Plane(Point3D.ZERO, FLOOR_NORMAL));
            List<TriangleMesh> closed = new ArrayList<>();
            for (int m = 0; m < count + (kT == 0 ? 1 : 0); ++m) {
                int rings = 6 + rnd.nextInt(6);
                TriangleMesh mesh = SphereMesh.mesh(randomAbove(rnd, 0.5, 6), 1 + 2 * rnd.nextDouble(), rings,
                        2 * rings);
                mesh.setMaterial(new Material().setKt(m < count ? kT : 0.5));
                closed.add(mesh);
                geometries.add(mesh);
            }
            TriangleMesh bowl = bowl(randomAbove(rnd, 2, 6), 1.5 + rnd.nextDouble(), 8, 16);
            geometries.add(bowl);
            List<Sphere> spheres = new ArrayList<>();
            for (int i = 0; i < 2; ++i) {
                Sphere sphere = new Sphere(randomAbove(rnd, 1.5, 8), 0.5 + rnd.nextDouble());
                spheres.add(sphere);
                geometries.add(sphere);
            }
            return new SolidScene(geometries, closed, List.of(bowl), spheres);
        }

        /**
         * A random point over x, y in [−8, 8] at a height.
         *
         * @param rnd  the generator
         * @param low  the lowest height
         * @param high the highest height
         * @return the point
         */
        private static Point3D randomAbove(Random rnd, double low, double high) {
            return new Point3D(16 * rnd.nextDouble() - 8, 16 * rnd.nextDouble() - 8,
                    low + (high - low) * rnd.nextDouble());
        }
    }

    /** What the bundles over closed meshes did. */
    private static final class SolidCounts {
        /** bundles blocksBundle said were blocked. */
        private int blocked;
        /** of them, bundles leaving a mesh's surface (the rays entering the mesh). */
        private int blockedOnMesh;
        /** bundles that gathered something and were not blocked. */
        private int unblocked;
        /** rays of unblocked bundles traced as a packet that pass through an opaque closed mesh's core. */
        private int coreRays;
        /** rays traced, and of them those the scan found darkened. */
        private int rays;
        private int darkened;
    }

    /**
     * Traces random bundles through a scene of closed meshes as the renderer sets them: from random
     * points of the floor (a third of them right under a closed mesh), of the meshes' triangles and of
     * the spheres, to squares of half-side 0.5 to 6 around {@link #SOLID_LIGHT}, 24 rays each. When
     * {@link BoundingVolumeHierarchy#blocksBundle} says a bundle is blocked, every ray's brute-force
     * answer is 0, and the scan blocks no bundle itself; otherwise every ray's gathered transmittance,
     * and its answer in the packet, is exactly the scan's.
     *
     * @param rnd     the generator
     * @param scene   the scene
     * @param bundles the number of bundles
     * @param counts  the counters to add to
     * @param tc      the test-case label
     */
    private static void checkSolidBundles(Random rnd, SolidScene scene, int bundles, SolidCounts counts, String tc) {
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries());
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene.geometries());
        Query query = bvh.newQuery();
        Query scanQuery = scan.newQuery();
        Query scanGather = scan.newQuery();
        List<TriangleMesh> meshes = new ArrayList<>(scene.closed());
        meshes.addAll(scene.open());
        for (int bundle = 0; bundle < bundles; ++bundle) {
            double choice = rnd.nextDouble();
            Point3D p;
            Vector normal = FLOOR_NORMAL;
            boolean facet = false;
            if (choice < 0.35)
                p = new Point3D(24 * rnd.nextDouble() - 12, 24 * rnd.nextDouble() - 12, 0);
            else if (choice < 0.55) {
                double[] box = new double[6];
                scene.closed().get(rnd.nextInt(scene.closed().size())).bounds(box, 0);
                p = new Point3D((box[0] + box[3]) / 2 + rnd.nextGaussian(), (box[1] + box[4]) / 2 + rnd.nextGaussian(),
                        0);
            } else if (choice < 0.85) {
                TriangleMesh mesh = meshes.get(rnd.nextInt(meshes.size()));
                int t = rnd.nextInt(mesh.getTrianglesCount());
                double u = rnd.nextDouble();
                p = pointOnTriangle(mesh, t, u, (1 - u) * rnd.nextDouble());
                normal = mesh.getNormal(t);
                facet = true;
            } else {
                Sphere sphere = scene.spheres().get(rnd.nextInt(scene.spheres().size()));
                normal = randomUnit(rnd);
                p = sphere.getCenter().add(normal.scale(sphere.getRadius()));
            }
            Vector n = normal.scale(Ray.DELTA / normal.length());
            Point3D c = SOLID_LIGHT.add(new Vector(10 * rnd.nextDouble() - 5, 10 * rnd.nextDouble() - 5, 1));
            double half = 0.5 + 5.5 * rnd.nextDouble();
            double angle = Math.PI * rnd.nextDouble();
            Vector a = new Vector(Math.cos(angle), Math.sin(angle), 0).scale(half);
            Vector b = new Vector(-Math.sin(angle), Math.cos(angle), 0).scale(half);
            int[] gathered = gatherLeaving(bvh, query, p, n, c, a, b, facet);
            if (gathered == null)
                continue;
            boolean blocked = gathered[1] == 1 && bvh.blocksBundle(query);
            double[][] rays = shadowRays(rnd, p, n, c, a, b, 24);
            String bundleLabel = tc + " bundle " + bundle + " (p " + p + ", n " + n + ", c " + c + ", a " + a + ", b "
                    + b + ", facet " + facet + ", side " + gathered[0] + ", gathered " + gathered[1] + ", blocked "
                    + blocked + ")";
            if (blocked) {
                ++counts.blocked;
                if (facet)
                    ++counts.blockedOnMesh;
                int[] scanGathered = gatherLeaving(scan, scanGather, p, n, c, a, b, facet);
                assertFalse(scanGathered[1] == 1 && scan.blocksBundle(scanGather),
                        bundleLabel + ": the scan must block no bundle");
            } else if (gathered[1] == 1)
                ++counts.unblocked;
            List<Ray> packet = new ArrayList<>();
            List<Double> distances = new ArrayList<>();
            for (double[] ray : rays) {
                Supplier<String> label = () -> bundleLabel + " ray " + Arrays.toString(ray);
                double expected = 1;
                for (double minK : new double[] { MIN_K, 0 }) {
                    expected = rayTransmittance(scan, scanQuery, ray, minK);
                    if (blocked)
                        assertEquals(0, expected, 0, () -> label.get() + ": a ray of a blocked bundle must be blocked");
                    else
                        assertEquals(expected, gatheredRay(bvh, query, ray, minK), 0, label);
                }
                ++counts.rays;
                if (expected < 1) // without the cut-off
                    ++counts.darkened;
                packet.add(new Ray(new Point3D(ray[0], ray[1], ray[2]), new Vector(ray[3], ray[4], ray[5])));
                distances.add(ray[6]);
                if (!blocked && query.isSubtreeGathered() && throughCore(scene.closed(), ray))
                    ++counts.coreRays;
            }
            if (!blocked)
                assertPacket(bvh, query, scan, scanQuery, packet, distances, 0, () -> bundleLabel);
        }
    }

    /** {@return the place of mesh m of TC11's 5 × 4 grid, at a height} */
    private static Point3D gridPlace(int m, double height) {
        return new Point3D(10 * (m % 5) - 20, 10 * (m / 5) - 15, height);
    }

    /**
     * Whether a ray passes through an inner box of a closed part, closed without caps, of one of some
     * meshes that are opaque.
     *
     * @param meshes the meshes
     * @param ray    {ox, oy, oz, dx, dy, dz, distance}
     * @return true when it does
     */
    private static boolean throughCore(List<TriangleMesh> meshes, double[] ray) {
        RayState state = new RayState().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], ray[6]).invert();
        for (TriangleMesh mesh : meshes)
            for (ClosedParts.Part part : ClosedParts.of(mesh)) {
                if (mesh.getMaterial().getKt() != 0 || part.capBoxes().length > 0)
                    continue;
                double[] inner = part.innerBoxes();
                for (int b = 0; b < inner.length; b += 6)
                    if (state.boxEntry(inner, b, ray[6]) != RayState.MISSED)
                        return true;
            }
        return false;
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#blocksBundle} and
     * {@link BoundingVolumeHierarchy#packetTransmittances}: a bundle is said blocked only when the
     * brute-force scan blocks every one of its rays, and in a packet a ray through a closed opaque
     * mesh's core gets exactly the scan's answer.
     */
    @Test
    void testTryOn() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 4 random scenes of 3 opaque closed sphere meshes (and one of kT 0.5), an open bowl, two
        // spheres and a floor, 120 bundles each, as the renderer sets them (thin from the floor and the
        // spheres, thin or thick from the meshes' triangles): blocked bundles are blocked ray by ray by
        // the scan (not by its own blocksBundle), the others' rays get the scan's answers, one by one
        // and in packets
        Random rnd = new Random(20261204);
        SolidCounts opaque = new SolidCounts();
        for (int s = 0; s < 4; ++s)
            checkSolidBundles(rnd, SolidScene.random(rnd, 3, 0), 120, opaque, "TC01: scene " + s);
        // both answers are common, many blocked bundles leave a mesh, many packet rays pass through a core
        assertTrue(opaque.blocked >= 60 && opaque.unblocked >= 150, "TC01: too few blocked (" + opaque.blocked
                + ") or unblocked (" + opaque.unblocked + ") bundles");
        assertTrue(opaque.blockedOnMesh >= 20, "TC01: too few blocked bundles leaving a mesh: " + opaque.blockedOnMesh);
        assertTrue(opaque.coreRays >= 200, "TC01: too few packet rays through a core: " + opaque.coreRays);
        assertTrue(opaque.darkened >= 3000 && opaque.rays - opaque.darkened >= 3000, "TC01: too few darkened ("
                + opaque.darkened + ") or open (" + (opaque.rays - opaque.darkened) + ") rays of " + opaque.rays);
        // TC02: the same with every closed mesh of kT 0.5: no bundle is blocked, the rays through the
        // cores get the scan's answers (products of 0.5, exact in any order)
        SolidCounts transparent = new SolidCounts();
        for (int s = 0; s < 2; ++s)
            checkSolidBundles(rnd, SolidScene.random(rnd, 3, 0.5), 120, transparent, "TC02: scene " + s);
        assertEquals(0, transparent.blocked, "TC02: transparent meshes must block no bundle");
        assertTrue(transparent.unblocked >= 100, "TC02: too few bundles gathered something: " + transparent.unblocked);
        // TC03: a scene of TC02 inside an opaque closed sphere mesh (radius 60 around (0, 0, 10)) whose box
        // holds the light: its cores lie across the bundles, but no bundle is blocked and every ray gets
        // the scan's answer
        SolidScene inside = SolidScene.random(rnd, 3, 0.5);
        TriangleMesh enclosing = SphereMesh.mesh(new Point3D(0, 0, 10), 60, 8, 16);
        inside.geometries().add(enclosing);
        List<TriangleMesh> closed = new ArrayList<>(inside.closed());
        closed.add(enclosing);
        SolidCounts enclosed = new SolidCounts();
        checkSolidBundles(rnd, new SolidScene(inside.geometries(), closed, inside.open(), inside.spheres()), 120,
                enclosed, "TC03");
        assertFalse(ClosedParts.of(enclosing).isEmpty(), "TC03: the enclosing mesh has a core");
        assertEquals(0, enclosed.blocked, "TC03: a mesh around the light must block no bundle");
        assertTrue(enclosed.unblocked >= 50, "TC03: too few bundles gathered something: " + enclosed.unblocked);

        // TC04: an opaque closed bar [−20, 20] × [−1.5, 1.5] × [3, 6] over the floor: narrow bundles
        // (half-side 0.5) from the floor under it at x = 12 and x = −15 to squares over them pass through
        // an inner box: blocked, and every ray is blocked by the scan;
        // one from x = 25, beside the bar: not blocked
        Geometries bar = new Geometries(new Plane(Point3D.ZERO, FLOOR_NORMAL), cuboid(-20, -1.5, 3, 20, 1.5, 6));
        BoundingVolumeHierarchy barTree = BoundingVolumeHierarchy.build(bar);
        BoundingVolumeHierarchy barScan = BoundingVolumeHierarchy.scan(bar);
        Query barQuery = barTree.newQuery();
        Query barScanQuery = barScan.newQuery();
        Vector up = FLOOR_NORMAL.scale(Ray.DELTA);
        for (double x : new double[] { 12, -15, 25 }) {
            Point3D p = new Point3D(x, 0, 0);
            Point3D c = new Point3D(x, 0, 30);
            gatherLeaving(barTree, barQuery, p, up, c, new Vector(0.5, 0, 0), new Vector(0, 0.5, 0), false);
            assertEquals(x < 20, barTree.blocksBundle(barQuery), "TC04: the bundle from x = " + x);
            gatherLeaving(barScan, barScanQuery, p, up, c, new Vector(0.5, 0, 0), new Vector(0, 0.5, 0), false);
            for (double[] ray : shadowRays(rnd, p, up, c, new Vector(0.5, 0, 0), new Vector(0, 0.5, 0), 10))
                assertEquals(x < 20 ? 0 : 1, rayTransmittance(barScan, barScanQuery, ray, 0), 0,
                        "TC04: a ray from x = " + x + " by the scan");
        }

        // TC05: an opaque bowl with a small hole (a sphere's mesh of radius 3 at (0, 0, 5) without the fan
        // around its +y pole, the hole's radius 0.39), closed by a cap: from its centre, inside its core,
        // a wide bundle toward +y is not blocked whole, and of its rays the scan's answers, those out
        // through the hole 1 and the others 0, are the packet's; toward +x every ray is blocked
        TriangleMesh holed = bowl(new Point3D(0, 0, 5), 3, 24, 48);
        assertEquals(6, ClosedParts.of(holed).get(0).capBoxes().length, "TC05: the bowl's hole must be capped");
        Geometries cupScene = new Geometries(new Plane(Point3D.ZERO, FLOOR_NORMAL), holed);
        BoundingVolumeHierarchy cupTree = BoundingVolumeHierarchy.build(cupScene);
        BoundingVolumeHierarchy cupScan = BoundingVolumeHierarchy.scan(cupScene);
        Query cupQuery = cupTree.newQuery();
        Query cupScanQuery = cupScan.newQuery();
        Point3D centre = new Point3D(0, 0, 5);
        Vector[] ways = { new Vector(0, 1, 0), new Vector(1, 0, 0) };
        for (int w = 0; w < ways.length; ++w) {
            Vector way = ways[w];
            Point3D c = centre.add(way.scale(25));
            Vector a = new Vector(0, 0, 5);
            Vector b = way.crossProduct(a);
            gatherLeaving(cupTree, cupQuery, centre, way.scale(Ray.DELTA), c, a, b, false);
            assertFalse(cupTree.blocksBundle(cupQuery) && w == 0, "TC05: the bundle out through the hole");
            List<Ray> packet = new ArrayList<>();
            List<Double> distances = new ArrayList<>();
            int passed = 0;
            for (double[] ray : shadowRays(rnd, centre, way.scale(Ray.DELTA), c, a, b, 400)) {
                passed += (int) rayTransmittance(cupScan, cupScanQuery, ray, 0);
                packet.add(new Ray(new Point3D(ray[0], ray[1], ray[2]), new Vector(ray[3], ray[4], ray[5])));
                distances.add(ray[6]);
            }
            assertTrue(w == 0 ? passed > 0 && passed < packet.size() : passed == 0,
                    "TC05: rays out through the hole must pass, the others not: " + passed + " of " + packet.size());
            int number = w;
            assertPacket(cupTree, cupQuery, cupScan, cupScanQuery, packet, distances, 0, () -> "TC05: way " + number);
        }

        // ===== Boundary Values Tests =====
        // TC11: 17 opaque closed sphere meshes of radii 3, 3.1, …, 4.6 on a 5 × 4 grid (10 apart, at
        // height 6), a narrow bundle (half-side 0.5) from the floor right under each to a square right
        // over it: only the 16 closed meshes of the largest cores are tried, so every bundle but the
        // smallest mesh's is blocked; every ray is blocked by the scan, one by one, and the scan blocks no bundle
        Geometries row = new Geometries(new Plane(Point3D.ZERO, FLOOR_NORMAL));
        for (int m = 0; m < 17; ++m)
            row.add(SphereMesh.mesh(gridPlace(m, 6), 3 + 0.1 * m, 8, 16));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(row);
        BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(row);
        Query query = bvh.newQuery();
        Query scanQuery = scan.newQuery();
        Vector n = FLOOR_NORMAL.scale(Ray.DELTA);
        Vector a = new Vector(0.5, 0, 0);
        Vector b = new Vector(0, 0.5, 0);
        for (int m = 0; m < 17; ++m) {
            Point3D p = gridPlace(m, 0);
            Point3D c = gridPlace(m, 30);
            int[] gathered = gatherLeaving(bvh, query, p, n, c, a, b, false);
            assertEquals(1, gathered[1], "TC11: the bundle under mesh " + m + " must gather it");
            assertEquals(m > 0, bvh.blocksBundle(query), "TC11: the bundle under mesh " + m
                    + (m > 0 ? " must be blocked" : " must not be blocked: its core is the 17th largest"));
            gatherLeaving(scan, scanQuery, p, n, c, a, b, false);
            assertFalse(scan.blocksBundle(scanQuery), "TC11: the scan must block no bundle (mesh " + m + ")");
            for (double[] ray : shadowRays(rnd, p, n, c, a, b, 10))
                assertEquals(0, rayTransmittance(scan, scanQuery, ray, 0), 0, "TC11: a ray under mesh " + m
                        + " must be blocked");
        }
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#blocksBundle} through an {@link Instance}: an
     * instanced closed opaque mesh blocks a bundle whole, as the mesh built in place does.
     */
    @Test
    void testInstanceBlocks() {
        // a ball mesh of radius 1 at the origin, placed by an instance at (0, 0, 10) twice its size
        TriangleMesh ball = SphereMesh.mesh(Point3D.ZERO, 1, 16, 32);
        Instance placed = new Instance(ball, Transform.scale(2).then(Transform.translate(new Vector(0, 0, 10))));
        TriangleMesh inPlace = SphereMesh.mesh(new Point3D(0, 0, 10), 2, 16, 32);
        Vector a = new Vector(0.5, 0, 0);
        Vector b = new Vector(0, 0.5, 0);
        Point3D light = new Point3D(0, 0, 20);
        Point3D beside = new Point3D(12, 0, 20);
        // ===== Equivalence Partitions Tests =====
        for (Geometries scene : List.of(new Geometries(placed, new Plane(Point3D.ZERO, new Vector(0, 0, 1))),
                new Geometries(inPlace, new Plane(Point3D.ZERO, new Vector(0, 0, 1))))) {
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene);
            Query query = bvh.newQuery();
            String what = scene.getGeometries().get(0) instanceof Instance ? "instanced" : "in place";
            // TC01: a small light right over the ball, seen from under it: every ray crosses the ball
            assertTrue(gather(bvh, query, new Point3D(0, 0, 1), light, a, b), "TC01: " + what + " gathers");
            assertTrue(bvh.blocksBundle(query), "TC01: the " + what + " ball must block the bundle");
            // TC02: a light beside the ball: no ray meets it, nothing blocks the bundle
            assertFalse(gather(bvh, query, new Point3D(12, 0, 1), beside, a, b) && bvh.blocksBundle(query),
                    "TC02: the " + what + " ball must not block a bundle beside it");
        }
        // TC03: the instanced ball of kT 0.5 lets light through: no bundle blocked
        ball.setMaterial(new Material().setKt(0.5));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(new Geometries(placed));
        bvh.readMaterials();
        Query query = bvh.newQuery();
        gather(bvh, query, new Point3D(0, 0, 1), light, a, b);
        assertFalse(bvh.blocksBundle(query), "TC03: a transparent instanced ball must not block the bundle");
    }
}
