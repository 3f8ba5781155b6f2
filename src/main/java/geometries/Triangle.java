package geometries;

import accel.RayState;
import accel.ShadowFrustum;
import primitives.Point3D;

import static primitives.Util.alignZero;

/**
 * A triangle: a polygon of three vertices. Like every {@link Polygon} it has two edge rules: the
 * course's queries ({@link #findIntersections}, {@link #findGeoIntersections}) take it as open (a ray
 * through an edge, a vertex or an edge's continuation misses), and the renderer's path takes it as
 * closed, by the Möller–Trumbore test on precomputed edges, so that triangles sharing an edge leave no
 * seam.
 */
public class Triangle extends Polygon {
    /** Tolerance on the barycentric coordinates, so that neighbours sharing an edge leave no seam. */
    public static final double BARYCENTRIC_TOLERANCE = 1e-9;

    /** The |determinant| of the intersection test below which a ray is taken as parallel to the triangle. */
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
        double[] v = vertexCoordinates;
        parallelLimit = parallelLimit(v[3] - v[0], v[4] - v[1], v[5] - v[2], v[6] - v[0], v[7] - v[1], v[8] - v[2]);
    }

    /**
     * The |determinant| of the intersection test below which a ray is taken as parallel to a
     * triangle: a tiny fraction of the product of its edges' lengths.
     *
     * @param e1x the first edge p2 − p1, x
     * @param e1y the first edge, y
     * @param e1z the first edge, z
     * @param e2x the second edge p3 − p1, x
     * @param e2y the second edge, y
     * @param e2z the second edge, z
     * @return the limit
     */
    public static double parallelLimit(double e1x, double e1y, double e1z, double e2x, double e2y, double e2z) {
        return 1e-12 * Math.sqrt((e1x * e1x + e1y * e1y + e1z * e1z) * (e2x * e2x + e2y * e2y + e2z * e2z));
    }

    /** The renderer's test ({@link #intersect}) on the triangle's data, written into the ray's scratch space. */
    @Override
    public double nearestHit(RayState ray) {
        double[] data = ray.triangleScratch();
        writeData(vertexCoordinates, 0, 3, 6, parallelLimit, data, 0);
        return intersect(ray, data, 0, parallelLimit);
    }

    /**
     * Writes a triangle's data, the numbers of {@link #intersect} and {@link #project}: its first
     * vertex p1, its edges p2 − p1 and p3 − p1, and its parallel limit.
     *
     * @param vertices      the vertices' coordinates, three doubles each
     * @param p1            where the first vertex's x lies in vertices
     * @param p2            where the second vertex's x lies
     * @param p3            where the third vertex's x lies
     * @param parallelLimit the triangle's {@link #parallelLimit}
     * @param target        the array
     * @param offset        where the {@value TriangleMesh#TRIANGLE_DATA} numbers go
     */
    public static void writeData(double[] vertices, int p1, int p2, int p3, double parallelLimit, double[] target,
                                 int offset) {
        for (int k = 0; k < 3; ++k) {
            target[offset + k] = vertices[p1 + k];
            target[offset + 3 + k] = vertices[p2 + k] - vertices[p1 + k];
            target[offset + 6 + k] = vertices[p3 + k] - vertices[p1 + k];
        }
        target[offset + TriangleMesh.PARALLEL_LIMIT] = parallelLimit;
    }

    /** The number of doubles {@link #project} writes. */
    public static final int PROJECTION = 6;

    /**
     * Projects a point onto a triangle's plane: the barycentric coordinates u (along e1) and v (along
     * e2) of its foot, the point's signed distance from the plane and the plane's unit normal, in
     * that order.
     *
     * @param data   a triangle's data (p1, e1 = p2 − p1, e2 = p3 − p1, ...), as {@link TriangleMesh#triangleData} writes them
     * @param x      the point, x
     * @param y      the point, y
     * @param z      the point, z
     * @param target where the {@value #PROJECTION} numbers go
     */
    public static void project(double[] data, double x, double y, double z, double[] target) {
        double e1x = data[3];
        double e1y = data[4];
        double e1z = data[5];
        double e2x = data[6];
        double e2y = data[7];
        double e2z = data[8];
        double wx = x - data[0];
        double wy = y - data[1];
        double wz = z - data[2];
        double d11 = e1x * e1x + e1y * e1y + e1z * e1z;
        double d12 = e1x * e2x + e1y * e2y + e1z * e2z;
        double d22 = e2x * e2x + e2y * e2y + e2z * e2z;
        double w1 = wx * e1x + wy * e1y + wz * e1z;
        double w2 = wx * e2x + wy * e2y + wz * e2z;
        double denominator = d11 * d22 - d12 * d12;
        double nx = e1y * e2z - e1z * e2y;
        double ny = e1z * e2x - e1x * e2z;
        double nz = e1x * e2y - e1y * e2x;
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        target[0] = (d22 * w1 - d12 * w2) / denominator;
        target[1] = (d11 * w2 - d12 * w1) / denominator;
        target[2] = (wx * nx + wy * ny + wz * nz) / length;
        target[3] = nx / length;
        target[4] = ny / length;
        target[5] = nz / length;
    }

    /**
     * The Möller–Trumbore test of a ray (origin o, unit direction d) against a triangle given by its
     * first vertex p1 and its edges e1 = p2 − p1 and e2 = p3 − p1: closed, its edges and vertices hit
     * within a barycentric tolerance. Every triangle of the renderer's path, a {@link Triangle} or one
     * of a {@link TriangleMesh}, is tested here, on the numbers {@link TriangleMesh#triangleData}
     * writes, so the same triangle gets the same answer whoever holds it. The kernel is 322 bytes of
     * bytecode, under the JIT's limit for inlining hot methods (325), so each test is compiled into its
     * caller's loop: hence the ray as the first parameter (its seven reads take the one-byte load) and
     * the barycentric tests folded into one comparison.
     *
     * @param ray           the ray: origin, unit direction and the largest distance that counts
     * @param data          the triangle's data: p1, e1 and e2, three doubles each
     * @param at            where p1's x lies in data
     * @param parallelLimit the |determinant| below which the ray is taken as parallel, see
     *                      {@link #parallelLimit}
     * @return the distance t in (0, maxT], or {@link #NO_HIT} when the ray misses
     */
    public static double intersect(RayState ray, double[] data, int at, double parallelLimit) {
        double e1x = data[at + 3];
        double e1y = data[at + 4];
        double e1z = data[at + 5];
        double e2x = data[at + 6];
        double e2y = data[at + 7];
        double e2z = data[at + 8];
        double dx = ray.dx();
        double dy = ray.dy();
        double dz = ray.dz();
        double px = dy * e2z - dz * e2y;
        double py = dz * e2x - dx * e2z;
        double pz = dx * e2y - dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        double inv = 1.0 / det;
        double tx = ray.ox() - data[at];
        double ty = ray.oy() - data[at + 1];
        double tz = ray.oz() - data[at + 2];
        double u = (tx * px + ty * py + tz * pz) * inv;
        double qx = ty * e1z - tz * e1y;
        double qy = tz * e1x - tx * e1z;
        double qz = tx * e1y - ty * e1x;
        double v = (dx * qx + dy * qy + dz * qz) * inv;
        // A parallel ray is rare, a predictable branch. The four barycentric tests (u, v ≥ −τ and
        // u, u + v ≤ 1 + τ), hard to predict, are one comparison: for finite a and b, a − b > 0 exactly
        // when a > b (IEEE subtraction keeps the sign), so the largest of the margins decides.
        if (Math.abs(det) < parallelLimit || Math.max(-BARYCENTRIC_TOLERANCE - Math.min(u, v),
                Math.max(u, u + v) - (1 + BARYCENTRIC_TOLERANCE)) > 0)
            return NO_HIT;
        return hitWithin(alignZero((e2x * qx + e2y * qy + e2z * qz) * inv), ray.maxT());
    }

    /**
     * A triangle can meet a bundle only when it is not outside a face of the bundle's pyramid nor
     * behind the rays' starts ({@link ShadowFrustum#meetsTriangle}) and its plane meets the pyramid.
     */
    @Override
    public boolean mayMeet(ShadowFrustum frustum) {
        return frustum.meetsTriangle(vertexCoordinates, 0, 3, 6) && super.mayMeet(frustum);
    }

    /**
     * The box around every point {@link #nearestHit} accepts: the triangle grown by the barycentric
     * tolerance τ, whose corners are p + τ·((p − q) + (p − r)) for each vertex p and the other two q, r.
     */
    @Override
    public boolean bounds(double[] box, int b) {
        bounds(vertexCoordinates, 0, 3, 6, box, b);
        return true;
    }

    /**
     * Writes the box around every point the renderer's test of a triangle accepts (see
     * {@link #bounds(double[], int)}) into an array.
     *
     * @param vertices the vertices' coordinates, three doubles each
     * @param p1       where the first vertex's x lies in vertices
     * @param p2       where the second vertex's x lies
     * @param p3       where the third vertex's x lies
     * @param box      the array
     * @param b        where the box's six numbers go: {minX, minY, minZ, maxX, maxY, maxZ}
     */
    public static void bounds(double[] vertices, int p1, int p2, int p3, double[] box, int b) {
        for (int k = 0; k < 3; ++k) {
            double a = vertices[p1 + k];
            double bk = vertices[p2 + k];
            double c = vertices[p3 + k];
            double ca = a + BARYCENTRIC_TOLERANCE * ((a - bk) + (a - c));
            double cb = bk + BARYCENTRIC_TOLERANCE * ((bk - a) + (bk - c));
            double cc = c + BARYCENTRIC_TOLERANCE * ((c - a) + (c - bk));
            box[b + k] = Math.min(Math.min(a, Math.min(bk, c)), Math.min(ca, Math.min(cb, cc)));
            box[b + 3 + k] = Math.max(Math.max(a, Math.max(bk, c)), Math.max(ca, Math.max(cb, cc)));
        }
    }

    @Override
    public String toString() {
        return "Triangle" + vertices;
    }
}
