package geometries;

import java.util.List;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.alignZero;
import static primitives.Util.isZero;
import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * An infinite tube: the points at a fixed distance (the radius) from an axis line.
 */
public class Tube extends Geometry {
    /** The axis: a point on it and its unit direction. */
    protected final Ray axisRay;
    /** The radius. */
    protected final double radius;

    /**
     * Creates a tube.
     *
     * @param axisRay the axis
     * @param radius  the radius, positive
     * @throws IllegalArgumentException when the axis is null or the radius is not positive
     */
    public Tube(Ray axisRay, double radius) {
        this.axisRay = requireNonNull(axisRay, "tube axis ray");
        this.radius = requirePositive(radius, "tube radius");
    }

    /**
     * Creates a tube, radius first: the course's other order, the same tube as {@link #Tube(Ray, double)}.
     *
     * @param radius  the radius, positive
     * @param axisRay the axis
     * @throws IllegalArgumentException when the axis is null or the radius is not positive
     */
    public Tube(double radius, Ray axisRay) {
        this(axisRay, radius);
    }

    /** {@return the axis} */
    public Ray getAxisRay() {
        return axisRay;
    }

    /** {@return the radius} */
    public double getRadius() {
        return radius;
    }

    @Override
    public Vector getNormal(Point3D point) {
        requireNonNull(point, "point");
        Point3D p0 = axisRay.getP0();
        Vector dir = axisRay.getDir();
        double t = alignZero((point.getX() - p0.getX()) * dir.getX()
                + (point.getY() - p0.getY()) * dir.getY()
                + (point.getZ() - p0.getZ()) * dir.getZ());
        return point.subtract(axisRay.getPoint(t)).normalize();
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        double[] ts = sideDistances(ray);
        return ts == null ? null : hitsAt(ray, ts[0], ts[1], maxDistance);
    }

    /**
     * The two distances along a ray where its line crosses the infinite tube surface.
     *
     * @param ray the ray
     * @return {t1, t2} with t1 &lt; t2 (either may be negative), or null when the line is parallel
     *         to the axis, misses the tube or only touches it
     */
    double[] sideDistances(Ray ray) {
        Vector va = axisRay.getDir();
        Vector v = ray.getDir();
        Point3D pa = axisRay.getP0();
        Point3D p = ray.getP0();
        // the components of the direction and of the offset from the axis perpendicular to the axis
        double vva = v.dotProduct(va);
        double ax = v.getX() - vva * va.getX();
        double ay = v.getY() - vva * va.getY();
        double az = v.getZ() - vva * va.getZ();
        double a = ax * ax + ay * ay + az * az;
        if (isZero(a))
            return null;
        double dx = p.getX() - pa.getX();
        double dy = p.getY() - pa.getY();
        double dz = p.getZ() - pa.getZ();
        double dva = dx * va.getX() + dy * va.getY() + dz * va.getZ();
        double bx = dx - dva * va.getX();
        double by = dy - dva * va.getY();
        double bz = dz - dva * va.getZ();
        double halfB = ax * bx + ay * by + az * bz;
        double c = bx * bx + by * by + bz * bz - radius * radius;
        double discriminant = alignZero(halfB * halfB - a * c);
        if (discriminant <= 0)
            return null;
        double root = Math.sqrt(discriminant);
        return new double[] { alignZero((-halfB - root) / a), alignZero((-halfB + root) / a) };
    }

    @Override
    public String toString() {
        return "Tube{axis=" + axisRay + ", radius=" + radius + "}";
    }
}
