package geometries;

import accel.RayState;
import accel.ShadowFrustum;
import accel.BoundingVolumeHierarchy;
import java.util.List;

import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.isZero;
import static primitives.Util.requireNonNull;

/**
 * A flat convex polygon. Its edges follow two rules, each where it belongs:
 * <ul>
 * <li>The course's queries on the body itself ({@link #findIntersections}, {@link #findGeoIntersections})
 * take it as <b>open</b>: a ray through an edge, a vertex or the continuation of an edge gives no
 * intersection (null). These are the course's boundary values, which every course test suite asserts.</li>
 * <li>The renderer's own path (the primitive-double routines the {@link BoundingVolumeHierarchy} calls)
 * takes it as <b>closed</b>: a ray through an edge or a vertex hits. Two polygons sharing an edge then
 * leave no seam between them (the open rule leaves a dark line of missed pixels along every shared
 * edge, as in the report's own pictures), and meshes render watertight.</li>
 * </ul>
 * Both rules allow the same relative tolerance: a point within {@code 1e-9} of the polygon's largest edge
 * from an edge's line counts as on it.
 */
public class Polygon extends Geometry {
    /** Relative tolerance, in units of the polygon's size, for points on an edge. */
    private static final double EDGE_TOLERANCE = 1e-9;

    /** The vertices, in order around the polygon. */
    protected final List<Point3D> vertices;
    /** The plane the polygon lies in. */
    protected final Plane plane;

    /** Inward unit normals of the edges within the plane, three doubles per edge. */
    private final double[] edgeNormals;
    /** The vertices' coordinates, three doubles per vertex. */
    final double[] vertexCoordinates;
    /** The largest edge length: the scale of the edge tolerance. */
    private final double size;

    /**
     * Creates a polygon from its vertices, in order around it.
     *
     * @param vertices at least three points, coplanar, forming a convex polygon
     * @throws IllegalArgumentException when there are fewer than three vertices, two neighbours
     *                                  coincide, a vertex lies on the edge of its neighbours, or
     *                                  the vertices are not coplanar or not convex
     */
    public Polygon(Point3D... vertices) {
        if (vertices == null || vertices.length < 3)
            throw new IllegalArgumentException("a polygon needs at least 3 vertices, got "
                    + (vertices == null ? 0 : vertices.length));
        for (int i = 0; i < vertices.length; ++i)
            requireNonNull(vertices[i], "polygon vertex " + i);
        this.vertices = List.of(vertices);
        Vector[] edges = edgesOf(vertices);
        this.size = maxLength(edges);
        Vector normal = edges[0].crossProduct(edges[1]).normalize();
        requireCoplanar(vertices, normal, size);
        requireConvex(edges, normal);
        this.plane = new Plane(vertices[0], normal);
        this.edgeNormals = inwardEdgeNormals(edges, normal);
        this.vertexCoordinates = new double[3 * vertices.length];
        for (int i = 0; i < vertices.length; ++i) {
            vertexCoordinates[3 * i] = vertices[i].getX();
            vertexCoordinates[3 * i + 1] = vertices[i].getY();
            vertexCoordinates[3 * i + 2] = vertices[i].getZ();
        }
    }

    /**
     * The edges, from each vertex to the next. Two neighbours coincide when they are closer than
     * {@link #EDGE_TOLERANCE} of the longest edge: the test is relative, so a polygon of any size is
     * judged by its shape.
     */
    static Vector[] edgesOf(Point3D[] vertices) {
        int n = vertices.length;
        double longest = 0;
        for (int i = 0; i < n; ++i)
            longest = Math.max(longest, vertices[i].distance(vertices[(i + 1) % n]));
        Vector[] edges = new Vector[n];
        for (int i = 0; i < n; ++i) {
            Point3D next = vertices[(i + 1) % n];
            if (vertices[i].distance(next) <= EDGE_TOLERANCE * longest)
                throw new IllegalArgumentException("polygon vertices " + i + " and " + (i + 1) % n + " coincide: " + next);
            edges[i] = next.subtract(vertices[i]);
        }
        for (int i = 0; i < n; ++i) {
            Vector e1 = edges[i];
            Vector e2 = edges[(i + 1) % n];
            double sin = crossLength(e1, e2) / (e1.length() * e2.length());
            if (isZero(sin))
                throw new IllegalArgumentException("polygon vertex " + (i + 1) % n + " " + vertices[(i + 1) % n]
                        + " lies on the line of its neighbours' edge (three consecutive vertices are collinear)");
        }
        return edges;
    }

    private static double crossLength(Vector a, Vector b) {
        double cx = a.getY() * b.getZ() - a.getZ() * b.getY();
        double cy = a.getZ() * b.getX() - a.getX() * b.getZ();
        double cz = a.getX() * b.getY() - a.getY() * b.getX();
        return Math.sqrt(cx * cx + cy * cy + cz * cz);
    }

    private static double maxLength(Vector[] edges) {
        double max = 0;
        for (Vector edge : edges)
            max = Math.max(max, edge.length());
        return max;
    }

    private static void requireCoplanar(Point3D[] vertices, Vector normal, double size) {
        for (int i = 3; i < vertices.length; ++i) {
            double distance = vertices[i].subtract(vertices[0]).dotProduct(normal);
            if (!isZero(distance / size))
                throw new IllegalArgumentException("polygon vertices are not coplanar: vertex " + i + " "
                        + vertices[i] + " is off the plane of the first three");
        }
    }

    /**
     * Every turn must go the same way around the normal, and the turns must add up to one full
     * circle (a star whose turns all go one way winds around twice).
     */
    private static void requireConvex(Vector[] edges, Vector normal) {
        double totalTurn = 0;
        for (int i = 0; i < edges.length; ++i) {
            Vector e1 = edges[i];
            Vector e2 = edges[(i + 1) % edges.length];
            double sin = e1.crossProduct(e2).dotProduct(normal);
            if (sin <= 0)
                throw new IllegalArgumentException("polygon is not convex: it turns the other way at vertex " + (i + 1) % edges.length);
            totalTurn += Math.atan2(sin, e1.dotProduct(e2));
        }
        if (Math.abs(totalTurn - 2 * Math.PI) > 1e-6)
            throw new IllegalArgumentException("polygon is not convex: its edges cross each other");
    }

    private static double[] inwardEdgeNormals(Vector[] edges, Vector normal) {
        double[] normals = new double[edges.length * 3];
        for (int i = 0; i < edges.length; ++i) {
            Vector inward = normal.crossProduct(edges[i]).normalize();
            normals[3 * i] = inward.getX();
            normals[3 * i + 1] = inward.getY();
            normals[3 * i + 2] = inward.getZ();
        }
        return normals;
    }

    /** {@return the vertices, in order} */
    public List<Point3D> getVertices() {
        return vertices;
    }

    /** {@return the plane the polygon lies in} */
    public Plane getPlane() {
        return plane;
    }

    @Override
    public Vector getNormal(Point3D point) {
        requireNonNull(point, "point");
        return plane.getNormal();
    }

    @Override
    protected boolean hasUV() {
        return true;
    }

    /**
     * {@inheritDoc} The point's position in the polygon's plane, in scene units, from its first vertex:
     * u along its first edge, v along normal × u (for a polygon counter-clockwise seen from its normal's
     * side, v points into it).
     */
    @Override
    public double[] getUV(Point3D point) {
        double ux = vertexCoordinates[3] - vertexCoordinates[0];
        double uy = vertexCoordinates[4] - vertexCoordinates[1];
        double uz = vertexCoordinates[5] - vertexCoordinates[2];
        double length = Math.sqrt(ux * ux + uy * uy + uz * uz);
        return Plane.planeUV(point, vertices.get(0), new double[] { ux / length, uy / length, uz / length },
                plane.getNormal());
    }

    /**
     * The course's query: the polygon is open, so a ray through an edge, a vertex or an edge's
     * continuation gives null.
     */
    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        double t = hitInside(toRayState(ray, maxDistance), EDGE_TOLERANCE * size);
        return t < NO_HIT ? List.of(new GeoPoint(this, ray.getPoint(t))) : null;
    }

    /** The renderer's path: the polygon is closed, so a ray through an edge or a vertex hits. */
    @Override
    public double nearestHit(RayState ray) {
        return hitInside(ray, -EDGE_TOLERANCE * size);
    }

    /**
     * The distance to where a ray crosses the polygon's plane, if that point lies at least a margin
     * inside every edge.
     *
     * @param ray    the ray
     * @param margin how far inside every edge's line the point must be: positive for the open polygon,
     *               negative for the closed one
     * @return the distance t in (0, maxT], or {@link #NO_HIT}
     */
    private double hitInside(RayState ray, double margin) {
        double t = plane.nearestHit(ray);
        if (t == NO_HIT)
            return NO_HIT;
        double px = ray.ox() + t * ray.dx();
        double py = ray.oy() + t * ray.dy();
        double pz = ray.oz() + t * ray.dz();
        for (int i = 0; i < vertexCoordinates.length; i += 3) {
            double inside = (px - vertexCoordinates[i]) * edgeNormals[i]
                    + (py - vertexCoordinates[i + 1]) * edgeNormals[i + 1]
                    + (pz - vertexCoordinates[i + 2]) * edgeNormals[i + 2];
            if (inside < margin)
                return NO_HIT;
        }
        return t;
    }

    @Override
    int hitCount(RayState ray) {
        return nearestHit(ray) < NO_HIT ? 1 : 0;
    }

    /**
     * The box around every point {@link #nearestHit} accepts: the polygon grown by the edge
     * tolerance. Its corners lie past the vertices, where the two shifted edge lines meet:
     * v − δ·(n₁ + n₂) / (1 + n₁·n₂) with n₁, n₂ the inward normals of the vertex's edges, farther
     * out at sharp vertices.
     */
    @Override
    public boolean bounds(double[] box, int b) {
        for (int k = 0; k < 3; ++k) {
            box[b + k] = Double.POSITIVE_INFINITY;
            box[b + 3 + k] = Double.NEGATIVE_INFINITY;
        }
        double delta = EDGE_TOLERANCE * size;
        int n = vertexCoordinates.length / 3;
        for (int i = 0; i < n; ++i) {
            int previous = 3 * ((i + n - 1) % n);
            int current = 3 * i;
            double cos = edgeNormals[previous] * edgeNormals[current]
                    + edgeNormals[previous + 1] * edgeNormals[current + 1]
                    + edgeNormals[previous + 2] * edgeNormals[current + 2];
            double reach = delta / (1 + cos);
            for (int k = 0; k < 3; ++k) {
                double corner = vertexCoordinates[current + k]
                        - reach * (edgeNormals[previous + k] + edgeNormals[current + k]);
                box[b + k] = Math.min(box[b + k], Math.min(corner, vertexCoordinates[current + k]));
                box[b + 3 + k] = Math.max(box[b + 3 + k], Math.max(corner, vertexCoordinates[current + k]));
            }
        }
        return true;
    }

    /** A polygon lies in its plane: it can meet a bundle only when its plane does. */
    @Override
    public boolean mayMeet(ShadowFrustum frustum) {
        return plane.mayMeet(frustum);
    }

    @Override
    public String toString() {
        return "Polygon" + vertices;
    }
}
