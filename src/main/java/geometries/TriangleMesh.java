package geometries;

import accel.ShadowFrustum;
import accel.BoundingVolumeHierarchy;
import accel.RayState;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.requireNonNull;

/**
 * A triangle mesh stored flat: every vertex once, as three doubles in one array, and every triangle
 * as the indices of its three vertices in another, so that neighbouring triangles share their
 * vertices and no object exists per triangle. This is how large meshes (an imported OBJ model, a
 * terrain) fit in memory: about 24 bytes per triangle for a closed mesh or a grid, against several
 * hundred for a {@link Triangle} object each. The whole mesh has one emission and one material.
 * <p>
 * Each triangle is the {@link Triangle} of its three vertices, in order, and behaves exactly like
 * it: the course's queries ({@link #findIntersections}, {@link #findGeoIntersections}) take every
 * triangle as open (a ray through an edge, a vertex or an edge's continuation misses it), the
 * renderer's path takes it as closed, so the mesh is watertight, and its normal is the
 * {@link Triangle}'s: (p2 − p1) × (p3 − p2), normalised. The {@link BoundingVolumeHierarchy} holds
 * a mesh's triangles as its own bodies, by index. A hit on a mesh is a {@link MeshPoint}, which
 * knows its triangle, so {@link GeoPoint#getNormal()} gives that triangle's normal.
 * <p>
 * A mesh is flat until it is given a normal per vertex ({@link #setNormals}, or {@link #smoothNormals}
 * to compute them): then it is smooth, and the normal of a hit is its triangle's vertex normals mixed
 * by the hit's barycentric weights, normalised, found when the hit is shaded (the intersection tests
 * never read the normals). The shadow rays of a hit on a smooth mesh leave from the point lifted onto
 * the curved surface the normals describe ({@link GeoPoint#getShadowPoint}), so that a coarse mesh
 * shows no shadow-terminator artefacts (see {@link MeshShading}).
 */
public final class TriangleMesh extends Geometry {
    /** The number of doubles of a triangle's data for {@link #triangleData}. */
    public static final int TRIANGLE_DATA = 10;
    /** Where a triangle's parallel limit lies in its data, after p1 and the two edges. */
    public static final int PARALLEL_LIMIT = 9;
    /** The tolerance, relative to a triangle's longest edge, of a point on it (see {@link #getNormal(Point3D)}). */
    private static final double ON_TRIANGLE_TOLERANCE = 1e-9;

    /** The vertices' coordinates, three doubles per vertex. */
    private final double[] vertices;
    /** The triangles' vertices, three indices per triangle. */
    private final int[] indices;
    /** Per triangle, the |determinant| below which a ray is taken as parallel to it. */
    private final double[] parallelLimits;
    /** The box around every point the renderer's test of a triangle accepts. */
    private final double[] box = { Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY };
    /** The vertices' normals, when the mesh is smooth. */
    private final MeshShading shading;

    /**
     * Creates a mesh from its vertices and triangles. The arrays are copied.
     *
     * @param vertices the vertices' coordinates, x, y and z of each vertex in turn
     * @param indices  the triangles, the indices (from 0) of the three vertices of each in turn
     * @throws IllegalArgumentException when an array is null, its length is not a multiple of 3, there
     *                                  is no triangle, a coordinate is not a finite number, an index
     *                                  names no vertex, or a triangle is degenerate (its vertices
     *                                  coincide or are collinear, as {@link Triangle} refuses them);
     *                                  the message names the vertex or the triangle
     */
    public TriangleMesh(double[] vertices, int[] indices) {
        requireNonNull(vertices, "mesh vertices");
        requireNonNull(indices, "mesh triangles");
        if (vertices.length % 3 != 0)
            throw new IllegalArgumentException("mesh vertices need three coordinates each, got " + vertices.length
                    + " numbers");
        if (indices.length == 0 || indices.length % 3 != 0)
            throw new IllegalArgumentException("mesh triangles need three vertex indices each (one triangle or"
                    + " more), got " + indices.length + " indices");
        this.vertices = vertices.clone();
        this.indices = indices.clone();
        for (int i = 0; i < this.vertices.length; ++i)
            if (!Double.isFinite(this.vertices[i]))
                throw new IllegalArgumentException("mesh vertex " + i / 3 + " has a coordinate that is not a finite"
                        + " number: " + this.vertices[i]);
        int count = this.vertices.length / 3;
        for (int i = 0; i < this.indices.length; ++i)
            if (this.indices[i] < 0 || this.indices[i] >= count)
                throw new IllegalArgumentException("mesh triangle " + i / 3 + " refers to vertex " + this.indices[i]
                        + ", out of range [0, " + count + ")");
        this.parallelLimits = new double[this.indices.length / 3];
        double[] triangleBox = new double[6];
        for (int t = 0; t < parallelLimits.length; ++t) {
            requireNotDegenerate(t);
            parallelLimits[t] = parallelLimit(t);
            bounds(t, triangleBox, 0);
            for (int k = 0; k < 3; ++k) {
                box[k] = Math.min(box[k], triangleBox[k]);
                box[3 + k] = Math.max(box[3 + k], triangleBox[3 + k]);
            }
        }
        this.shading = new MeshShading(this, this.vertices, this.indices);
    }

    /**
     * Makes the mesh smooth with the given vertex normals (copied).
     *
     * @param normals one unit normal per vertex, x, y and z of each in turn (outward, as the triangles'
     *                normals are, for a light to shade the side it faces)
     * @return this mesh
     * @throws IllegalArgumentException when the array is null, its length is not three times the
     *                                  number of vertices, or a normal is not a unit vector (NaN or
     *                                  infinite included; the message names the vertex)
     */
    public TriangleMesh setNormals(double[] normals) {
        shading.setNormals(normals);
        return this;
    }

    /**
     * Makes the mesh smooth with vertex normals computed from its triangles: at each vertex, the
     * normals of the triangles around it weighted by their angles there, normalised. The vertices of a
     * sharp edge should not be shared by its two sides, or the edge is rounded too.
     *
     * @return this mesh
     */
    public TriangleMesh smoothNormals() {
        shading.computeNormals();
        return this;
    }

    /** {@return true when the mesh has vertex normals, false when it is flat} */
    public boolean isSmooth() {
        return shading.isSmooth();
    }

    /** {@return the vertices' normals and UVs, for the mesh's hits ({@link MeshPoint})} */
    MeshShading shading() {
        return shading;
    }

    /** {@return a copy of the vertex normals, three numbers per vertex, or null when the mesh is flat} */
    public double[] getNormals() {
        return shading.getNormals();
    }

    /**
     * Gives the vertices surface coordinates (copied), which a texture is looked up at: a point of a
     * triangle has its vertices' UVs mixed by its barycentric weights.
     *
     * @param uvs u and v of each vertex in turn (as an OBJ file's vt: the image's bottom left at (0, 0),
     *            its top right at (1, 1))
     * @return this mesh
     * @throws IllegalArgumentException when the array is null, its length is not twice the number of
     *                                  vertices, or a coordinate is not finite (the message names the vertex)
     */
    public TriangleMesh setUVs(double[] uvs) {
        shading.setUVs(uvs);
        return this;
    }

    /** {@return a copy of the vertices' UVs, two numbers per vertex, or null when the mesh has none} */
    public double[] getUVs() {
        return shading.getUVs();
    }

    /** {@return true once the mesh has UVs} */
    @Override
    protected boolean hasUV() {
        return shading.hasUVs();
    }

    /**
     * {@inheritDoc} The UVs of the triangle the point lies on, mixed by its barycentric weights there
     * (every triangle is searched, as by {@link #getNormal(Point3D)}).
     */
    @Override
    public double[] getUV(Point3D point) {
        int t = nearestTriangle(point);
        return shading.uv(t, shading.weights(t, point));
    }

    /**
     * Whether three points make a degenerate triangle, one that {@link Triangle} and a mesh refuse:
     * two of them coincide or all three are collinear (by the library's relative tolerances).
     *
     * @param p1 the first vertex
     * @param p2 the second vertex
     * @param p3 the third vertex
     * @return true when no triangle can be made of them
     * @throws IllegalArgumentException when a point is null
     */
    public static boolean isDegenerate(Point3D p1, Point3D p2, Point3D p3) {
        Point3D[] vertices = { requireNonNull(p1, "vertex p1"), requireNonNull(p2, "vertex p2"),
                requireNonNull(p3, "vertex p3") };
        try {
            Polygon.edgesOf(vertices);
            return false;
        } catch (IllegalArgumentException degenerate) {
            return true;
        }
    }

    /** Throws when triangle t is degenerate, naming it. */
    private void requireNotDegenerate(int t) {
        try {
            Polygon.edgesOf(new Point3D[] { vertexOf(t, 0), vertexOf(t, 1), vertexOf(t, 2) });
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("mesh triangle " + t + " (vertices " + indices[3 * t] + ", "
                    + indices[3 * t + 1] + ", " + indices[3 * t + 2] + ") is degenerate: " + e.getMessage(), e);
        }
    }

    /** {@return triangle t's parallel limit, the {@link Triangle}'s} */
    private double parallelLimit(int t) {
        int a = corner(t, 0);
        int b = corner(t, 1);
        int c = corner(t, 2);
        return Triangle.parallelLimit(vertices[b] - vertices[a], vertices[b + 1] - vertices[a + 1],
                vertices[b + 2] - vertices[a + 2], vertices[c] - vertices[a], vertices[c + 1] - vertices[a + 1],
                vertices[c + 2] - vertices[a + 2]);
    }

    /** {@return the number of vertices} */
    public int getVerticesCount() {
        return vertices.length / 3;
    }

    /** {@return the number of triangles} */
    public int getTrianglesCount() {
        return parallelLimits.length;
    }

    /**
     * A vertex.
     *
     * @param v the vertex's index, from 0
     * @return the vertex
     * @throws IllegalArgumentException when there is no such vertex
     */
    public Point3D getVertex(int v) {
        if (v < 0 || v >= getVerticesCount())
            throw new IllegalArgumentException("mesh vertex " + v + " out of range [0, " + getVerticesCount() + ")");
        return new Point3D(vertices[3 * v], vertices[3 * v + 1], vertices[3 * v + 2]);
    }

    /**
     * A vertex of a triangle.
     *
     * @param t the triangle's index, from 0
     * @param k which of its vertices: 0, 1 or 2
     * @return the index of that vertex in the mesh
     * @throws IllegalArgumentException when there is no such triangle or k is not 0, 1 or 2
     */
    public int getVertexIndex(int t, int k) {
        requireTriangle(t);
        if (k < 0 || k > 2)
            throw new IllegalArgumentException("a triangle's vertex is 0, 1 or 2, got " + k);
        return indices[3 * t + k];
    }

    /**
     * A triangle of the mesh as a course-style {@link Triangle} object of the same vertices, with the
     * mesh's emission and material (a new object at each call).
     *
     * @param t the triangle's index, from 0
     * @return the triangle
     * @throws IllegalArgumentException when there is no such triangle
     */
    public Triangle getTriangle(int t) {
        requireTriangle(t);
        Triangle triangle = new Triangle(vertexOf(t, 0), vertexOf(t, 1), vertexOf(t, 2));
        triangle.setEmission(getEmission()).setMaterial(getMaterial());
        return triangle;
    }

    /**
     * The mesh's triangles as course-style {@link Triangle} objects, in its order, each with the mesh's
     * emission and material: for code written against lists of triangles (new objects at each call).
     *
     * @return the triangles
     */
    public List<Triangle> getTriangles() {
        List<Triangle> triangles = new ArrayList<>(getTrianglesCount());
        for (int t = 0; t < getTrianglesCount(); ++t)
            triangles.add(getTriangle(t));
        return triangles;
    }

    /**
     * The unit normal of a triangle: (p2 − p1) × (p3 − p2), normalised, the same vector as its
     * {@link Triangle}'s.
     *
     * @param t the triangle's index, from 0
     * @return the outward unit normal of the triangle (outward for vertices counter-clockwise seen
     *         from outside)
     * @throws IllegalArgumentException when there is no such triangle
     */
    public Vector getNormal(int t) {
        requireTriangle(t);
        Point3D p2 = vertexOf(t, 1);
        // normalised twice, as a Triangle's edges' product is and then the plane's copy of it
        return p2.subtract(vertexOf(t, 0)).crossProduct(vertexOf(t, 2).subtract(p2)).normalize().normalized();
    }

    /**
     * The unit normal at a point of the mesh: that of the triangle the point lies on (of the nearest
     * to it, on an edge two triangles share), or on a smooth mesh the smooth normal there. Every
     * triangle is searched; a renderer gets the normal from the hit, {@link MeshPoint#getNormal()},
     * instead.
     *
     * @param point a point on the mesh
     * @return the normal of the triangle it lies on, or the smooth normal
     * @throws IllegalArgumentException when the point is null or lies on no triangle of the mesh
     */
    @Override
    public Vector getNormal(Point3D point) {
        int nearest = nearestTriangle(point);
        return isSmooth() ? shading.normal(nearest, shading.weights(nearest, point)) : getNormal(nearest);
    }

    /**
     * The triangle a point lies on (the nearest to it, on an edge two triangles share).
     *
     * @throws IllegalArgumentException when the point is null or lies on no triangle of the mesh
     */
    private int nearestTriangle(Point3D point) {
        requireNonNull(point, "point");
        int nearest = -1;
        double nearestDistance = Double.POSITIVE_INFINITY;
        for (int t = 0; t < getTrianglesCount(); ++t) {
            double distance = distanceOnTriangle(t, point);
            if (distance < nearestDistance) {
                nearest = t;
                nearestDistance = distance;
            }
        }
        if (nearest < 0)
            throw new IllegalArgumentException("point " + point + " lies on no triangle of the mesh");
        return nearest;
    }

    /**
     * The distance of a point from a triangle's plane, when the point lies on the triangle: within the
     * tolerance of its plane and its edges.
     *
     * @return the distance, or +∞ when the point is off the triangle
     */
    private double distanceOnTriangle(int t, Point3D point) {
        double[] data = new double[TRIANGLE_DATA];
        double[] foot = new double[Triangle.PROJECTION];
        triangleData(t, data, 0);
        Triangle.project(data, point.getX(), point.getY(), point.getZ(), foot);
        double u = foot[0];
        double v = foot[1];
        double distance = Math.abs(foot[2]);
        double d11 = data[3] * data[3] + data[4] * data[4] + data[5] * data[5];
        double d22 = data[6] * data[6] + data[7] * data[7] + data[8] * data[8];
        double d33 = (data[6] - data[3]) * (data[6] - data[3]) + (data[7] - data[4]) * (data[7] - data[4])
                + (data[8] - data[5]) * (data[8] - data[5]);
        double longest = Math.sqrt(Math.max(Math.max(d11, d22), d33));
        boolean inside = u >= -ON_TRIANGLE_TOLERANCE && v >= -ON_TRIANGLE_TOLERANCE
                && u + v <= 1 + ON_TRIANGLE_TOLERANCE;
        return inside && distance <= ON_TRIANGLE_TOLERANCE * longest ? distance : Double.POSITIVE_INFINITY;
    }

    /** Throws when there is no triangle t. */
    private void requireTriangle(int t) {
        if (t < 0 || t >= getTrianglesCount())
            throw new IllegalArgumentException("mesh triangle " + t + " out of range [0, " + getTrianglesCount() + ")");
    }

    /** {@return vertex k (0, 1 or 2) of triangle t} */
    private Point3D vertexOf(int t, int k) {
        return getVertex(indices[3 * t + k]);
    }

    /**
     * The course's query: every triangle is open, as a {@link Triangle}'s own query takes it. Only the
     * triangles whose boxes the ray meets are tested as {@link Triangle}s.
     */
    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        Point3D p0 = ray.getP0();
        Vector dir = ray.getDir();
        RayState inverted = new RayState().set(p0.getX(), p0.getY(), p0.getZ(), dir.getX(), dir.getY(), dir.getZ(),
                maxDistance).invert();
        if (!meets(box, inverted, maxDistance))
            return null;
        List<GeoPoint> hits = new ArrayList<>();
        double[] triangleBox = new double[6];
        for (int t = 0; t < getTrianglesCount(); ++t) {
            bounds(t, triangleBox, 0);
            if (meets(triangleBox, inverted, maxDistance)) {
                List<GeoPoint> found = getTriangle(t).findGeoIntersectionsHelper(ray, maxDistance);
                if (found != null)
                    hits.add(new MeshPoint(this, t, found.get(0).point));
            }
        }
        if (hits.isEmpty())
            return null;
        hits.sort(Comparator.comparingDouble(hit -> hit.point.distanceSquared(p0)));
        return hits;
    }

    /**
     * Whether a ray meets a box between its origin and a distance, for the course's query: the
     * hierarchy's slab test ({@link RayState#boxEntry}).
     *
     * @param box  the box
     * @param ray  the ray, {@link RayState#invert inverted}
     * @param maxT the distance
     */
    private static boolean meets(double[] box, RayState ray, double maxT) {
        return ray.boxEntry(box, 0, maxT) != RayState.MISSED;
    }

    /** The renderer's path for the whole mesh (outside a hierarchy): the nearest closed triangle hit. */
    @Override
    public double nearestHit(RayState ray) {
        double nearest = NO_HIT;
        for (int t = 0; t < getTrianglesCount(); ++t)
            nearest = Math.min(nearest, triangleHit(t, ray));
        return nearest;
    }

    @Override
    int hitCount(RayState ray) {
        int count = 0;
        for (int t = 0; t < getTrianglesCount(); ++t)
            if (triangleHit(t, ray) < NO_HIT)
                ++count;
        return count;
    }

    /**
     * The renderer's test of one triangle: closed, the test of its {@link Triangle}
     * ({@link Triangle#intersect}) on the same numbers, its {@link #triangleData} written into the
     * ray's scratch space.
     *
     * @param t   the triangle's index
     * @param ray the ray: origin, unit direction and the largest distance that counts
     * @return the distance in (0, maxT], or {@link #NO_HIT}
     */
    public double triangleHit(int t, RayState ray) {
        double[] data = ray.triangleScratch();
        triangleData(t, data, 0);
        return Triangle.intersect(ray, data, 0, parallelLimits[t]);
    }

    /**
     * Writes the box of one triangle, the box of its {@link Triangle}, into an array.
     *
     * @param t      the triangle's index
     * @param target the array
     * @param b      where the box's six numbers go
     */
    public void bounds(int t, double[] target, int b) {
        Triangle.bounds(vertices, corner(t, 0), corner(t, 1), corner(t, 2), target, b);
    }

    /**
     * Whether triangle t may meet any ray of a shadow bundle: only when the triangle itself may
     * ({@link ShadowFrustum#meetsTriangle}, tested first: the cheaper test, and the one that sets aside
     * the surface around the apex and behind the rays' starts) and its plane meets the pyramid (as
     * {@link Polygon}'s test). Reads the mesh's arrays, allocates nothing.
     *
     * @param t       the triangle's index
     * @param frustum the pyramid the bundle sweeps
     * @return false only when no ray of the bundle can meet the triangle
     */
    public boolean mayMeet(int t, ShadowFrustum frustum) {
        int a = corner(t, 0);
        int b = corner(t, 1);
        int c = corner(t, 2);
        if (!frustum.meetsTriangle(vertices, a, b, c))
            return false;
        double ux = vertices[b] - vertices[a];
        double uy = vertices[b + 1] - vertices[a + 1];
        double uz = vertices[b + 2] - vertices[a + 2];
        double vx = vertices[c] - vertices[b];
        double vy = vertices[c + 1] - vertices[b + 1];
        double vz = vertices[c + 2] - vertices[b + 2];
        double nx = uy * vz - uz * vy;
        double ny = uz * vx - ux * vz;
        double nz = ux * vy - uy * vx;
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        return frustum.meetsPlane(nx / length, ny / length, nz / length, vertices[a], vertices[a + 1],
                vertices[a + 2]);
    }

    /**
     * Writes the data of triangle t into an array: the first vertex p1, the edges p2 − p1 and p3 − p1,
     * and the parallel limit, as the renderer's test ({@link Triangle#intersect}, which gives exactly
     * {@link #triangleHit} on them) and {@link Triangle#project} take them.
     *
     * @param t      the triangle's index
     * @param target the array
     * @param offset where the {@value #TRIANGLE_DATA} numbers go
     */
    public void triangleData(int t, double[] target, int offset) {
        Triangle.writeData(vertices, corner(t, 0), corner(t, 1), corner(t, 2), parallelLimits[t], target, offset);
    }

    /** {@return the vertices' coordinates, x, y and z of each vertex in turn: a copy, so the mesh cannot change under its user} */
    public double[] coordinates() {
        return vertices.clone();
    }

    /** {@return the triangles' vertex indices, three per triangle: a copy, so the mesh cannot change under its user} */
    public int[] indices() {
        return indices.clone();
    }

    /** {@return where vertex k (0, 1 or 2) of triangle t lies in the vertices' array: the place of its x} */
    private int corner(int t, int k) {
        return 3 * indices[3 * t + k];
    }

    @Override
    public boolean bounds(double[] target, int b) {
        System.arraycopy(box, 0, target, b, 6);
        return true;
    }

    /**
     * The hit at a distance along a ray: on a given triangle, or when the hit was found on the whole
     * mesh ({@link #nearestHit(RayState)}), on the first
     * triangle the ray hits at that distance.
     */
    @Override
    public GeoPoint hitPoint(Ray ray, double t, int part) {
        int triangle = part;
        if (triangle < 0) {
            RayState numbers = toRayState(ray, t);
            triangle = 0;
            while (triangleHit(triangle, numbers) != t)
                ++triangle;
        }
        return new MeshPoint(this, triangle, ray.getPoint(t));
    }

    @Override
    public String toString() {
        return "TriangleMesh{" + getVerticesCount() + " vertices, " + getTrianglesCount() + " triangles}";
    }
}
