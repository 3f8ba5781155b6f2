package geometries;

import primitives.Point3D;
import primitives.Vector;

import static primitives.Util.alignZero;
import static primitives.Util.requireNonNull;

/**
 * What the vertices of a {@link TriangleMesh} carry for shading, beside their positions: a smooth
 * normal per vertex (three doubles each) and surface coordinates, UV, per vertex (two doubles each),
 * in flat arrays of their own. They are read only when a hit is shaded, from the hit's barycentric
 * weights: never while a ray walks the mesh or the hierarchy.
 * <p>
 * A smooth normal is the barycentric interpolation of the triangle's vertex normals, normalised. A
 * coarse mesh shaded so has a <em>shadow terminator</em> problem: where the smooth normal turns to the
 * light but the flat triangle under it does not, the triangle's neighbours shadow the point, a dark
 * band of facets where the shading should fade out smoothly. The fix of Hanika ("Hacking the Shadow
 * Terminator", Ray Tracing Gems II, 2021) moves the point the shadow rays leave from onto the curved
 * surface the normals describe: the point is projected onto the tangent plane of each vertex (the
 * plane through the vertex across its normal) that it lies below, and the projections are mixed by the
 * barycentric weights ({@link #shadowPoint}). On a flat part of the mesh, and where the surface is
 * concave, the point stays where it is.
 */
final class MeshShading {
    /** How far from 1 the length of a given vertex normal may be. */
    static final double UNIT_TOLERANCE = 1e-6;
    /** A sum of weighted normals shorter than this is taken as no direction at all. */
    private static final double NO_DIRECTION = 1e-12;

    /** The mesh, for its triangles' data and flat normals. */
    private final TriangleMesh mesh;
    /** The mesh's vertices' coordinates, three doubles per vertex (the mesh's array, not a copy). */
    private final double[] vertices;
    /** The mesh's triangles, three vertex indices each (the mesh's array, not a copy). */
    private final int[] indices;
    /** The unit normals, three doubles per vertex, or null for a flat mesh. */
    private double[] normals;
    /** The surface coordinates, u and v per vertex, or null when the mesh has none. */
    private double[] uvs;

    /**
     * Shading data for a mesh's vertices, none yet.
     *
     * @param mesh     the mesh
     * @param vertices the mesh's vertices' coordinates
     * @param indices  the mesh's triangles' vertex indices
     */
    MeshShading(TriangleMesh mesh, double[] vertices, int[] indices) {
        this.mesh = mesh;
        this.vertices = vertices;
        this.indices = indices;
    }

    /** {@return the number of vertices} */
    private int vertexCount() {
        return vertices.length / 3;
    }

    /**
     * Sets the vertex normals, checked and copied.
     *
     * @param given one unit normal per vertex, x, y and z of each in turn
     * @throws IllegalArgumentException when the array is null or of the wrong length, or a normal is
     *                                  not a finite unit vector (the message names the vertex)
     */
    void setNormals(double[] given) {
        requireNonNull(given, "mesh vertex normals");
        if (given.length != 3 * vertexCount())
            throw new IllegalArgumentException("mesh vertex normals need three numbers for each of the "
                    + vertexCount() + " vertices (" + 3 * vertexCount() + " numbers), got " + given.length);
        for (int v = 0; v < vertexCount(); ++v) {
            double x = given[3 * v];
            double y = given[3 * v + 1];
            double z = given[3 * v + 2];
            double length = Math.sqrt(x * x + y * y + z * z);
            if (!(Math.abs(length - 1) <= UNIT_TOLERANCE))
                throw new IllegalArgumentException("the normal of mesh vertex " + v + " must be a unit vector, got ("
                        + x + ", " + y + ", " + z + ") of length " + length);
        }
        normals = given.clone();
    }

    /** {@return a copy of the vertex normals, or null for a flat mesh} */
    double[] getNormals() {
        return normals == null ? null : normals.clone();
    }

    /** {@return true when the mesh has vertex normals} */
    boolean isSmooth() {
        return normals != null;
    }

    /**
     * Sets the vertices' surface coordinates, checked and copied.
     *
     * @param given u and v of each vertex in turn
     * @throws IllegalArgumentException when the array is null or of the wrong length, or a coordinate is
     *                                  not a finite number (the message names the vertex)
     */
    void setUVs(double[] given) {
        requireNonNull(given, "mesh UVs");
        if (given.length != 2 * vertexCount())
            throw new IllegalArgumentException("mesh UVs need two numbers (u v) for each of the " + vertexCount()
                    + " vertices (" + 2 * vertexCount() + " numbers), got " + given.length);
        for (int i = 0; i < given.length; ++i)
            if (!Double.isFinite(given[i]))
                throw new IllegalArgumentException("the UV of mesh vertex " + i / 2 + " has a coordinate that is not"
                        + " a finite number: " + given[i]);
        uvs = given.clone();
    }

    /** {@return a copy of the vertices' surface coordinates, or null when the mesh has none} */
    double[] getUVs() {
        return uvs == null ? null : uvs.clone();
    }

    /** {@return true when the mesh has surface coordinates} */
    boolean hasUVs() {
        return uvs != null;
    }

    /**
     * The surface coordinates at a point of a triangle: its vertices' UVs mixed by the point's weights.
     *
     * @param t       the triangle
     * @param weights the weights of its three vertices at the point
     * @return {u, v}
     * @throws UnsupportedOperationException when the mesh has no UVs
     */
    double[] uv(int t, double[] weights) {
        if (uvs == null)
            throw new UnsupportedOperationException(mesh + " has no UVs");
        return new double[] { mixed(uvs, 2, 0, t, weights), mixed(uvs, 2, 1, t, weights) };
    }

    /**
     * Computes the vertex normals from the triangles around each vertex: the sum of their unit normals,
     * each weighted by the triangle's angle at the vertex (so that how a surface is cut into triangles
     * does not tilt its normals), normalised. Where the sum vanishes (the two sides of a sheet meet at
     * the vertex) the vertex takes the normal of its first triangle; a vertex no triangle uses gets
     * (0, 0, 1), which nothing reads.
     */
    void computeNormals() {
        double[] sums = new double[vertices.length];
        double[] first = new double[vertices.length];
        boolean[] used = new boolean[vertexCount()];
        for (int t = 0; t < indices.length / 3; ++t) {
            Vector normal = mesh.getNormal(t);
            double[] face = { normal.getX(), normal.getY(), normal.getZ() };
            for (int k = 0; k < 3; ++k) {
                int v = indices[3 * t + k];
                double angle = cornerAngle(v, indices[3 * t + (k + 1) % 3], indices[3 * t + (k + 2) % 3]);
                for (int i = 0; i < 3; ++i) {
                    sums[3 * v + i] += angle * face[i];
                    if (!used[v])
                        first[3 * v + i] = face[i];
                }
                used[v] = true;
            }
        }
        for (int v = 0; v < vertexCount(); ++v) {
            double length = Math.sqrt(sums[3 * v] * sums[3 * v] + sums[3 * v + 1] * sums[3 * v + 1]
                    + sums[3 * v + 2] * sums[3 * v + 2]);
            if (!used[v])
                sums[3 * v + 2] = 1;
            else if (length <= NO_DIRECTION)
                System.arraycopy(first, 3 * v, sums, 3 * v, 3);
            else
                for (int i = 0; i < 3; ++i)
                    sums[3 * v + i] /= length;
        }
        normals = sums;
    }

    /** {@return the angle at vertex v between its edges to vertices p and q} */
    private double cornerAngle(int v, int p, int q) {
        double ux = vertices[3 * p] - vertices[3 * v];
        double uy = vertices[3 * p + 1] - vertices[3 * v + 1];
        double uz = vertices[3 * p + 2] - vertices[3 * v + 2];
        double wx = vertices[3 * q] - vertices[3 * v];
        double wy = vertices[3 * q + 1] - vertices[3 * v + 1];
        double wz = vertices[3 * q + 2] - vertices[3 * v + 2];
        double cx = uy * wz - uz * wy;
        double cy = uz * wx - ux * wz;
        double cz = ux * wy - uy * wx;
        return Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), ux * wx + uy * wy + uz * wz);
    }

    /**
     * The barycentric weights of a triangle's three vertices at a point of it (of its plane).
     *
     * @param t     the triangle
     * @param point the point
     * @return {w1, w2, w3}, summing to 1
     */
    double[] weights(int t, Point3D point) {
        double[] data = new double[TriangleMesh.TRIANGLE_DATA];
        double[] foot = new double[Triangle.PROJECTION];
        mesh.triangleData(t, data, 0);
        Triangle.project(data, point.getX(), point.getY(), point.getZ(), foot);
        return new double[] { 1 - foot[0] - foot[1], foot[0], foot[1] };
    }

    /**
     * The smooth normal at a point of a triangle: its vertex normals mixed by the point's barycentric
     * weights, normalised; the triangle's own normal where they cancel out.
     *
     * @param t       the triangle
     * @param weights the weights of its three vertices at the point
     * @return the unit normal
     */
    Vector normal(int t, double[] weights) {
        double x = mixed(normals, 3, 0, t, weights);
        double y = mixed(normals, 3, 1, t, weights);
        double z = mixed(normals, 3, 2, t, weights);
        double length = Math.sqrt(x * x + y * y + z * z);
        return length > NO_DIRECTION ? new Vector(x / length, y / length, z / length) : mesh.getNormal(t);
    }

    /**
     * One number of a per-vertex attribute at a point of a triangle: the triangle's vertices' values
     * mixed by the point's barycentric weights.
     *
     * @param values  the attribute, {@code width} numbers per vertex
     * @param width   how many numbers a vertex has
     * @param number  which of them
     * @param t       the triangle
     * @param weights the weights of its three vertices at the point
     * @return the mixed number
     */
    private double mixed(double[] values, int width, int number, int t, double[] weights) {
        double sum = 0;
        for (int k = 0; k < 3; ++k)
            sum += weights[k] * values[width * indices[3 * t + k] + number];
        return sum;
    }

    /**
     * The point shadow rays leave a hit from (Hanika's fix, see the class comment): the hit moved onto
     * the tangent planes of the triangle's vertices that it lies below, seen from the side of the smooth
     * normal the light is on, mixed by its barycentric weights.
     *
     * @param t       the triangle
     * @param weights the weights of its three vertices at the point
     * @param point   the hit
     * @param l       the unit direction from the light to the point
     * @return the lifted point, or the hit itself when no tangent plane lies above it or the light lies
     *         along the surface
     */
    Point3D shadowPoint(int t, double[] weights, Point3D point, Vector l) {
        double facing = alignZero(normal(t, weights).dotProduct(requireNonNull(l, "light direction")));
        if (facing == 0)
            return point;
        double side = facing < 0 ? 1 : -1;
        double x = 0;
        double y = 0;
        double z = 0;
        for (int k = 0; k < 3; ++k) {
            int v = 3 * indices[3 * t + k];
            double nx = side * normals[v];
            double ny = side * normals[v + 1];
            double nz = side * normals[v + 2];
            double height = (point.getX() - vertices[v]) * nx + (point.getY() - vertices[v + 1]) * ny
                    + (point.getZ() - vertices[v + 2]) * nz;
            if (height < 0) { // below this vertex's tangent plane: its projection lifts the point
                x -= weights[k] * height * nx;
                y -= weights[k] * height * ny;
                z -= weights[k] * height * nz;
            }
        }
        return x == 0 && y == 0 && z == 0 ? point
                : new Point3D(point.getX() + x, point.getY() + y, point.getZ() + z);
    }
}
