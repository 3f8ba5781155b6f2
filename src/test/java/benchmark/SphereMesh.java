package benchmark;

import java.util.ArrayList;
import java.util.List;

import geometries.Triangle;
import primitives.Point3D;

/**
 * A UV-sphere tessellation: a closed, watertight triangle mesh whose vertices all lie on a sphere.
 * The sphere is cut into {@code rings} bands of equal polar angle (pole to pole along y) and
 * {@code segments} slices of equal azimuth. The two bands at the poles are fans of triangles around
 * the pole vertex; every other band is a row of quads split into two triangles. Neighbouring
 * triangles share the same vertex objects, and every triangle's vertices run counter-clockwise seen
 * from outside (its normal {@code (p2 - p1) × (p3 - p1)} points outward).
 */
public final class SphereMesh {
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
     * Tessellates a sphere.
     *
     * @param center   the sphere's centre
     * @param radius   the sphere's radius, positive
     * @param rings    the number of bands from pole to pole, 2 or more
     * @param segments the number of slices around the axis, 3 or more
     * @return the triangles, {@link #trianglesCount(int, int)} of them
     * @throws IllegalArgumentException when the radius is not positive or rings or segments are too few
     */
    public static List<Triangle> triangles(Point3D center, double radius, int rings, int segments) {
        if (center == null)
            throw new IllegalArgumentException("sphere mesh centre must not be null");
        if (!(radius > 0) || Double.isInfinite(radius))
            throw new IllegalArgumentException("sphere mesh radius must be positive and finite, got " + radius);
        checkCounts(rings, segments);

        // ring k = 1 .. rings-1 at polar angle k·π/rings; ring[k][j] at azimuth j·2π/segments
        Point3D[][] ring = new Point3D[rings + 1][];
        for (int k = 1; k < rings; ++k) {
            double theta = Math.PI * k / rings;
            double y = radius * Math.cos(theta);
            double rho = radius * Math.sin(theta);
            ring[k] = new Point3D[segments];
            for (int j = 0; j < segments; ++j) {
                double phi = 2 * Math.PI * j / segments;
                ring[k][j] = new Point3D(center.getX() + rho * Math.cos(phi), center.getY() + y,
                        center.getZ() + rho * Math.sin(phi));
            }
        }
        Point3D top = new Point3D(center.getX(), center.getY() + radius, center.getZ());
        Point3D bottom = new Point3D(center.getX(), center.getY() - radius, center.getZ());

        List<Triangle> triangles = new ArrayList<>(trianglesCount(rings, segments));
        for (int j = 0; j < segments; ++j) {
            int next = (j + 1) % segments;
            triangles.add(new Triangle(top, ring[1][next], ring[1][j]));
            for (int k = 1; k < rings - 1; ++k) {
                Point3D a = ring[k][j];
                Point3D b = ring[k][next];
                Point3D c = ring[k + 1][next];
                Point3D d = ring[k + 1][j];
                triangles.add(new Triangle(a, b, d));
                triangles.add(new Triangle(b, c, d));
            }
            triangles.add(new Triangle(bottom, ring[rings - 1][j], ring[rings - 1][next]));
        }
        return triangles;
    }

    private static void checkCounts(int rings, int segments) {
        if (rings < 2)
            throw new IllegalArgumentException("sphere mesh needs 2 or more rings, got " + rings);
        if (segments < 3)
            throw new IllegalArgumentException("sphere mesh needs 3 or more segments, got " + segments);
    }
}
