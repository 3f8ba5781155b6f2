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
    private final double cx;
    private final double cy;
    private final double cz;
    private final double radiusSquared;

    /**
     * Creates a sphere.
     *
     * @param center the centre
     * @param radius the radius, positive
     * @throws IllegalArgumentException when the centre is null or the radius is not positive
     */
    public Sphere(Point3D center, double radius) {
        this.center = requireNonNull(center, "sphere center");
        this.radius = requirePositive(radius, "sphere radius");
        this.cx = center.getX();
        this.cy = center.getY();
        this.cz = center.getZ();
        this.radiusSquared = radius * radius;
    }

    /**
     * Creates a sphere, radius first: the course's other order, the same sphere as
     * {@link #Sphere(Point3D, double)}.
     *
     * @param radius the radius, positive
     * @param center the centre
     * @throws IllegalArgumentException when the centre is null or the radius is not positive
     */
    public Sphere(double radius, Point3D center) {
        this(center, radius);
    }

    /** {@return the centre} */
    public Point3D getCenter() {
        return center;
    }

    /** {@return the radius} */
    public double getRadius() {
        return radius;
    }

    @Override
    public Vector getNormal(Point3D point) {
        return requireNonNull(point, "point").subtract(center).normalize();
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        Point3D p0 = ray.getP0();
        Vector dir = ray.getDir();
        return hitsAt(ray, root(p0.getX(), p0.getY(), p0.getZ(), dir.getX(), dir.getY(), dir.getZ(), -1),
                root(p0.getX(), p0.getY(), p0.getZ(), dir.getX(), dir.getY(), dir.getZ(), 1), maxDistance);
    }

    @Override
    public double nearestHit(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
        double t1 = root(ox, oy, oz, dx, dy, dz, -1);
        if (t1 > 0)
            return hitWithin(t1, maxT);
        if (Double.isNaN(t1)) // the ray misses the sphere
            return NO_HIT;
        return hitWithin(root(ox, oy, oz, dx, dy, dz, 1), maxT);
    }

    @Override
    int hitCount(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
        return (within(root(ox, oy, oz, dx, dy, dz, -1), maxT) ? 1 : 0)
                + (within(root(ox, oy, oz, dx, dy, dz, 1), maxT) ? 1 : 0);
    }

    @Override
    public boolean bounds(double[] box, int b) {
        box[b] = cx - radius;
        box[b + 1] = cy - radius;
        box[b + 2] = cz - radius;
        box[b + 3] = cx + radius;
        box[b + 4] = cy + radius;
        box[b + 5] = cz + radius;
        return true;
    }

    /**
     * One of the distances along a ray (origin o, unit direction d) where it crosses the sphere:
     * tm ∓ th, with tm the distance to the point nearest the centre and th the half chord.
     *
     * @param sign -1 for the nearer crossing, 1 for the farther
     * @return the distance (maybe negative), or NaN when the ray misses or only touches the sphere
     */
    private double root(double ox, double oy, double oz, double dx, double dy, double dz, double sign) {
        double ux = cx - ox;
        double uy = cy - oy;
        double uz = cz - oz;
        double tm = ux * dx + uy * dy + uz * dz;
        double thSquared = alignZero(radiusSquared - (ux * ux + uy * uy + uz * uz - tm * tm));
        return thSquared <= 0 ? Double.NaN : alignZero(tm + sign * Math.sqrt(thSquared));
    }

    @Override
    public String toString() {
        return "Sphere{center=" + center + ", radius=" + radius + "}";
    }
}
