package renderer;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.alignZero;

/**
 * The square that the spread rays of a glossy or blurry surface pass through: perpendicular to the
 * sharp ray (the mirror reflection, or the straight-through refraction), centred on it at unit
 * distance from the surface point, with a half-edge of the material's {@code kG} (or {@code kB}).
 * A sample point (u, v) of the unit square, as a {@link JitteredGrid} draws it, gives the ray from
 * the surface point through the square's point {@code r + h·((2u − 1)·a + (2v − 1)·b)}, where r is
 * the sharp ray's unit direction, h the half-edge and a, b two unit vectors perpendicular to r and to
 * each other.
 * <p>
 * A spread ray must leave the surface on the same side as the sharp ray: a reflected ray that would
 * go into the surface, or a refracted ray that would come back out of it, is replaced by the sharp
 * ray itself. So every sample keeps its weight, and near grazing angles the surface looks more like
 * a mirror, as real surfaces do.
 */
final class SpreadSquare {
    private final Point3D point;
    private final Ray sharpRay;
    private final Vector n;
    private final double nx;
    private final double ny;
    private final double nz;
    /** The side of the surface the rays must leave to: the sign of r·n. */
    private final double side;
    private final double rx;
    private final double ry;
    private final double rz;
    private final double ax;
    private final double ay;
    private final double az;
    private final double bx;
    private final double by;
    private final double bz;

    /**
     * Places the square around a sharp ray.
     *
     * @param point    the surface point the rays leave
     * @param sharpRay the sharp reflected or refracted ray from that point
     * @param n        the surface normal at the point
     * @param halfEdge the square's half-edge at unit distance: the material's kG or kB, in (0, 1]
     */
    SpreadSquare(Point3D point, Ray sharpRay, Vector n, double halfEdge) {
        this.point = point;
        this.sharpRay = sharpRay;
        this.n = n;
        Vector r = sharpRay.getDir();
        rx = r.getX();
        ry = r.getY();
        rz = r.getZ();
        nx = n.getX();
        ny = n.getY();
        nz = n.getZ();
        side = Math.signum(alignZero(rx * nx + ry * ny + rz * nz));
        // a: a unit vector orthogonal to r, scaled to the half-edge; b = r × a, as long
        Vector a = r.orthogonal();
        ax = a.getX() * halfEdge;
        ay = a.getY() * halfEdge;
        az = a.getZ() * halfEdge;
        bx = ry * az - rz * ay;
        by = rz * ax - rx * az;
        bz = rx * ay - ry * ax;
    }

    /**
     * The spread ray through a sample point of the square.
     *
     * @param u the sample point's first coordinate in the unit square
     * @param v the sample point's second coordinate in the unit square
     * @return the ray from the surface point through the square's point (u, v); the sharp ray when
     * that one would leave the surface on the other side
     */
    Ray ray(double u, double v) {
        double du = 2 * u - 1;
        double dv = 2 * v - 1;
        double dx = rx + ax * du + bx * dv;
        double dy = ry + ay * du + by * dv;
        double dz = rz + az * du + bz * dv;
        if (side == 0 || alignZero(dx * nx + dy * ny + dz * nz) * side <= 0)
            return sharpRay;
        return new Ray(point, new Vector(dx, dy, dz), n);
    }
}
