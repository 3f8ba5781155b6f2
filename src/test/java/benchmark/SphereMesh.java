package benchmark;

import java.util.List;

import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Point3D;

/**
 * A UV-sphere tessellation: a closed, watertight triangle mesh whose vertices all lie on a sphere.
 * The sphere is cut into {@code rings} bands of equal polar angle (pole to pole along y) and
 * {@code segments} slices of equal azimuth. The two bands at the poles are fans of triangles around
 * the pole vertex; every other band is a row of quads split into two triangles. Neighbouring
 * triangles share the same vertex objects, and every triangle's vertices run counter-clockwise seen
 * from outside (its normal {@code (p2 - p1) × (p3 - p1)} points outward). The benchmark renders it as
 * a flat {@link TriangleMesh}.
 */
public final class SphereMesh {
    /** The indices of the poles' vertices. */
    private static final int TOP = 0;
    private static final int BOTTOM = 1;

    /** Not instantiable. */
    private SphereMesh() {
    }

    /**
     * The number of triangles of a mesh: a fan of {@code segments} triangles at each pole and two
     * triangles per quad in each of the {@code rings - 2} inner bands.
     *
     * @param rings    the number of bands from pole to pole, 2 or more
     * @param segments the number of slices around the axis, 3 or more
     * @return {@code 2 · segments · (rings - 1)}
     * @throws IllegalArgumentException when rings or segments are too few
     */
    public static int trianglesCount(int rings, int segments) {
        checkCounts(rings, segments);
        return 2 * segments * (rings - 1);
    }

    /**
     * Tessellates a sphere into triangle objects: the triangles of {@link #mesh}, in its order.
     *
     * @param center   the sphere's centre
     * @param radius   the sphere's radius, positive
     * @param rings    the number of bands from pole to pole, 2 or more
     * @param segments the number of slices around the axis, 3 or more
     * @return the triangles, {@link #trianglesCount(int, int)} of them
     * @throws IllegalArgumentException when the radius is not positive or rings or segments are too few
     */
    public static List<Triangle> triangles(Point3D center, double radius, int rings, int segments) {
        return mesh(center, radius, rings, segments).getTriangles();
    }

    /**
     * Tessellates a sphere into a flat mesh: the two poles (vertices 0, the top, and 1), then ring
     * k = 1 … rings − 1 at polar angle k·π/rings, its vertex j at azimuth j·2π/segments. The
     * triangles go slice by slice: the top's fan triangle, the band's pairs from top to bottom, the
     * bottom's fan triangle.
     *
     * @param center   the sphere's centre
     * @param radius   the sphere's radius, positive
     * @param rings    the number of bands from pole to pole, 2 or more
     * @param segments the number of slices around the axis, 3 or more
     * @return the mesh, of {@link #trianglesCount(int, int)} triangles
     * @throws IllegalArgumentException when the radius is not positive or rings or segments are too few
     */
    public static TriangleMesh mesh(Point3D center, double radius, int rings, int segments) {
        if (center == null)
            throw new IllegalArgumentException("sphere mesh centre must not be null");
        if (!(radius > 0) || Double.isInfinite(radius))
            throw new IllegalArgumentException("sphere mesh radius must be positive and finite, got " + radius);
        checkCounts(rings, segments);

        double[] vertices = new double[3 * (2 + (rings - 1) * segments)];
        setVertex(vertices, TOP, center.getX(), center.getY() + radius, center.getZ());
        setVertex(vertices, BOTTOM, center.getX(), center.getY() - radius, center.getZ());
        for (int k = 1; k < rings; ++k) {
            double theta = Math.PI * k / rings;
            double y = radius * Math.cos(theta);
            double rho = radius * Math.sin(theta);
            for (int j = 0; j < segments; ++j) {
                double phi = 2 * Math.PI * j / segments;
                setVertex(vertices, ringVertex(k, j, segments), center.getX() + rho * Math.cos(phi),
                        center.getY() + y, center.getZ() + rho * Math.sin(phi));
            }
        }

        int[] indices = new int[3 * trianglesCount(rings, segments)];
        int i = 0;
        for (int j = 0; j < segments; ++j) {
            int next = (j + 1) % segments;
            i = setTriangle(indices, i, TOP, ringVertex(1, next, segments), ringVertex(1, j, segments));
            for (int k = 1; k < rings - 1; ++k) {
                int a = ringVertex(k, j, segments);
                int b = ringVertex(k, next, segments);
                int c = ringVertex(k + 1, next, segments);
                int d = ringVertex(k + 1, j, segments);
                i = setTriangle(indices, i, a, b, d);
                i = setTriangle(indices, i, b, c, d);
            }
            i = setTriangle(indices, i, BOTTOM, ringVertex(rings - 1, j, segments), ringVertex(rings - 1, next, segments));
        }
        return new TriangleMesh(vertices, indices);
    }

    /** {@return the index of vertex j of ring k} */
    private static int ringVertex(int k, int j, int segments) {
        return 2 + (k - 1) * segments + j;
    }

    /** Sets vertex v's coordinates. */
    private static void setVertex(double[] vertices, int v, double x, double y, double z) {
        vertices[3 * v] = x;
        vertices[3 * v + 1] = y;
        vertices[3 * v + 2] = z;
    }

    /** Sets the triangle whose indices start at i; returns where the next one's start. */
    static int setTriangle(int[] indices, int i, int a, int b, int c) {
        indices[i] = a;
        indices[i + 1] = b;
        indices[i + 2] = c;
        return i + 3;
    }

    private static void checkCounts(int rings, int segments) {
        if (rings < 2)
            throw new IllegalArgumentException("sphere mesh needs 2 or more rings, got " + rings);
        if (segments < 3)
            throw new IllegalArgumentException("sphere mesh needs 3 or more segments, got " + segments);
    }
}
