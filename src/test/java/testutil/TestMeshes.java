package testutil;

import geometries.TriangleMesh;
import benchmark.SphereMesh;
import primitives.Point3D;

/**
 * Small triangle meshes shared by the tests and the benchmark: a cube, a box, a tetrahedron, one mesh
 * of several, and a bowl.
 */
public final class TestMeshes {
    /** Not instantiable. */
    private TestMeshes() {
    }

    /**
     * An axis-aligned cube of 12 triangles over 8 shared vertices, vertex i at the corner whose bits
     * 1, 2 and 4 of i choose the high x, y and z.
     *
     * @param x0   the low corner, x
     * @param y0   the low corner, y
     * @param z0   the low corner, z
     * @param side the edge's length
     * @return the mesh
     */
    public static TriangleMesh cube(double x0, double y0, double z0, double side) {
        return cuboid(x0, y0, z0, x0 + side, y0 + side, z0 + side);
    }

    /**
     * A closed box mesh [x0, x1] × [y0, y1] × [z0, z1]: twelve triangles, two per face, facing out.
     *
     * @param x0 the low corner, x
     * @param y0 the low corner, y
     * @param z0 the low corner, z
     * @param x1 the high corner, x
     * @param y1 the high corner, y
     * @param z1 the high corner, z
     * @return the mesh
     */
    public static TriangleMesh cuboid(double x0, double y0, double z0, double x1, double y1, double z1) {
        double[] vertices = new double[24];
        for (int i = 0; i < 8; ++i) {
            vertices[3 * i] = (i & 1) == 0 ? x0 : x1;
            vertices[3 * i + 1] = (i >> 1 & 1) == 0 ? y0 : y1;
            vertices[3 * i + 2] = (i >> 2 & 1) == 0 ? z0 : z1;
        }
        return new TriangleMesh(vertices, cubeFaces());
    }

    /** {@return the 12 triangles of {@link #cube}'s six faces, by vertex index} */
    public static int[] cubeFaces() {
        return new int[] { 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2,
                1, 3, 7, 1, 7, 5 };
    }

    /** {@return the coordinates of the tetrahedron (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)} */
    public static double[] tetrahedronVertices() {
        return new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    }

    /** {@return the four faces of {@link #tetrahedronVertices}'s tetrahedron, by vertex index, facing out} */
    public static int[] tetrahedronFaces() {
        return new int[] { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
    }

    /**
     * The tetrahedron (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1) moved by a point.
     *
     * @param at where the first vertex goes
     * @return the mesh
     */
    public static TriangleMesh tetrahedron(Point3D at) {
        double[] vertices = tetrahedronVertices();
        for (int i = 0; i < vertices.length; i += 3) {
            vertices[i] += at.getX();
            vertices[i + 1] += at.getY();
            vertices[i + 2] += at.getZ();
        }
        return new TriangleMesh(vertices, tetrahedronFaces());
    }

    /**
     * One mesh of the triangles of several, each keeping its own vertices.
     *
     * @param meshes the meshes
     * @return the mesh of all their triangles
     */
    public static TriangleMesh merge(TriangleMesh... meshes) {
        int vertexCount = 0;
        int triangleCount = 0;
        for (TriangleMesh mesh : meshes) {
            vertexCount += mesh.getVerticesCount();
            triangleCount += mesh.getTrianglesCount();
        }
        double[] vertices = new double[3 * vertexCount];
        int[] indices = new int[3 * triangleCount];
        int v = 0;
        int i = 0;
        for (TriangleMesh mesh : meshes) {
            for (int t = 0; t < mesh.getTrianglesCount(); ++t)
                for (int k = 0; k < 3; ++k)
                    indices[i++] = v + mesh.getVertexIndex(t, k);
            for (int m = 0; m < mesh.getVerticesCount(); ++m, ++v) {
                Point3D point = mesh.getVertex(m);
                vertices[3 * v] = point.getX();
                vertices[3 * v + 1] = point.getY();
                vertices[3 * v + 2] = point.getZ();
            }
        }
        return new TriangleMesh(vertices, indices);
    }

    /**
     * An open mesh: a sphere's mesh without the triangles of its top cap.
     *
     * @param centre   the sphere's centre
     * @param radius   its radius
     * @param rings    its bands
     * @param segments its slices
     * @return the mesh
     */
    public static TriangleMesh bowl(Point3D centre, double radius, int rings, int segments) {
        TriangleMesh sphere = SphereMesh.mesh(centre, radius, rings, segments);
        int perSlice = 2 * (rings - 1); // the top's triangle first, then the bands' and the bottom's
        int[] indices = new int[3 * (sphere.getTrianglesCount() - segments)];
        int i = 0;
        for (int t = 0; t < sphere.getTrianglesCount(); ++t)
            if (t % perSlice != 0)
                for (int k = 0; k < 3; ++k)
                    indices[i++] = sphere.getVertexIndex(t, k);
        return new TriangleMesh(sphere.coordinates(), indices);
    }
}
