package geometries;

import accel.ShadowFrustum;
import java.util.List;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.alignZero;
import static primitives.Util.isZero;
import static primitives.Util.requireNonNull;

/**
 * An infinite plane: a point on it and a unit normal.
 */
public class Plane extends Geometry {
    private final Point3D q0;
    private final Vector normal;
    private final double qx;
    private final double qy;
    private final double qz;
    private final double nx;
    private final double ny;
    private final double nz;

    /**
     * Creates a plane from a point on it and its normal.
     *
     * @param p0     a point on the plane
     * @param normal the normal (any length; the plane keeps a unit copy)
     */
    public Plane(Point3D p0, Vector normal) {
        this.q0 = requireNonNull(p0, "plane point");
        this.normal = requireNonNull(normal, "plane normal").normalized();
        this.qx = q0.getX();
        this.qy = q0.getY();
        this.qz = q0.getZ();
        this.nx = this.normal.getX();
        this.ny = this.normal.getY();
        this.nz = this.normal.getZ();
    }

    /**
     * Creates the plane through three points; the normal is (p2 − p1) × (p3 − p1), normalised.
     *
     * @param p1 first point
     * @param p2 second point
     * @param p3 third point
     * @throws IllegalArgumentException when two points coincide or all three are collinear
     */
    public Plane(Point3D p1, Point3D p2, Point3D p3) {
        this(requireNonNull(p1, "plane point p1"),
                normalThrough(p1, requireNonNull(p2, "plane point p2"), requireNonNull(p3, "plane point p3")));
    }

    /**
     * The unit normal of the plane through three points.
     *
     * @throws IllegalArgumentException when two points coincide or all three are collinear
     */
    static Vector normalThrough(Point3D p1, Point3D p2, Point3D p3) {
        if (p1.equals(p2) || p2.equals(p3) || p1.equals(p3))
            throw new IllegalArgumentException("plane points coincide: " + p1 + ", " + p2 + ", " + p3);
        Vector v1 = p2.subtract(p1);
        Vector v2 = p3.subtract(p1);
        double cx = v1.getY() * v2.getZ() - v1.getZ() * v2.getY();
        double cy = v1.getZ() * v2.getX() - v1.getX() * v2.getZ();
        double cz = v1.getX() * v2.getY() - v1.getY() * v2.getX();
        double crossLength = Math.sqrt(cx * cx + cy * cy + cz * cz);
        if (isZero(crossLength / (v1.length() * v2.length())))
            throw new IllegalArgumentException("plane points are collinear: " + p1 + ", " + p2 + ", " + p3);
        return new Vector(cx / crossLength, cy / crossLength, cz / crossLength);
    }

    /** {@return the point the plane was built from} */
    public Point3D getQ0() {
        return q0;
    }

    /** {@return the unit normal} */
    public Vector getNormal() {
        return normal;
    }

    @Override
    public Vector getNormal(Point3D point) {
        requireNonNull(point, "point");
        return normal;
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        return singleHit(ray, maxDistance);
    }

    @Override
    public double nearestHit(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
        double nv = alignZero(nx * dx + ny * dy + nz * dz);
        double nq = nx * (qx - ox) + ny * (qy - oy) + nz * (qz - oz);
        // t = nq / nv lies in (0, maxT] only if nq has the sign of nv and |nq| <= maxT·|nv|: divide only then
        if (nv == 0 || (nv > 0 ? !(nq > 0 && nq <= maxT * nv) : !(nq < 0 && nq >= maxT * nv)))
            return NO_HIT;
        return hitWithin(alignZero(nq / nv), maxT);
    }

    @Override
    int hitCount(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
        return nearestHit(ox, oy, oz, dx, dy, dz, maxT) < NO_HIT ? 1 : 0;
    }

    @Override
    public boolean mayMeet(ShadowFrustum frustum) {
        return frustum.meetsPlane(nx, ny, nz, qx, qy, qz);
    }

    @Override
    public String toString() {
        return "Plane{q0=" + q0 + ", normal=" + normal + "}";
    }
}
