package geometries;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.alignZero;
import static primitives.Util.isZero;
import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * A finite cylinder closed by two caps: the axis ray's start is the centre of the bottom cap, and
 * the top cap lies {@code height} along the axis direction.
 */
public class Cylinder extends Tube {
    /** How far past radius² a squared distance may be and still be on a cap (isZero's tolerance). */
    private static final double CAP_TOLERANCE = 1e-10;

    private final double height;

    /**
     * Creates a cylinder.
     *
     * @param axisRay the axis; its start is the centre of the bottom cap
     * @param radius  the radius, positive
     * @param height  the height, positive
     * @throws IllegalArgumentException when the axis is null or the radius or height is not positive
     */
    public Cylinder(Ray axisRay, double radius, double height) {
        super(axisRay, radius);
        this.height = requirePositive(height, "cylinder height");
    }

    /**
     * Creates a cylinder, radius first: the course's other order, the same cylinder as
     * {@link #Cylinder(Ray, double, double)}.
     *
     * @param radius  the radius, positive
     * @param axisRay the axis; its start is the centre of the bottom cap
     * @param height  the height, positive
     * @throws IllegalArgumentException when the axis is null or the radius or height is not positive
     */
    public Cylinder(double radius, Ray axisRay, double height) {
        this(axisRay, radius, height);
    }

    /** {@return the height} */
    public double getHeight() {
        return height;
    }

    /**
     * The box around both caps: along each axis a cap reaches radius·sqrt(1 − a²) from its centre.
     * The cap test accepts squared distances up to radius² + 1e-10 (the tolerance of
     * {@link primitives.Util#isZero}), so the radius taken is sqrt(radius² + 1e-10).
     */
    @Override
    public boolean bounds(double[] box, int b) {
        Point3D bottom = getAxisRay().getP0();
        Point3D top = getAxisRay().getPoint(height);
        Vector a = getAxisRay().getDir();
        double[] axis = { a.getX(), a.getY(), a.getZ() };
        double[] from = { bottom.getX(), bottom.getY(), bottom.getZ() };
        double[] to = { top.getX(), top.getY(), top.getZ() };
        double capRadius = Math.sqrt(getRadius() * getRadius() + CAP_TOLERANCE);
        for (int i = 0; i < 3; ++i) {
            double reach = capRadius * Math.sqrt(Math.max(0, 1 - axis[i] * axis[i]));
            box[b + i] = Math.min(from[i], to[i]) - reach;
            box[b + 3 + i] = Math.max(from[i], to[i]) + reach;
        }
        return true;
    }

    @Override
    public Vector getNormal(Point3D point) {
        requireNonNull(point, "point");
        Vector va = axisRay.getDir();
        Point3D p0 = axisRay.getP0();
        double s = (point.getX() - p0.getX()) * va.getX()
                + (point.getY() - p0.getY()) * va.getY()
                + (point.getZ() - p0.getZ()) * va.getZ();
        if (isZero(s))
            return va.scale(-1);
        if (isZero(s - height))
            return va;
        return super.getNormal(point);
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        List<Double> ts = new ArrayList<>(2);
        double[] side = sideDistances(ray);
        if (side != null)
            for (double t : side)
                if (within(t, maxDistance) && isBetweenCaps(ray, t))
                    ts.add(t);
        addCapHit(ray, 0, maxDistance, ts);
        addCapHit(ray, height, maxDistance, ts);
        if (ts.isEmpty())
            return null;
        ts.sort(Comparator.naturalOrder());
        List<GeoPoint> result = new ArrayList<>(ts.size());
        for (double t : ts)
            result.add(new GeoPoint(this, ray.getPoint(t)));
        return result;
    }

    /** The height along the axis of the point at distance t on a ray. */
    private double heightAt(Ray ray, double t) {
        Vector va = axisRay.getDir();
        Point3D pa = axisRay.getP0();
        Point3D p = ray.getP0();
        Vector v = ray.getDir();
        return (p.getX() + t * v.getX() - pa.getX()) * va.getX()
                + (p.getY() + t * v.getY() - pa.getY()) * va.getY()
                + (p.getZ() + t * v.getZ() - pa.getZ()) * va.getZ();
    }

    /** Strictly between the caps: a point on the rim belongs to the cap. */
    private boolean isBetweenCaps(Ray ray, double t) {
        double s = heightAt(ray, t);
        return alignZero(s) > 0 && alignZero(s - height) < 0;
    }

    /**
     * Adds the distance to the cap at a height along the axis, when the ray crosses the cap's disc
     * (rim included) within the distance limit.
     */
    private void addCapHit(Ray ray, double capHeight, double maxDistance, List<Double> ts) {
        Vector va = axisRay.getDir();
        double vva = alignZero(ray.getDir().dotProduct(va));
        if (vva == 0)
            return;
        double t = alignZero((capHeight - heightAt(ray, 0)) / vva);
        if (!within(t, maxDistance))
            return;
        Point3D center = capHeight == 0 ? axisRay.getP0() : axisRay.getPoint(capHeight);
        if (alignZero(ray.getPoint(t).distanceSquared(center) - radius * radius) <= 0)
            ts.add(t);
    }

    @Override
    public String toString() {
        return "Cylinder{axis=" + axisRay + ", radius=" + radius + ", height=" + height + "}";
    }
}
