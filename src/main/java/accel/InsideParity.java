package accel;

import geometries.Triangle;
import geometries.TriangleMesh;

/**
 * Whether a point lies inside a closed triangle mesh, told by the parity of the crossings of three
 * rays from it: every edge of a closed mesh is shared by an even number of its triangles, so a ray
 * from a point inside crosses its surface an odd number of times. A ray that passes near an edge or
 * along a triangle is unsure, and so is the answer.
 */
final class InsideParity {
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

    /** Not instantiable. */
    private InsideParity() {
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
        double[] foot = new double[Triangle.PROJECTION];
        double[] centre = { x, y, z };
        int parity = UNSURE;
        for (double[] d : PARITY_DIRECTIONS) {
            int crossings = crossings(mesh, data, foot, centre, d);
            if (crossings == UNSURE || (parity != UNSURE && crossings % 2 != parity))
                return UNSURE;
            parity = crossings % 2;
        }
        return parity;
    }

    /**
     * Counts the triangles a ray from a centre crosses, with exact barycentric bounds.
     *
     * @param data scratch space for a triangle's data
     * @param foot scratch space for a point's projection onto a triangle ({@link Triangle#project})
     * @param d    the ray's unit direction
     * @return the count, or {@link #UNSURE} when the ray passes near an edge or along a triangle
     */
    private static int crossings(TriangleMesh mesh, double[] data, double[] foot, double[] centre, double[] d) {
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

    /** {@return a vector scaled to length 1} */
    private static double[] unit(double x, double y, double z) {
        double length = Math.sqrt(x * x + y * y + z * z);
        return new double[] { x / length, y / length, z / length };
    }
}
