package testutil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.ArrayList;
import java.util.List;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import geometries.Geometries;
import geometries.Intersectable.GeoPoint;
import geometries.Intersectable;
import geometries.Polygon;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * The brute-force answers the hierarchy's walks are compared with (every body's own query, by the
 * renderer's rule: polygons closed, see {@link #renderedIntersections}), and the assertions comparing them.
 */
public final class BruteForce {
    /** Not instantiable. */
    private BruteForce() {
    }

    /** Tolerance on the coordinates of a hit point. */
    public static final double POINT_DELTA = 1e-7;

    /** Two hits whose distances differ by less than this are a tie: either body is right. */
    public static final double TIE = 1e-9;

    /** Rays whose hit lies this close to the transmittance distance are not judged. */
    public static final double MARGIN = 1e-6;

    /** The renderer's transmittance cut-off. */
    public static final double MIN_K = 1e-3;


    /**
     * The brute-force closest hit: every intersection of the composite, the nearest kept.
     *
     * @param geometries the composite
     * @param ray        the ray
     * @return the nearest intersection, or null
     */
    public static GeoPoint reference(Intersectable geometries, Ray ray) {
        return ray.findClosestGeoPoint(renderedIntersections(geometries, ray, Double.POSITIVE_INFINITY));
    }

    /**
     * The brute-force intersections by the renderer's rule: every body's own query, except that
     * polygons are closed (the course's {@link Intersectable#findGeoIntersections} takes them as open).
     *
     * @param item the body or composite
     * @param ray  the ray
     * @param maxT the largest distance that counts
     * @return the intersections, or null when there is none
     */
    public static List<GeoPoint> renderedIntersections(Intersectable item, Ray ray, double maxT) {
        if (item instanceof Polygon polygon)
            return polygon.singleHit(ray, maxT);
        if (!(item instanceof Geometries composite))
            return item.findGeoIntersections(ray, maxT);
        List<GeoPoint> all = new ArrayList<>();
        for (Intersectable child : composite.getGeometries()) {
            List<GeoPoint> hits = renderedIntersections(child, ray, maxT);
            if (hits != null)
                all.addAll(hits);
        }
        return all.isEmpty() ? null : all;
    }

    /**
     * The brute-force transmittance: the product of the kT at every intersection up to a distance.
     *
     * @param geometries the composite
     * @param ray        the ray
     * @param maxT       the distance
     * @return the product (1 when nothing is crossed)
     */
    public static double referenceTransmittance(Intersectable geometries, Ray ray, double maxT) {
        List<GeoPoint> hits = renderedIntersections(geometries, ray, maxT);
        double product = 1;
        if (hits != null)
            for (GeoPoint hit : hits)
                product *= hit.geometry.getMaterial().getKt();
        return product;
    }

    /**
     * The hierarchy's transmittance along a ray.
     *
     * @param bvh   the hierarchy (or scan)
     * @param ray   the ray
     * @param maxT  the distance
     * @param minK  the cut-off
     * @param query the scratch space
     * @return the transmittance
     */
    public static double transmittance(BoundingVolumeHierarchy bvh, Ray ray, double maxT, double minK, Query query) {
        Point3D p = ray.getP0();
        Vector d = ray.getDir();
        return bvh.transmittance(query.setRay(p.getX(), p.getY(), p.getZ(), d.getX(), d.getY(), d.getZ(), maxT), minK);
    }

    /**
     * Asserts that a hit is the expected one: both null, or the same body (either of two bodies hit
     * at the same distance) at the same point.
     *
     * @param expected the brute-force hit
     * @param actual   the hit found
     * @param ray      the ray
     * @param message  the failure message
     */
    public static void assertSameHit(GeoPoint expected, GeoPoint actual, Ray ray, String message) {
        if (expected == null) {
            assertNull(actual, message + ": no hit expected for " + ray);
            return;
        }
        assertNotNull(actual, message + ": expected " + expected + " for " + ray);
        Point3D p0 = ray.getP0();
        if (actual.geometry != expected.geometry)
            assertEquals(p0.distance(expected.point), p0.distance(actual.point), TIE,
                    message + ": another body hit (not a tie) for " + ray + ": expected " + expected + ", got "
                            + actual);
        assertPoint(expected.point, actual.point, message + " for " + ray);
    }

    /**
     * Asserts a point's coordinates within {@link #POINT_DELTA}.
     *
     * @param expected the expected point
     * @param actual   the actual point
     * @param message  the failure message
     */
    public static void assertPoint(Point3D expected, Point3D actual, String message) {
        assertEquals(expected.getX(), actual.getX(), POINT_DELTA, message + " (x)");
        assertEquals(expected.getY(), actual.getY(), POINT_DELTA, message + " (y)");
        assertEquals(expected.getZ(), actual.getZ(), POINT_DELTA, message + " (z)");
    }

    /**
     * Asserts that the hierarchy, the linear scan and the brute force all find the expected hit.
     *
     * @param geometries the composite
     * @param ray        the ray
     * @param expected   the expected point, or null for no hit
     * @param tc         the test-case label
     */
    public static void assertHitEverywhere(Intersectable geometries, Ray ray, Point3D expected, String tc) {
        for (BoundingVolumeHierarchy bvh : List.of(BoundingVolumeHierarchy.build(geometries),
                BoundingVolumeHierarchy.scan(geometries))) {
            GeoPoint hit = bvh.closestHit(ray, bvh.newQuery());
            if (expected == null)
                assertNull(hit, tc + ": no hit expected for " + ray);
            else {
                assertNotNull(hit, tc + ": a hit expected for " + ray);
                assertPoint(expected, hit.point, tc + ": wrong hit point");
            }
            assertSameHit(reference(geometries, ray), hit, ray, tc + ": differs from the brute force");
        }
    }

    /**
     * Whether any intersection of a ray lies within {@link #MARGIN} of a distance.
     *
     * @param geometries the composite
     * @param ray        the ray
     * @param d          the distance
     * @return true when the answer would hang on rounding
     */
    public static boolean nearAHit(Intersectable geometries, Ray ray, double d) {
        List<GeoPoint> hits = renderedIntersections(geometries, ray, Double.POSITIVE_INFINITY);
        if (hits != null)
            for (GeoPoint hit : hits)
                if (Math.abs(ray.getP0().distance(hit.point) - d) < MARGIN)
                    return true;
        return false;
    }

    /**
     * The point of a hit, or null.
     *
     * @param hit the hit (may be null)
     * @return its point
     */
    public static Point3D pointOrNull(GeoPoint hit) {
        return hit == null ? null : hit.point;
    }
}
