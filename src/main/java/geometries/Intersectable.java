package geometries;

import java.util.List;

import accel.BoundingVolumeHierarchy;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.requireNonNull;

/**
 * Anything a ray can hit. Every query returns null, not an empty list, when the ray misses: the
 * course's tests assert exactly that. Only points strictly ahead of the ray's start (t &gt; 0) count.
 */
public abstract class Intersectable {
    /** The hierarchy over the object's bodies, as they were when it was built (see {@link #hierarchy}). */
    private BoundingVolumeHierarchy hierarchy;

    /** Creates an intersectable object. */
    protected Intersectable() {
    }

    /**
     * A number that grows whenever a body is added inside the object; a hierarchy built over the
     * object compares it to know whether it is out of date. A single body never changes: 0.
     *
     * @return the version of the object's contents
     */
    public long version() {
        return 0;
    }

    /**
     * The bounding volume hierarchy over the object's bodies, kept with them so that every ray tracer
     * of a scene and every {@link Instance} of a body share one (a course test makes a new tracer for
     * every picture; a thousand instances of a mesh walk one tree): built on the first call, and again
     * only when bodies were added since (see {@link #version()}).
     *
     * @param threads how many threads may share a build, 1 or more
     * @return the hierarchy over the bodies as they are now
     * @throws IllegalArgumentException when threads is below 1
     */
    public synchronized BoundingVolumeHierarchy hierarchy(int threads) {
        if (threads < 1)
            throw new IllegalArgumentException("threads must be 1 or more, got " + threads);
        if (hierarchy == null || !hierarchy.isBuiltFrom(this))
            hierarchy = BoundingVolumeHierarchy.build(this, threads);
        return hierarchy;
    }

    /**
     * An intersection point together with the geometry it lies on.
     */
    public static class GeoPoint {
        /** The geometry hit. */
        public final Geometry geometry;
        /** The point hit. */
        public final Point3D point;

        /**
         * Pairs a geometry with a point on it.
         *
         * @param geometry the geometry
         * @param point    the point on it
         * @throws IllegalArgumentException when the point is null
         */
        public GeoPoint(Geometry geometry, Point3D point) {
            this.geometry = geometry;
            this.point = requireNonNull(point, "intersection point");
        }

        /**
         * The unit normal of the surface at the point, for shading: the geometry's normal there. A
         * body made of many faces ({@link TriangleMesh}) answers for the face that was hit.
         *
         * @return the outward unit normal at the point
         */
        public Vector getNormal() {
            return geometry.getNormal(point);
        }

        /**
         * The surface coordinates of the point, where the body's texture is looked up: the geometry's
         * there ({@link Geometry#getUV}). A {@link TriangleMesh} answers with the UVs of the triangle hit.
         *
         * @return {u, v}
         * @throws UnsupportedOperationException when the body has no surface coordinates
         */
        public double[] getUV() {
            return geometry.getUV(point);
        }

        /**
         * The point the shadow rays toward a light leave from: the hit point itself, except on a smooth
         * {@link TriangleMesh}, whose flat triangles lie below the surface their normals describe.
         *
         * @param l the unit direction from the light to the point
         * @return the point shadow rays start from (before they move {@link primitives.Ray#DELTA} off the surface)
         */
        public Point3D getShadowPoint(Vector l) {
            return point;
        }

        /**
         * The normal of the flat face under a smooth surface at the point, which tells which side of the
         * face a ray comes from: on a smooth {@link TriangleMesh}, the normal of the triangle hit.
         *
         * @return the face's unit normal, or null where the surface is its own face (its normal tells the side)
         */
        public Vector getFaceNormal() {
            return null;
        }

        /** Equal when they name the same geometry object and equal points. */
        @Override
        public boolean equals(Object obj) {
            if (this == obj)
                return true;
            return obj instanceof GeoPoint other && geometry == other.geometry && point.equals(other.point);
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(geometry) * 31 + point.hashCode();
        }

        @Override
        public String toString() {
            return "GeoPoint{" + geometry + " at " + point + "}";
        }
    }

    /**
     * Finds the points where a ray hits this object.
     *
     * @param ray the ray
     * @return the points, nearest first for a single body (a {@link Geometries}' body by body), or null when
     *         the ray misses
     */
    public List<Point3D> findIntersections(Ray ray) {
        List<GeoPoint> geoPoints = findGeoIntersections(ray);
        return geoPoints == null ? null : geoPoints.stream().map(gp -> gp.point).toList();
    }

    /**
     * Finds the points where a ray hits this object, with the geometry hit at each.
     *
     * @param ray the ray
     * @return the intersections, nearest first for a single body (a {@link Geometries}' body by body), or
     *         null when the ray misses
     */
    public final List<GeoPoint> findGeoIntersections(Ray ray) {
        return findGeoIntersections(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * Finds the points where a ray hits this object no farther than a distance from its start.
     *
     * @param ray         the ray
     * @param maxDistance the largest distance from the ray's start that counts (positive)
     * @return the intersections, nearest first for a single body (a {@link Geometries}' body by body), or
     *         null when there is none within the distance
     */
    public final List<GeoPoint> findGeoIntersections(Ray ray, double maxDistance) {
        requireNonNull(ray, "ray");
        if (Double.isNaN(maxDistance) || maxDistance <= 0)
            throw new IllegalArgumentException("maximum intersection distance must be positive, got " + maxDistance);
        return findGeoIntersectionsHelper(ray, maxDistance);
    }

    /**
     * The intersection search each kind of object implements; arguments are already checked.
     *
     * @param ray         the ray
     * @param maxDistance the largest distance that counts
     * @return the intersections, or null when there is none
     */
    protected abstract List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance);
}
