package accel;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

import geometries.TriangleMesh;
import primitives.Point3D;

/**
 * Caps over the small holes of an open part of a mesh (a scan's or a model's eyes, mouth, neck): a
 * hole is a connected set of the part's boundary edges, those its triangles use an odd number of
 * times, and its cap is the fan of triangles from the centroid of its vertices over those edges. Each
 * boundary edge is then used once more and each spoke of a fan twice (every vertex of a hole has an
 * even number of boundary edges, or the part is not capped), so the part and its caps close a volume,
 * with cores inside ({@link InnerBoxes}). The caps are not the mesh's and block nothing: a ray
 * through such a core that meets no cap's box still crosses the part's own triangles
 * ({@link ClosedMeshBlockers}).
 */
final class HoleCaps {
    /**
     * The largest hole capped, its box's longest side relative to the part's: an eye socket (a fifth of a
     * head) is capped, a larger hole's box would shut out most rays through the cores.
     */
    static final double MAX_HOLE = 0.25;
    /** How much a cap's box is grown, relative to the part's extent: it must hold every ray the renderer's test lets slip past the boundary. */
    private static final double GROW = 1e-6;
    /** The least sine of a cap triangle's angles: a flatter one would be refused as a mesh triangle. */
    private static final double MIN_SINE = 1e-6;

    /** The cap triangles: the hole's centroid (a place in {@link #centroids}), then the edge's two welded vertices. */
    final int[] triangles;
    /** The holes' centroids, three coordinates each. */
    final double[] centroids;
    /** The box around each hole's cap, grown, six numbers each. */
    final double[] boxes;

    private HoleCaps(int[] triangles, double[] centroids, double[] boxes) {
        this.triangles = triangles;
        this.centroids = centroids;
        this.boxes = boxes;
    }

    /**
     * The caps over the holes of a part of a mesh.
     *
     * @param mesh    the mesh
     * @param welded  per vertex, its welded vertex
     * @param indices the mesh's triangles' vertex indices, three per triangle
     * @param part    the part's triangles, connected, not closed
     * @return the caps, or null when a hole is too large, does not close, or its cap would be degenerate
     */
    static HoleCaps of(TriangleMesh mesh, int[] welded, int[] indices, int[] part) {
        long[] edges = boundaryEdges(welded, indices, part);
        Map<Integer, Integer> slots = new HashMap<>(); // boundary vertex -> its place
        for (long edge : edges) {
            slots.putIfAbsent((int) (edge >>> 32), slots.size());
            slots.putIfAbsent((int) edge, slots.size());
        }
        int[] parent = new int[slots.size()];
        int[] degree = new int[slots.size()];
        for (int s = 0; s < parent.length; ++s)
            parent[s] = s;
        for (long edge : edges) {
            int a = slots.get((int) (edge >>> 32));
            int b = slots.get((int) edge);
            ++degree[a];
            ++degree[b];
            ClosedParts.union(parent, a, b);
        }
        for (int d : degree)
            if (d % 2 != 0)
                return null;
        int[] hole = new int[parent.length]; // per vertex place, its hole
        Arrays.fill(hole, -1);
        int holes = 0;
        for (int s = 0; s < parent.length; ++s) {
            int r = ClosedParts.root(parent, s);
            hole[s] = hole[r] >= 0 ? hole[r] : (hole[r] = holes++);
        }
        double[] centroids = new double[3 * holes];
        int[] counts = new int[holes];
        double[] boxes = Boxes.empty(holes);
        for (Map.Entry<Integer, Integer> vertex : slots.entrySet()) {
            int h = hole[vertex.getValue()];
            Point3D p = mesh.getVertex(vertex.getKey());
            add(centroids, boxes, h, p.getX(), p.getY(), p.getZ());
            ++counts[h];
        }
        for (int h = 0; h < holes; ++h)
            for (int k = 0; k < 3; ++k)
                centroids[3 * h + k] /= counts[h];
        int[] triangles = new int[3 * edges.length];
        for (int e = 0; e < edges.length; ++e) {
            int a = (int) (edges[e] >>> 32);
            triangles[3 * e] = hole[slots.get(a)];
            triangles[3 * e + 1] = a;
            triangles[3 * e + 2] = (int) edges[e];
        }
        HoleCaps caps = new HoleCaps(triangles, centroids, boxes);
        double[] meshBox = new double[6];
        mesh.bounds(meshBox, 0);
        // the mesh's box first, at once: a part with a wide hole (a terrain's rim) stops there
        return caps.small(meshBox) && caps.fits(mesh, boxOf(mesh, part)) ? caps : null;
    }

    /** {@return the part's edges used an odd number of times, sorted (see {@link ClosedParts#sortedEdges})} */
    private static long[] boundaryEdges(int[] welded, int[] indices, int[] part) {
        long[] edges = ClosedParts.sortedEdges(welded, indices, part);
        long[] odd = new long[edges.length];
        int count = 0;
        for (int i = 0; i < edges.length; ) {
            int j = i;
            while (j < edges.length && edges[j] == edges[i])
                ++j;
            if ((j - i) % 2 != 0)
                odd[count++] = edges[i];
            i = j;
        }
        return Arrays.copyOf(odd, count);
    }

    /** Adds a vertex of hole h to the sums of the centroids and to the hole's box. */
    private static void add(double[] centroids, double[] boxes, int h, double x, double y, double z) {
        centroids[3 * h] += x;
        centroids[3 * h + 1] += y;
        centroids[3 * h + 2] += z;
        Boxes.include(boxes, 6 * h, x, y, z);
    }

    /** {@return whether every hole is small next to a box (the holes' boxes not grown yet)} */
    private boolean small(double[] box) {
        double limit = MAX_HOLE * Boxes.extent(box, 0);
        for (int b = 0; b < boxes.length; b += 6)
            for (int k = 0; k < 3; ++k)
                if (boxes[b + 3 + k] - boxes[b + k] > limit)
                    return false;
        return true;
    }

    /**
     * Whether every hole is small next to the part and every cap triangle well shaped; grows the
     * holes' boxes (which hold their centroids, the mean of their vertices) by the rounding margin.
     */
    private boolean fits(TriangleMesh mesh, double[] partBox) {
        if (!small(partBox))
            return false;
        Boxes.pad(boxes, GROW * Boxes.extent(partBox, 0));
        for (int t = 0; t < triangles.length; t += 3)
            if (!wellShaped(centroidOf(triangles[t]), mesh.getVertex(triangles[t + 1]), mesh.getVertex(triangles[t + 2])))
                return false;
        return true;
    }

    /** {@return the box around some of a mesh's triangles} */
    private static double[] boxOf(TriangleMesh mesh, int[] triangles) {
        double[] box = Boxes.empty(1);
        double[] one = new double[6];
        for (int t : triangles) {
            mesh.bounds(t, one, 0);
            Boxes.grow(box, 0, one, 0);
        }
        return box;
    }

    /** {@return the centroid of hole h} */
    Point3D centroidOf(int h) {
        return new Point3D(centroids[3 * h], centroids[3 * h + 1], centroids[3 * h + 2]);
    }

    /** {@return whether no two of a triangle's vertices coincide and none of its angles is nearly flat} */
    private static boolean wellShaped(Point3D a, Point3D b, Point3D c) {
        double[][] v = { { a.getX(), a.getY(), a.getZ() }, { b.getX(), b.getY(), b.getZ() },
                { c.getX(), c.getY(), c.getZ() } };
        for (int i = 0; i < 3; ++i) {
            double[] p = v[i];
            double[] q = v[(i + 1) % 3];
            double[] r = v[(i + 2) % 3];
            double ux = q[0] - p[0];
            double uy = q[1] - p[1];
            double uz = q[2] - p[2];
            double wx = r[0] - p[0];
            double wy = r[1] - p[1];
            double wz = r[2] - p[2];
            double cx = uy * wz - uz * wy;
            double cy = uz * wx - ux * wz;
            double cz = ux * wy - uy * wx;
            double lengths = Math.sqrt((ux * ux + uy * uy + uz * uz) * (wx * wx + wy * wy + wz * wz));
            if (!(Math.sqrt(cx * cx + cy * cy + cz * cz) > MIN_SINE * lengths))
                return false;
        }
        return true;
    }
}
