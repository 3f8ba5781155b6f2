package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.BruteForce.MARGIN;
import static testutil.BruteForce.MIN_K;
import static testutil.BruteForce.nearAHit;
import static testutil.BruteForce.reference;
import static testutil.BruteForce.referenceTransmittance;
import static testutil.BruteForce.transmittance;
import static testutil.TestScenes.randomRay;
import static testutil.TestScenes.randomScene;
import static testutil.TestScenes.setKt;

import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Intersectable.GeoPoint;
import geometries.Intersectable;
import geometries.Sphere;
import geometries.Triangle;
import primitives.Material;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.TestScenes.TestScene;

/**
 * Unit tests for {@link TransmittanceWalk}, through {@link BoundingVolumeHierarchy#transmittance}: the
 * shadow ray's transmittance equals the brute force's product of kT, on opaque and transparent scenes.
 */
class TransmittanceWalkTest {
    /**
     * Test method for {@link BoundingVolumeHierarchy#transmittance} on opaque scenes: an any-hit
     * query, 0 exactly when the closest hit is within the distance.
     */
    @Test
    void testTransmittanceOpaque() {
        // ===== Equivalence Partitions Tests =====
        // TC01: opaque random scenes, random distances: 0 when the closest hit is at most that far, else 1
        Random rnd = new Random(77);
        int blocked = 0;
        int open = 0;
        for (int s : new int[] { 0, 2, 5, 6, 8, 9, 12, 13, 15, 17, 19 }) {
            TestScene scene = randomScene(rnd, s);
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries());
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene.geometries());
            Query query = bvh.newQuery();
            for (int r = 0; r < 300; ++r) {
                Ray ray = randomRay(rnd, scene);
                GeoPoint closest = reference(scene.geometries(), ray);
                double t = closest == null ? Double.POSITIVE_INFINITY : ray.getP0().distance(closest.point);
                // random distances, and distances just before and just past the hit
                double[] distances = { 60 * rnd.nextDouble(), t + 1e-5, Math.max(1e-7, t - 1e-5),
                        Double.POSITIVE_INFINITY };
                for (double d : distances) {
                    if (closest != null && Math.abs(t - d) < MARGIN)
                        continue;
                    double expected = closest != null && t <= d ? 0 : 1;
                    if (expected == 0)
                        ++blocked;
                    else
                        ++open;
                    String tc = "TC01: scene " + s + " ray " + r + " " + ray + " distance " + d;
                    assertEquals(expected, transmittance(bvh, ray, d, MIN_K, query), 0, tc + " (tree)");
                    assertEquals(expected, transmittance(bvh, ray, d, 0, query), 0, tc + " (tree, no cut-off)");
                    assertEquals(expected, transmittance(scan, ray, d, MIN_K, scan.newQuery()), 0, tc + " (scan)");
                }
            }
        }
        assertTrue(blocked > 1000 && open > 1000, "TC01: too few blocked (" + blocked + ") or open (" + open
                + ") rays");

        // ===== Boundary Values Tests =====
        // TC11: a sphere at distance 4..6 along the ray: distance 4 − 1e-9 gives 1, 4 gives 0 (the hit counts)
        Geometries one = new Geometries(new Sphere(new Point3D(0, 0, -5), 1));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(one);
        Ray down = new Ray(new Point3D(0, 0, 0), new Vector(0, 0, -1));
        assertEquals(1, transmittance(bvh, down, 4 - 1e-9, MIN_K, bvh.newQuery()), 0, "TC11: hit beyond the distance");
        assertEquals(0, transmittance(bvh, down, 4, MIN_K, bvh.newQuery()), 0, "TC11: hit at the distance");
    }

    /**
     * Test method for {@link BoundingVolumeHierarchy#transmittance} on transparent scenes: the
     * product of kT over the intersections up to the distance.
     */
    @Test
    void testTransmittanceTransparent() {
        // ===== Equivalence Partitions Tests =====
        // TC01: random kT (0.5, 0.9, 0.25, 1, some opaque): the product of kT over the intersections
        // up to d (polygons closed), and 0 below the cut-off; the scan gives the same
        Random rnd = new Random(4242);
        double[] kts = { 0.5, 0.9, 0.25, 1, 0.75, 0.999, 0.5, 0.9, 0 };
        int partial = 0;
        for (int s : new int[] { 0, 4, 5, 6, 8, 9, 13, 15, 18, 19 }) {
            TestScene scene = randomScene(rnd, s);
            for (Intersectable body : scene.bodies())
                setKt(body, kts, rnd);
            BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries());
            BoundingVolumeHierarchy scan = BoundingVolumeHierarchy.scan(scene.geometries());
            Query query = bvh.newQuery();
            Query scanQuery = scan.newQuery();
            for (int r = 0; r < 300; ++r) {
                Ray ray = randomRay(rnd, scene);
                double d = rnd.nextInt(8) == 0 ? Double.POSITIVE_INFINITY : 60 * rnd.nextDouble();
                if (nearAHit(scene.geometries(), ray, d))
                    continue;
                double expected = referenceTransmittance(scene.geometries(), ray, d);
                if (expected > 0 && expected < 1)
                    ++partial;
                String tc = "TC01: scene " + s + " ray " + r + " " + ray + " distance " + d;
                assertEquals(expected, transmittance(bvh, ray, d, 0, query), 1e-12, tc + " (tree)");
                assertEquals(expected, transmittance(scan, ray, d, 0, scanQuery), 1e-12, tc + " (scan)");
                double cut = expected < MIN_K ? 0 : expected;
                assertEquals(cut, transmittance(bvh, ray, d, MIN_K, query), 1e-12, tc + " (tree, cut-off)");
                assertEquals(cut, transmittance(scan, ray, d, MIN_K, scanQuery), 1e-12, tc + " (scan, cut-off)");
            }
        }
        assertTrue(partial > 500, "TC01: too few rays through transparent bodies (" + partial + ")");

        // ===== Boundary Values Tests =====
        // TC11: a sphere of kT 0.5 crossed twice and a triangle of kT 0.5 behind it: 0.25 up to the
        // triangle, 0.125 past it; with the cut-off 0.2 the second is 0
        Geometries glass = new Geometries(
                new Sphere(new Point3D(0, 0, -5), 1).setMaterial(new Material().setKt(0.5)),
                new Triangle(new Point3D(-1, -1, -8), new Point3D(1, -1, -8), new Point3D(0, 1, -8))
                        .setMaterial(new Material().setKt(0.5)));
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(glass);
        Ray down = new Ray(new Point3D(0, 0, 0), new Vector(0, 0, -1));
        assertEquals(0.25, transmittance(bvh, down, 7, 0, bvh.newQuery()), 1e-12, "TC11: two sphere crossings");
        assertEquals(0.125, transmittance(bvh, down, 8, 0, bvh.newQuery()), 1e-12, "TC11: and the triangle");
        assertEquals(0, transmittance(bvh, down, 8, 0.2, bvh.newQuery()), 0, "TC11: below the cut-off");
        // TC12: a ray starting inside the sphere crosses it once: 0.5
        Ray inside = new Ray(new Point3D(0, 0, -5), new Vector(0, 0, 1));
        assertEquals(0.5, transmittance(bvh, inside, 10, 0, bvh.newQuery()), 1e-12, "TC12: one crossing from inside");
    }
}
