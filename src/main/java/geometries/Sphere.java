package geometries;

import accel.RayState;

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
    protected boolean hasUV() {
        return true;
    }

    /**
     * {@inheritDoc} Longitude and latitude, each as a fraction of its whole: u = 0.5 + φ / 2π with φ the
     * angle around the y axis from the +z side (φ = atan2(x, z) of the point seen from the centre), so that
     * u runs from 0 to 1 around the sphere with 0.5 on its +z side; v = 0.5 + θ / π with θ the latitude
     * (asin(y / radius)), 0 at the bottom pole and 1 at the top.
     */
    @Override
    public double[] getUV(Point3D point) {
        double x = point.getX() - cx;
        double y = point.getY() - cy;
        double z = point.getZ() - cz;
        double sin = Math.max(-1, Math.min(1, y / Math.sqrt(x * x + y * y + z * z)));
        return new double[] { 0.5 + Math.atan2(x, z) / (2 * Math.PI), 0.5 + Math.asin(sin) / Math.PI };
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        RayState numbers = toRayState(ray, maxDistance);
        return hitsAt(ray, root(numbers, -1), root(numbers, 1), maxDistance);
    }

    @Override
    public double nearestHit(RayState ray) {
        double t1 = root(ray, -1);
        if (t1 > 0)
            return hitWithin(t1, ray.maxT());
        if (Double.isNaN(t1)) // the ray misses the sphere
            return NO_HIT;
        return hitWithin(root(ray, 1), ray.maxT());
    }

    @Override
    int hitCount(RayState ray) {
        return (within(root(ray, -1), ray.maxT()) ? 1 : 0) + (within(root(ray, 1), ray.maxT()) ? 1 : 0);
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
    private double root(RayState ray, double sign) {
        double ux = cx - ray.ox();
        double uy = cy - ray.oy();
        double uz = cz - ray.oz();
        double tm = ux * ray.dx() + uy * ray.dy() + uz * ray.dz();
        double thSquared = alignZero(radiusSquared - (ux * ux + uy * uy + uz * uz - tm * tm));
        return thSquared <= 0 ? Double.NaN : alignZero(tm + sign * Math.sqrt(thSquared));
    }

    @Override
    public String toString() {
        return "Sphere{center=" + center + ", radius=" + radius + "}";
    }
}
