package geometries;

import primitives.Point3D;

import static primitives.Util.alignZero;

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
    double nearestHit(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
        double px = dy * e2z - dz * e2y;
        double py = dz * e2x - dx * e2z;
        double pz = dx * e2y - dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        if (Math.abs(det) < parallelLimit)
            return NO_HIT;
        double inv = 1.0 / det;
        double tx = ox - p1x;
        double ty = oy - p1y;
        double tz = oz - p1z;
        double u = (tx * px + ty * py + tz * pz) * inv;
        if (u < -BARYCENTRIC_TOLERANCE || u > 1 + BARYCENTRIC_TOLERANCE)
            return NO_HIT;
        double qx = ty * e1z - tz * e1y;
        double qy = tz * e1x - tx * e1z;
        double qz = tx * e1y - ty * e1x;
        double v = (dx * qx + dy * qy + dz * qz) * inv;
        if (v < -BARYCENTRIC_TOLERANCE || u + v > 1 + BARYCENTRIC_TOLERANCE)
            return NO_HIT;
        double t = alignZero((e2x * qx + e2y * qy + e2z * qz) * inv);
        return t > 0 && t <= maxT ? t : NO_HIT;
    }

    /**
     * The box around every point {@link #nearestHit} accepts: the triangle grown by the barycentric
     * tolerance τ, whose corners are p + τ·((p − q) + (p − r)) for each vertex p and the other two q, r.
     */
    @Override
    double[] bounds() {
        double[] box = new double[6];
        for (int k = 0; k < 3; ++k) {
            double a = coordinate(vertices.get(0), k);
            double b = coordinate(vertices.get(1), k);
            double c = coordinate(vertices.get(2), k);
            double ca = a + BARYCENTRIC_TOLERANCE * ((a - b) + (a - c));
            double cb = b + BARYCENTRIC_TOLERANCE * ((b - a) + (b - c));
            double cc = c + BARYCENTRIC_TOLERANCE * ((c - a) + (c - b));
            box[k] = Math.min(Math.min(a, Math.min(b, c)), Math.min(ca, Math.min(cb, cc)));
            box[3 + k] = Math.max(Math.max(a, Math.max(b, c)), Math.max(ca, Math.max(cb, cc)));
        }
        return box;
    }

    private static double coordinate(Point3D point, int axis) {
        return axis == 0 ? point.getX() : axis == 1 ? point.getY() : point.getZ();
    }

    @Override
    public String toString() {
        return "Triangle" + vertices;
    }
}
