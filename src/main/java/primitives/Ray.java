package primitives;

import java.util.List;

import geometries.Intersectable.GeoPoint;

import static primitives.Util.alignZero;
import static primitives.Util.requireNonNull;

/**
 * A half-line: a start point {@code p0} and a unit direction.
 */
public class Ray {
    /** How far a secondary ray's head moves off the surface, to avoid hitting that surface again. */
    public static final double DELTA = 0.1;

    private final Point3D p0;
    private final Vector dir;

    /**
     * Creates a ray; it keeps its own unit copy of the direction.
     *
     * @param p0  the start point
     * @param dir the direction (any length)
     */
    public Ray(Point3D p0, Vector dir) {
        this.p0 = requireNonNull(p0, "ray start point");
        this.dir = requireNonNull(dir, "ray direction").normalized();
    }

    /**
     * Creates a secondary ray from a surface point: the head moves the distance {@link #DELTA} along
     * the normal (whatever the normal's length), toward the side of the surface the direction points
     * to; it stays put when the direction is orthogonal to the normal.
     *
     * @param head      the surface point
     * @param direction the ray's direction
     * @param normal    the surface normal at the point
     */
    public Ray(Point3D head, Vector direction, Vector normal) {
        requireNonNull(head, "ray start point");
        requireNonNull(direction, "ray direction");
        requireNonNull(normal, "surface normal");
        double nv = alignZero(normal.dotProduct(direction));
        this.p0 = nv == 0 ? head : head.add(normal.scale((nv > 0 ? DELTA : -DELTA) / normal.length()));
        this.dir = direction.normalized();
    }

    /** {@return the start point} */
    public Point3D getP0() {
        return p0;
    }

    /** {@return the unit direction} */
    public Vector getDir() {
        return dir;
    }

    /**
     * The point at a distance along the ray.
     *
     * @param t the distance from the start point
     * @return p0 + t·dir (p0 itself when t is zero)
     */
    public Point3D getPoint(double t) {
        return new Point3D(p0.x + t * dir.x, p0.y + t * dir.y, p0.z + t * dir.z);
    }

    /**
     * The point of a list nearest to the ray's start.
     *
     * @param points the candidates (may be null or empty)
     * @return the nearest point, or null when there is none
     */
    public Point3D findClosestPoint(List<Point3D> points) {
        if (points == null)
            return null;
        Point3D closest = null;
        double best = Double.POSITIVE_INFINITY;
        for (Point3D point : points) {
            double d = p0.distanceSquared(point);
            if (d < best) {
                best = d;
                closest = point;
            }
        }
        return closest;
    }

    /**
     * The intersection of a list nearest to the ray's start.
     *
     * @param geoPoints the candidates (may be null or empty)
     * @return the nearest one, or null when there is none
     */
    public GeoPoint findClosestGeoPoint(List<GeoPoint> geoPoints) {
        if (geoPoints == null)
            return null;
        GeoPoint closest = null;
        double best = Double.POSITIVE_INFINITY;
        for (GeoPoint geoPoint : geoPoints) {
            double d = p0.distanceSquared(geoPoint.point);
            if (d < best) {
                best = d;
                closest = geoPoint;
            }
        }
        return closest;
    }

    @Override
    public boolean equals(Object obj) {
        if (this == obj)
            return true;
        return obj instanceof Ray other && p0.equals(other.p0) && dir.equals(other.dir);
    }

    @Override
    public int hashCode() {
        return p0.hashCode() * 31 + dir.hashCode();
    }

    @Override
    public String toString() {
        return "Ray{" + p0 + " " + dir + "}";
    }
}
