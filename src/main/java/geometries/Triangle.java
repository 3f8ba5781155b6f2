package geometries;

import java.util.List;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/**
 * A triangle: a polygon of three vertices, intersected by the Möller–Trumbore test on precomputed
 * edges. Like every polygon it is closed: its edges and vertices are hit.
 */
public class Triangle extends Polygon {
    /** Tolerance on the barycentric coordinates, so that neighbours sharing an edge leave no seam. */
    private static final double BARYCENTRIC_TOLERANCE = 1e-9;

    private final double p1x;
    private final double p1y;
    private final double p1z;
    private final double e1x;
    private final double e1y;
    private final double e1z;
    private final double e2x;
    private final double e2y;
    private final double e2z;
    /** Below this |determinant| the ray is taken as parallel to the triangle. */
    private final double parallelLimit;

    /**
     * Creates a triangle.
     *
     * @param p1 first vertex
     * @param p2 second vertex
     * @param p3 third vertex
     * @throws IllegalArgumentException when vertices coincide or are collinear
     */
    public Triangle(Point3D p1, Point3D p2, Point3D p3) {
        super(p1, p2, p3);
        p1x = p1.getX();
        p1y = p1.getY();
        p1z = p1.getZ();
        e1x = p2.getX() - p1x;
        e1y = p2.getY() - p1y;
        e1z = p2.getZ() - p1z;
        e2x = p3.getX() - p1x;
        e2y = p3.getY() - p1y;
        e2z = p3.getZ() - p1z;
        parallelLimit = 1e-12 * Math.sqrt((e1x * e1x + e1y * e1y + e1z * e1z) * (e2x * e2x + e2y * e2y + e2z * e2z));
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        Vector dir = ray.getDir();
        double dx = dir.getX();
        double dy = dir.getY();
        double dz = dir.getZ();
        double px = dy * e2z - dz * e2y;
        double py = dz * e2x - dx * e2z;
        double pz = dx * e2y - dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        if (Math.abs(det) < parallelLimit)
            return null;
        double inv = 1.0 / det;
        Point3D p0 = ray.getP0();
        double tx = p0.getX() - p1x;
        double ty = p0.getY() - p1y;
        double tz = p0.getZ() - p1z;
        double u = (tx * px + ty * py + tz * pz) * inv;
        if (u < -BARYCENTRIC_TOLERANCE || u > 1 + BARYCENTRIC_TOLERANCE)
            return null;
        double qx = ty * e1z - tz * e1y;
        double qy = tz * e1x - tx * e1z;
        double qz = tx * e1y - ty * e1x;
        double v = (dx * qx + dy * qy + dz * qz) * inv;
        if (v < -BARYCENTRIC_TOLERANCE || u + v > 1 + BARYCENTRIC_TOLERANCE)
            return null;
        double t = primitives.Util.alignZero((e2x * qx + e2y * qy + e2z * qz) * inv);
        return t > 0 && t <= maxDistance ? List.of(new GeoPoint(this, ray.getPoint(t))) : null;
    }

    @Override
    public String toString() {
        return "Triangle" + vertices;
    }
}
