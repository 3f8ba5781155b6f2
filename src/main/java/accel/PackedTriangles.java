package accel;

import java.util.ArrayList;
import java.util.List;

import geometries.Geometry;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Point3D;

/**
 * A scene's course-style {@link Triangle} objects packed into one mesh of their own, so that the walks
 * test them from flat arrays, as a {@link TriangleMesh}'s, and their closed parts block whole bundles.
 * Each triangle of the mesh has its {@link Triangle}'s vertices in order, so it is tested on the same
 * numbers; a hit still reports the {@link Triangle}, and a shadow ray reads that triangle's own
 * {@code kT}: the mesh's material is never used.
 */
final class PackedTriangles {
    /** The fewest triangles packed: a closed part's fewest, a tetrahedron's. */
    static final int MIN_TRIANGLES = 4;

    /** The mesh of the triangles' vertices, three per triangle. */
    final TriangleMesh mesh;
    /** Per triangle of {@link #mesh}: its {@link Triangle}. */
    final Triangle[] triangles;

    private PackedTriangles(TriangleMesh mesh, Triangle[] triangles) {
        this.mesh = mesh;
        this.triangles = triangles;
    }

    /**
     * Packs the course-style triangles among bounded geometries (exactly {@link Triangle}s: a
     * subclass may answer otherwise) when there are {@value #MIN_TRIANGLES} or more: they leave the
     * list, and their mesh takes the first one's place.
     *
     * @param bounded the geometries of the tree, changed in place
     * @return the packed triangles, or null when too few were found (the list is then unchanged)
     */
    static PackedTriangles take(List<Geometry> bounded) {
        List<Triangle> plain = new ArrayList<>();
        int first = -1;
        for (int g = 0; g < bounded.size(); ++g)
            if (bounded.get(g).getClass() == Triangle.class) {
                first = first < 0 ? g : first;
                plain.add((Triangle) bounded.get(g));
            }
        if (plain.size() < MIN_TRIANGLES)
            return null;
        PackedTriangles packed = new PackedTriangles(meshOf(plain), plain.toArray(new Triangle[0]));
        bounded.removeIf(geometry -> geometry.getClass() == Triangle.class);
        bounded.add(first, packed.mesh);
        return packed;
    }

    /** {@return the mesh of some triangles' vertices, three per triangle, in order} */
    private static TriangleMesh meshOf(List<Triangle> triangles) {
        double[] vertices = new double[9 * triangles.size()];
        int[] indices = new int[3 * triangles.size()];
        for (int t = 0; t < triangles.size(); ++t) {
            List<Point3D> corners = triangles.get(t).getVertices();
            for (int k = 0; k < 3; ++k) {
                vertices[9 * t + 3 * k] = corners.get(k).getX();
                vertices[9 * t + 3 * k + 1] = corners.get(k).getY();
                vertices[9 * t + 3 * k + 2] = corners.get(k).getZ();
                indices[3 * t + k] = 3 * t + k;
            }
        }
        return new TriangleMesh(vertices, indices);
    }

    /** {@return whether a geometry is this packed mesh} */
    boolean isMesh(Geometry geometry) {
        return geometry == mesh;
    }
}
