package geometries;

import accel.RayState;
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
    protected boolean hasUV() {
        return true;
    }

    /**
     * {@inheritDoc} The point's position in the plane, in scene units, from q0 along two unit axes of the
     * plane: u along the coordinate axis most across the normal (x, y or z, the first of equals),
     * projected onto the plane; v along normal × u. A floor facing +y has u along +x and v along −z.
     */
    @Override
    public double[] getUV(Point3D point) {
        // the coordinate axis most across the normal, minus its part along the normal
        double[] u = nx * nx <= ny * ny && nx * nx <= nz * nz ? new double[] { 1 - nx * nx, -nx * ny, -nx * nz }
                : ny * ny <= nz * nz ? new double[] { -ny * nx, 1 - ny * ny, -ny * nz }
                : new double[] { -nz * nx, -nz * ny, 1 - nz * nz };
        double length = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (int k = 0; k < 3; ++k)
            u[k] /= length;
        return planeUV(point, q0, u, normal);
    }

    /**
     * The coordinates of a point in a plane from an origin in it, along a unit u axis of the plane and
     * along normal × u.
     *
     * @param point  the point
     * @param origin the origin of the coordinates
     * @param u      the unit u axis, in the plane: x, y, z
     * @param normal the plane's unit normal
     * @return {u, v}
     */
    static double[] planeUV(Point3D point, Point3D origin, double[] u, Vector normal) {
        double dx = point.getX() - origin.getX();
        double dy = point.getY() - origin.getY();
        double dz = point.getZ() - origin.getZ();
        double vx = normal.getY() * u[2] - normal.getZ() * u[1];
        double vy = normal.getZ() * u[0] - normal.getX() * u[2];
        double vz = normal.getX() * u[1] - normal.getY() * u[0];
        return new double[] { dx * u[0] + dy * u[1] + dz * u[2], dx * vx + dy * vy + dz * vz };
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        return singleHit(ray, maxDistance);
    }

    @Override
    public double nearestHit(RayState ray) {
        double maxT = ray.maxT();
        double nv = alignZero(nx * ray.dx() + ny * ray.dy() + nz * ray.dz());
        double nq = nx * (qx - ray.ox()) + ny * (qy - ray.oy()) + nz * (qz - ray.oz());
        // t = nq / nv lies in (0, maxT] only if nq has the sign of nv and |nq| <= maxT·|nv|: divide only then
        if (nv == 0 || (nv > 0 ? !(nq > 0 && nq <= maxT * nv) : !(nq < 0 && nq >= maxT * nv)))
            return NO_HIT;
        return hitWithin(alignZero(nq / nv), maxT);
    }

    @Override
    int hitCount(RayState ray) {
        return nearestHit(ray) < NO_HIT ? 1 : 0;
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
