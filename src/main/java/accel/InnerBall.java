package accel;

import geometries.TriangleMesh;
import geometries.Triangle;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.IntStream;

/**
 * A ball inside a closed triangle mesh, which touches none of its triangles. Every edge of a closed
 * mesh is shared by an even number of its triangles, so its surface splits space into an inside and
 * an outside; a segment from a point of the ball (inside) to a point outside the mesh crosses the
 * surface. An opaque closed mesh therefore blocks every shadow ray that passes through its inner
 * ball on the way to a light outside the mesh's box, without a triangle being tested: the solid core
 * of an occluder, which lets a whole bundle of shadow rays in a body's umbra be answered at once.
 * <p>
 * The ball is centred on the mean of the triangles' corners or on the centre of their box: the one
 * of the larger ball whose centre lies surely inside the mesh. Its radius is the distance from the
 * centre to the nearest triangle, less a rounding margin. Whether a centre lies inside is told by the
 * parity of the crossings of three rays from it, each of which must be sure (no crossing near an edge
 * or along a triangle) and odd.
 */
public final class InnerBall {
    /** The part of the distance to the nearest triangle kept off the radius, for rounding. */
    private static final double SHRINK = 1e-6;
    /** The part of the mesh's largest coordinate kept off the radius too, for rounding. */
    private static final double ROUNDING = 1e-12;
    /** How near, in barycentric terms, to an edge a crossing makes a parity ray unsure. */
    private static final double EDGE_MARGIN = 1e-7;
    /** Below this |cosine| between a parity ray and a triangle's normal, the ray is unsure. */
    private static final double GRAZING = 1e-7;
    /** The directions of the parity rays: three unit vectors off the axes and each other. */
    private static final double[][] PARITY_DIRECTIONS = {
            unit(0.5773502691896258, 0.6123724356957946, 0.5400617248673217),
            unit(-0.7071067811865475, 0.1224744871391589, 0.6963106238227914),
            unit(0.2672612419124244, -0.8017837257372732, -0.5345224838248488) };
    /** What a parity count answers when a ray is unsure. */
    private static final int UNSURE = -1;

    /** The centre, x. */
    public final double cx;
    /** The centre, y. */
    public final double cy;
    /** The centre, z. */
    public final double cz;
    /** The radius, positive. */
    public final double radius;
    /** The box around the ball. */
    private final double[] box;

    private InnerBall(double cx, double cy, double cz, double radius) {
        this.cx = cx;
        this.cy = cy;
        this.cz = cz;
        this.radius = radius;
        this.box = new double[] { cx - radius, cy - radius, cz - radius, cx + radius, cy + radius, cz + radius };
    }

    /** {@return the box around the ball, {minX, minY, minZ, maxX, maxY, maxZ}} */
    double[] box() {
        return box;
    }

    /**
     * Whether a segment passes through the inside of the ball: the point of the ray nearest the centre
     * within its distance lies nearer the centre than the radius.
     *
     * @param ox   the ray's origin, x
     * @param oy   the ray's origin, y
     * @param oz   the ray's origin, z
     * @param dx   the ray's unit direction, x
     * @param dy   the ray's unit direction, y
     * @param dz   the ray's unit direction, z
     * @param maxT the segment's length along the ray
     * @return true when the segment meets the ball's inside
     */
    boolean crossedBy(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
        double wx = cx - ox;
        double wy = cy - oy;
        double wz = cz - oz;
        double t = Math.min(Math.max(wx * dx + wy * dy + wz * dz, 0), maxT);
        double x = wx - t * dx;
        double y = wy - t * dy;
        double z = wz - t * dz;
        return x * x + y * y + z * z < radius * radius;
    }

    /**
     * Finds the inner ball of a mesh.
     *
     * @param mesh the mesh
     * @return the ball, or null when the mesh is not closed or neither centre is surely inside it
     */
    public static InnerBall of(TriangleMesh mesh) {
        return isClosed(mesh) ? ofClosed(mesh) : null;
    }

    /**
     * Finds the inner ball of a mesh known to be closed (see {@link ClosedParts}).
     *
     * @param mesh the mesh, closed
     * @return the ball, or null when neither centre is surely inside it
     */
    static InnerBall ofClosed(TriangleMesh mesh) {
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        double scale = largestCoordinate(mesh);
        List<InnerBall> balls = new ArrayList<>();
        for (double[] centre : centres(mesh, data)) {
            InnerBall ball = around(mesh, data, centre, scale);
            if (ball != null)
                balls.add(ball);
        }
        // the larger ball first: the other's centre is tried only when this one's is not surely inside
        balls.sort(Comparator.comparingDouble((InnerBall ball) -> ball.radius).reversed());
        for (InnerBall ball : balls)
            if (inside(mesh, ball))
                return ball;
        return null;
    }

    /**
     * Whether a mesh is closed by vertex index: every edge shared by an even number of triangles
     * ({@link ClosedParts#isClosed(int[], int[], int[])}, each vertex standing for itself).
     *
     * @param mesh the mesh
     * @return true when every edge is used an even number of times
     */
    static boolean isClosed(TriangleMesh mesh) {
        int[] own = IntStream.range(0, mesh.getVerticesCount()).toArray();
        int[] all = IntStream.range(0, mesh.getTrianglesCount()).toArray();
        return ClosedParts.isClosed(own, mesh.indices(), all);
    }

    /**
     * The candidate centres: the mean of the triangles' corners and the centre of their box.
     *
     * @param data scratch space for a triangle's data
     */
    private static double[][] centres(TriangleMesh mesh, double[] data) {
        int triangles = mesh.getTrianglesCount();
        double[] mean = new double[3];
        double[] low = { Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY };
        double[] high = { Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY };
        for (int t = 0; t < triangles; ++t) {
            mesh.triangleData(t, data, 0);
            for (int k = 0; k < 3; ++k) {
                double p1 = data[k];
                double p2 = p1 + data[3 + k];
                double p3 = p1 + data[6 + k];
                mean[k] += (p1 + p2 + p3) / (3.0 * triangles);
                low[k] = Math.min(low[k], Math.min(p1, Math.min(p2, p3)));
                high[k] = Math.max(high[k], Math.max(p1, Math.max(p2, p3)));
            }
        }
        double[] middle = new double[3];
        for (int k = 0; k < 3; ++k)
            middle[k] = (low[k] + high[k]) / 2;
        return new double[][] { mean, middle };
    }

    /** {@return the largest |coordinate| of a mesh's box} */
    private static double largestCoordinate(TriangleMesh mesh) {
        double[] box = new double[6];
        mesh.bounds(box, 0);
        double scale = 0;
        for (double bound : box)
            scale = Math.max(scale, Math.abs(bound));
        return scale;
    }

    /**
     * Whether a ball's centre lies surely inside a closed mesh: each parity ray from it is sure and
     * crosses the mesh an odd number of times.
     */
    private static boolean inside(TriangleMesh mesh, InnerBall ball) {
        return parity(mesh, ball.cx, ball.cy, ball.cz) == 1;
    }

    /**
     * Whether a point lies inside a closed mesh, as the parity rays from it tell: 1 when each is sure
     * and crosses the mesh an odd number of times, 0 when each is sure and crosses it an even number
     * of times, −1 when a ray is unsure or they disagree.
     *
     * @param mesh the mesh, closed
     * @param x    the point, x
     * @param y    the point, y
     * @param z    the point, z
     * @return 1 inside, 0 outside, −1 unsure
     */
    static int parity(TriangleMesh mesh, double x, double y, double z) {
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        double[] centre = { x, y, z };
        int parity = UNSURE;
        for (double[] d : PARITY_DIRECTIONS) {
            int crossings = crossings(mesh, data, centre, d);
            if (crossings == UNSURE || (parity != UNSURE && crossings % 2 != parity))
                return UNSURE;
            parity = crossings % 2;
        }
        return parity;
    }

    /**
     * The ball around a centre that touches no triangle, its radius the distance to the nearest
     * triangle less a relative margin and an absolute one for the rounding of coordinates as large as
     * the mesh's; whether it lies inside the mesh is not asked.
     *
     * @param data  scratch space for a triangle's data
     * @param scale the largest |coordinate| of the mesh's box
     * @return the ball, or null when the centre is (nearly) on a triangle
     */
    private static InnerBall around(TriangleMesh mesh, double[] data, double[] centre, double scale) {
        double nearest = Double.POSITIVE_INFINITY;
        double[] foot = new double[Triangle.PROJECTION];
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            mesh.triangleData(t, data, 0);
            nearest = Math.min(nearest, distanceToTriangle(data, centre[0], centre[1], centre[2], foot));
        }
        double radius = nearest * (1 - SHRINK) - ROUNDING * scale;
        return radius > 0 ? new InnerBall(centre[0], centre[1], centre[2], radius) : null;
    }

    /**
     * Counts the triangles a ray from a centre crosses, with exact barycentric bounds.
     *
     * @param data scratch space for a triangle's data
     * @param d    the ray's unit direction
     * @return the count, or {@link #UNSURE} when the ray passes near an edge or along a triangle
     */
    private static int crossings(TriangleMesh mesh, double[] data, double[] centre, double[] d) {
        double[] foot = new double[Triangle.PROJECTION];
        int count = 0;
        for (int t = 0; t < mesh.getTrianglesCount(); ++t) {
            mesh.triangleData(t, data, 0);
            Triangle.project(data, centre[0], centre[1], centre[2], foot);
            double cosine = d[0] * foot[3] + d[1] * foot[4] + d[2] * foot[5];
            double distance = -foot[2] / cosine;
            if (!(distance > 0 && distance < Double.POSITIVE_INFINITY))
                continue;
            Triangle.project(data, centre[0] + distance * d[0], centre[1] + distance * d[1],
                    centre[2] + distance * d[2], foot);
            double u = foot[0];
            double v = foot[1];
            if (!(u >= -EDGE_MARGIN && v >= -EDGE_MARGIN && u + v <= 1 + EDGE_MARGIN))
                continue;
            if (Math.abs(cosine) < GRAZING || u < EDGE_MARGIN || v < EDGE_MARGIN || u + v > 1 - EDGE_MARGIN)
                return UNSURE;
            ++count;
        }
        return count;
    }

    /**
     * The distance from a point to a triangle: to its plane when the point's foot on it falls inside
     * the triangle, else to the nearest of its edges.
     *
     * @param data the triangle's data, as {@link TriangleMesh#triangleData} writes it: p1, e1, e2
     * @param foot scratch space for {@link Triangle#project}
     * @return the distance
     */
    static double distanceToTriangle(double[] data, double x, double y, double z, double[] foot) {
        Triangle.project(data, x, y, z, foot);
        double u = foot[0];
        double v = foot[1];
        if (u >= 0 && v >= 0 && u + v <= 1)
            return Math.abs(foot[2]);
        double wx = x - data[0];
        double wy = y - data[1];
        double wz = z - data[2];
        double first = toSegment(wx, wy, wz, data[3], data[4], data[5]);
        double second = toSegment(wx, wy, wz, data[6], data[7], data[8]);
        double third = toSegment(wx - data[3], wy - data[4], wz - data[5], data[6] - data[3], data[7] - data[4],
                data[8] - data[5]);
        return Math.min(first, Math.min(second, third));
    }

    /** {@return the distance from a point, w from a segment's start, to the segment from there along e} */
    private static double toSegment(double wx, double wy, double wz, double ex, double ey, double ez) {
        double f = Math.min(Math.max((wx * ex + wy * ey + wz * ez) / (ex * ex + ey * ey + ez * ez), 0), 1);
        double x = wx - f * ex;
        double y = wy - f * ey;
        double z = wz - f * ez;
        return Math.sqrt(x * x + y * y + z * z);
    }

    /** {@return a vector scaled to length 1} */
    private static double[] unit(double x, double y, double z) {
        double length = Math.sqrt(x * x + y * y + z * z);
        return new double[] { x / length, y / length, z / length };
    }
}
