package geometries;

import java.util.List;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.alignZero;
import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * A sphere: a centre and a radius.
 */
public class Sphere extends Geometry {
    private final Point3D center;
    private final double radius;

    /**
     * Creates a sphere.
     *
     * @param center the centre
     * @param radius the radius, positive
     */
    public Sphere(Point3D center, double radius) {
        this.center = requireNonNull(center, "sphere center");
        this.radius = requirePositive(radius, "sphere radius");
    }

    /** @return the centre */
    public Point3D getCenter() {
        return center;
    }

    /** @return the radius */
    public double getRadius() {
        return radius;
    }

    @Override
    public Vector getNormal(Point3D point) {
        return point.subtract(center).normalize();
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        Point3D p0 = ray.getP0();
        Vector dir = ray.getDir();
        double ux = center.getX() - p0.getX();
        double uy = center.getY() - p0.getY();
        double uz = center.getZ() - p0.getZ();
        double tm = ux * dir.getX() + uy * dir.getY() + uz * dir.getZ();
        double dSquared = ux * ux + uy * uy + uz * uz - tm * tm;
        double thSquared = alignZero(radius * radius - dSquared);
        if (thSquared <= 0)
            return null; // the ray misses or only touches the sphere
        double th = Math.sqrt(thSquared);
        double t1 = alignZero(tm - th);
        double t2 = alignZero(tm + th);
        boolean hit1 = t1 > 0 && t1 <= maxDistance;
        boolean hit2 = t2 > 0 && t2 <= maxDistance;
        if (hit1 && hit2)
            return List.of(new GeoPoint(this, ray.getPoint(t1)), new GeoPoint(this, ray.getPoint(t2)));
        if (hit1)
            return List.of(new GeoPoint(this, ray.getPoint(t1)));
        if (hit2)
            return List.of(new GeoPoint(this, ray.getPoint(t2)));
        return null;
    }

    @Override
    public String toString() {
        return "Sphere{center=" + center + ", radius=" + radius + "}";
    }
}
