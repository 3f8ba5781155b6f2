package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * Unit tests for {@link geometries.Intersectable} and its nested {@link geometries.Intersectable.GeoPoint}.
 */
class IntersectableTest {
    private final Sphere sphere = new Sphere(new Point3D(1, 0, 0), 1);

    /**
     * An intersectable that returns fixed GeoPoints whatever the ray, and records the distance it was asked for.
     */
    private static class Fixed extends Intersectable {
        private final List<GeoPoint> answer;
        private double askedDistance = Double.NaN;

        /**
         * @param answer what every query returns (null for a miss)
         */
        Fixed(List<GeoPoint> answer) {
            this.answer = answer;
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            askedDistance = maxDistance;
            return answer;
        }
    }

    /**
     * Test method for {@link geometries.Intersectable.GeoPoint#equals(java.lang.Object)}.
     */
    @Test
    void testGeoPointEquals() {
        Sphere twin = new Sphere(new Point3D(1, 0, 0), 1);
        GeoPoint gp = new GeoPoint(sphere, new Point3D(2, 0, 0));

        // ===== Equivalence Partitions Tests =====
        // TC01: same geometry and equal points (different objects): equal, with equal hash codes
        GeoPoint same = new GeoPoint(sphere, new Point3D(2, 0, 0));
        assertEquals(gp, same, "TC01: same geometry and point must be equal");
        assertEquals(gp.hashCode(), same.hashCode(), "TC01: equal GeoPoints must have equal hash codes");

        // TC02: same geometry, different point: not equal
        assertNotEquals(gp, new GeoPoint(sphere, new Point3D(1, 1, 0)), "TC02: different points must not be equal");

        // TC03: an equal-looking but distinct geometry object: not equal
        assertNotEquals(gp, new GeoPoint(twin, new Point3D(2, 0, 0)), "TC03: different geometry objects must not be equal");

        // TC04: not equal to null nor to an object of another type
        assertNotEquals(null, gp, "TC04: a GeoPoint must not equal null");
        assertNotEquals(gp, new Point3D(2, 0, 0), "TC04: a GeoPoint must not equal a bare point");

        // TC05: the public fields hold what was given
        assertTrue(gp.geometry == sphere, "TC05: wrong geometry field");
        assertEquals(new Point3D(2, 0, 0), gp.point, "TC05: wrong point field");

        // TC06: a null point is rejected (no bare NullPointerException later in equals)
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new GeoPoint(sphere, null), "TC06: a null point must throw"), "point", "TC06");

        // ===== Boundary Values Tests =====
        // TC11: a GeoPoint equals itself
        assertEquals(gp, gp, "TC11: a GeoPoint must equal itself");

        // TC12: points differing within the tolerance (1e-11): equal, with equal hash codes
        GeoPoint near = new GeoPoint(sphere, new Point3D(2 + 1e-11, 0, 0));
        assertEquals(gp, near, "TC12: points within the tolerance must be equal");
        assertEquals(gp.hashCode(), near.hashCode(), "TC12: equal GeoPoints must have equal hash codes");
    }

    /**
     * Test method for {@link geometries.Intersectable#findIntersections(primitives.Ray)}.
     */
    @Test
    void testFindIntersections() {
        Ray ray = new Ray(new Point3D(1, -2, 0), new Vector(0, 1, 0));

        // ===== Equivalence Partitions Tests =====
        // TC01: the points are those of the GeoPoints, in the same order ((1,-1,0) then (1,1,0))
        List<GeoPoint> geo = sphere.findGeoIntersections(ray);
        List<Point3D> points = sphere.findIntersections(ray);
        assertEquals(List.of(new Point3D(1, -1, 0), new Point3D(1, 1, 0)), points, "TC01: wrong points");
        assertEquals(geo.stream().map(gp -> gp.point).toList(), points, "TC01: points differ from the GeoPoints");

        // TC02: a miss gives null for both queries
        Ray miss = new Ray(new Point3D(-1, 0, 0), new Vector(1, 1, 0));
        assertNull(sphere.findIntersections(miss), "TC02: a miss must give null points");
        assertNull(sphere.findGeoIntersections(miss), "TC02: a miss must give null GeoPoints");

        // TC03: the mapping keeps order and every point of any intersectable (3 points)
        List<Point3D> fixedPoints = List.of(new Point3D(5, 0, 0), new Point3D(1, 2, 3), new Point3D(-1, -1, -1));
        Fixed fixed = new Fixed(fixedPoints.stream().map(p -> new GeoPoint(sphere, p)).toList());
        assertEquals(fixedPoints, fixed.findIntersections(ray), "TC03: wrong mapping of GeoPoints to points");

        // ===== Boundary Values Tests =====
        // TC11: the helper's null is passed on as null (not an empty list)
        assertNull(new Fixed(null).findIntersections(ray), "TC11: a null result must stay null");

        // TC12: a query without a limit asks the helper for an infinite distance
        fixed.findGeoIntersections(ray);
        assertEquals(Double.POSITIVE_INFINITY, fixed.askedDistance, "TC12: no limit must mean infinite distance");
    }

    /**
     * Test method for {@link geometries.Intersectable#findGeoIntersections(primitives.Ray, double)}: argument checks.
     */
    @Test
    void testFindGeoIntersectionsArguments() {
        Ray ray = new Ray(new Point3D(1, -2, 0), new Vector(0, 1, 0));
        Fixed fixed = new Fixed(null);

        // ===== Equivalence Partitions Tests =====
        // TC01: a positive distance is passed to the helper unchanged (7.5)
        fixed.findGeoIntersections(ray, 7.5);
        assertEquals(7.5, fixed.askedDistance, 1e-10, "TC01: the max distance must reach the helper");

        // TC02: a negative distance is rejected
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> sphere.findGeoIntersections(ray, -1), "TC02: negative max distance must throw"),
                "distance", "TC02");

        // TC03: NaN distance is rejected
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> sphere.findGeoIntersections(ray, Double.NaN), "TC03: NaN max distance must throw"),
                "distance", "TC03");

        // TC04: a null ray is rejected, by every query
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> sphere.findGeoIntersections(null, 1), "TC04: null ray must throw"), "ray", "TC04");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> sphere.findGeoIntersections(null), "TC04: null ray must throw"), "ray", "TC04");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> sphere.findIntersections(null), "TC04: null ray must throw"), "ray", "TC04");

        // ===== Boundary Values Tests =====
        // TC11: zero distance is rejected
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> sphere.findGeoIntersections(ray, 0), "TC11: zero max distance must throw"), "distance", "TC11");

        // TC12: negative infinity is rejected
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> sphere.findGeoIntersections(ray, Double.NEGATIVE_INFINITY), "TC12: -infinity must throw"),
                "distance", "TC12");

        // TC13: positive infinity is accepted and means no limit (2 points)
        assertEquals(2, sphere.findGeoIntersections(ray, Double.POSITIVE_INFINITY).size(),
                "TC13: infinite max distance must find both points");

        // TC14: the smallest positive distance is accepted (0 points within it: null)
        assertNull(sphere.findGeoIntersections(ray, Double.MIN_VALUE), "TC14: nothing lies within a tiny distance");
    }

    /** Test method for {@link Intersectable#hierarchy(int)} and {@link Intersectable#version()} of a single body. */
    @Test
    void testHierarchy() {
        Sphere sphere = new Sphere(Point3D.ZERO, 1);
        // ===== Equivalence Partitions Tests =====
        // TC01: a single body keeps one hierarchy (the same object twice), over itself: one bounded body
        accel.BoundingVolumeHierarchy bvh = sphere.hierarchy(1);
        org.junit.jupiter.api.Assertions.assertSame(bvh, sphere.hierarchy(2), "TC01: the hierarchy must be kept");
        assertEquals(1, bvh.getBoundedCount(), "TC01: the sphere is the one body");
        // TC02: a single body never changes: version 0; a hit names no face normal (null)
        assertEquals(0, sphere.version(), "TC02: wrong version");
        assertNull(new GeoPoint(sphere, new Point3D(0, 0, 1)).getFaceNormal(), "TC02: a sphere is its own face");

        // ===== Boundary Values Tests =====
        // TC11: 0 threads: refused, naming the threads
        assertMessage(assertThrows(IllegalArgumentException.class, () -> sphere.hierarchy(0), "TC11: 0 threads"),
                "threads", "TC11");
    }
}
