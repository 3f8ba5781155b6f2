package benchmark;

import java.util.List;

import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Point3D;

/**
 * The benchmark's bumpy terrain (scenes G&lt;n&gt; of docs/benchmarks.md): the heightfield
 * {@code y = −45.5 + 2.5·sin(0.3x)·cos(0.25z) + 1.5·sin(0.11x + 0.7)·sin(0.13z)} over
 * x ∈ [−200, 200], z ∈ [−1500, 340], cut into a grid of cells about as long as they are wide, each
 * cell split into two triangles along its diagonal, stored as a flat {@link TriangleMesh} (neighbouring
 * triangles share their vertices).
 */
public final class Terrain {
    /** The terrain's extent along x. */
    static final double MIN_X = -200;
    static final double MAX_X = 200;
    /** The terrain's extent along z. */
    static final double MIN_Z = -1500;
    static final double MAX_Z = 340;

    /** Not instantiable. */
    private Terrain() {
    }

    /**
     * The height of the terrain.
     *
     * @param x the x coordinate
     * @param z the z coordinate
     * @return y at (x, z)
     */
    public static double height(double x, double z) {
        return -45.5 + 2.5 * Math.sin(0.3 * x) * Math.cos(0.25 * z) + 1.5 * Math.sin(0.11 * x + 0.7) * Math.sin(0.13 * z);
    }

    /**
     * The cells of the grid along z for about a number of triangles: cells about square.
     *
     * @param triangles the number of triangles wanted, 2 or more
     * @return the number of cells along z
     */
    public static int cellsAlongZ(int triangles) {
        requireTriangles(triangles);
        return Math.max(1, (int) Math.round(Math.sqrt(triangles / 2.0 * (MAX_Z - MIN_Z) / (MAX_X - MIN_X))));
    }

    /**
     * The cells of the grid along x for about a number of triangles.
     *
     * @param triangles the number of triangles wanted, 2 or more
     * @return the number of cells along x
     */
    public static int cellsAlongX(int triangles) {
        return Math.max(1, (int) Math.round(triangles / 2.0 / cellsAlongZ(triangles)));
    }

    /**
     * Tessellates the terrain into about a number of triangles, as triangle objects: the triangles of
     * {@link #mesh}, in its order.
     *
     * @param triangles the number of triangles wanted, 2 or more
     * @return the triangles, row by row along z
     * @throws IllegalArgumentException when fewer than 2 triangles are wanted
     */
    public static List<Triangle> triangles(int triangles) {
        return mesh(triangles).getTriangles();
    }

    /**
     * Tessellates the terrain into a flat mesh of about a number of triangles:
     * 2 · {@link #cellsAlongX} · {@link #cellsAlongZ} of them. Vertex i of row k (x = MIN_X + i · cell
     * width, z = MIN_Z + k · cell length) is vertex k · (nx + 1) + i; the cells go row by row along z,
     * each as two triangles.
     *
     * @param triangles the number of triangles wanted, 2 or more
     * @return the mesh
     * @throws IllegalArgumentException when fewer than 2 triangles are wanted
     */
    public static TriangleMesh mesh(int triangles) {
        int nx = cellsAlongX(triangles);
        int nz = cellsAlongZ(triangles);
        double[] vertices = new double[3 * (nx + 1) * (nz + 1)];
        for (int k = 0; k <= nz; ++k) {
            double z = MIN_Z + (MAX_Z - MIN_Z) * k / nz;
            for (int i = 0; i <= nx; ++i) {
                double x = MIN_X + (MAX_X - MIN_X) * i / nx;
                int v = 3 * (k * (nx + 1) + i);
                vertices[v] = x;
                vertices[v + 1] = height(x, z);
                vertices[v + 2] = z;
            }
        }
        int[] indices = new int[6 * nx * nz];
        int t = 0;
        for (int k = 1; k <= nz; ++k)
            for (int i = 0; i < nx; ++i) {
                int previous = (k - 1) * (nx + 1) + i;
                int current = k * (nx + 1) + i;
                t = SphereMesh.setTriangle(indices, t, previous, previous + 1, current + 1);
                t = SphereMesh.setTriangle(indices, t, previous, current + 1, current);
            }
        return new TriangleMesh(vertices, indices);
    }

    private static void requireTriangles(int triangles) {
        if (triangles < 2)
            throw new IllegalArgumentException("a terrain needs 2 triangles or more, got " + triangles);
    }
}
