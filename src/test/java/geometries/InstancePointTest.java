package geometries;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestInstances.DELTA;
import static testutil.TestInstances.SIMILARITY;

import java.util.Random;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Transform;
import primitives.Vector;
import testutil.TestInstances;
import testutil.TestRandom;

/**
 * Unit tests for {@link InstancePoint}: a hit through an instance answers for the body hit, carried to
 * the world, as the hit on the body built in place does.
 */
class InstancePointTest {
    /** A smooth, textured half-cylinder-like strip: two triangles whose vertex normals lean apart. */
    private static TriangleMesh smoothStrip() {
        double s = Math.sqrt(0.5);
        return new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 1, 0.2, 0, 1, 0.2 }, new int[] { 0, 1, 2, 0, 2, 3 })
                .setNormals(new double[] { -s, 0, s, s, 0, s, s, 0, s, -s, 0, s })
                .setUVs(new double[] { 0, 0, 1, 0, 1, 1, 0, 1 });
    }

    /** Asserts two points are the same within the tolerance. */
    private static void assertNear(Point3D expected, Point3D actual, String message) {
        assertEquals(0, expected.distance(actual), DELTA, message + ": " + actual + " instead of " + expected);
    }

    /** Test method for {@link InstancePoint#getNormal()}, {@link InstancePoint#getUV()}, {@link InstancePoint#getShadowPoint(Vector)} and {@link InstancePoint#getFaceNormal()}. */
    @Test
    void testInstancePoint() {
        TriangleMesh strip = smoothStrip();
        Instance instance = new Instance(strip, SIMILARITY);
        TriangleMesh copy = TestInstances.inPlace(strip, SIMILARITY);
        Random rnd = new Random(7);
        int hits = 0;

        // ===== Equivalence Partitions Tests =====
        // TC01: random rays toward the placed strip from above it: the copy's normal, UV, face normal and
        // shadow point (for a random light direction), and the hit names the strip
        for (int i = 0; i < 300; ++i) {
            Point3D target = SIMILARITY.apply(new Point3D(rnd.nextDouble(), rnd.nextDouble(), 0.1));
            Point3D start = target.add(SIMILARITY.applyToNormal(new Vector(0, 0, 1)).scale(5))
                    .add(TestRandom.randomUnit(rnd));
            Ray ray = new Ray(start, target.subtract(start));
            GeoPoint expected = ray.findClosestGeoPoint(copy.findGeoIntersections(ray));
            GeoPoint actual = ray.findClosestGeoPoint(instance.findGeoIntersections(ray));
            if (expected == null)
                continue;
            ++hits;
            TestInstances.assertSameHit(expected, actual, "TC01: ray " + i);
            assertSame(strip, actual.geometry, "TC01: the hit must name the strip");
            assertArrayEquals(expected.getUV(), actual.getUV(), DELTA, "TC01: wrong UV, ray " + i);
            assertEquals(1, expected.getFaceNormal().dotProduct(actual.getFaceNormal()), DELTA,
                    "TC01: wrong face normal, ray " + i);
            Vector l = new Vector(0.3, -0.2, -1).add(TestRandom.randomUnit(rnd).scale(0.3)).normalize();
            assertNear(expected.getShadowPoint(l), actual.getShadowPoint(l), "TC01: wrong shadow point, ray " + i);
        }
        assertTrue(hits > 200, "TC01: too few rays hit the strip: " + hits);

        // ===== Boundary Values Tests =====
        // TC11: on a flat body the shadow point is the hit point itself (the same object) and there is no face normal
        Instance ball = new Instance(new Sphere(Point3D.ZERO, 1), Transform.translate(new Vector(0, 0, -5)));
        GeoPoint top = ball.findGeoIntersections(new Ray(Point3D.ZERO, new Vector(0, 0, -1))).get(0);
        assertSame(top.point, top.getShadowPoint(new Vector(0, 0, -1)), "TC11: no lift on a sphere");
        assertNull(top.getFaceNormal(), "TC11: a sphere is its own face");
        // TC12: its text names the inner hit and the world point
        assertTrue(top.toString().contains("carried to") && top.toString().contains("Sphere"), "TC12: wrong text " + top);
    }
}
