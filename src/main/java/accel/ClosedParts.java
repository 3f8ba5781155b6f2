package accel;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.WeakHashMap;

import geometries.TriangleMesh;
import primitives.Point3D;

/**
 * The closed parts of a triangle mesh, each with its inner boxes: a mesh of several bodies (M's three
 * spheres as one mesh, a scan whose seams repeat their vertices) blocks whole bundles part by part.
 * <p>
 * Vertices with the same coordinates, to the bit, are welded into one: the renderer's triangle test
 * reads coordinates, not indices, so two triangles meeting at welded vertices share an edge exactly
 * as two sharing indices do. The triangles then fall into connected parts (union–find over their
 * welded corners); a part is closed when each of its edges is used by an even number of its
 * triangles, and a segment from inside a closed part to outside it crosses that part's surface,
 * whatever the mesh's other parts do. A part with a few small holes is closed by caps over them
 * ({@link HoleCaps}), which a segment must then miss. Each mesh's parts are found once and kept,
 * weakly, for as long as the mesh lives.
 */
final class ClosedParts {
    /** The fewest triangles a closed part has: a tetrahedron's. */
    private static final int MIN_TRIANGLES = 4;
    /** Each mesh's closed parts with a core, found on the first {@link #of} (weak keys: no leak). */
    private static final Map<TriangleMesh, List<Part>> FOUND = Collections.synchronizedMap(new WeakHashMap<>());

    /**
     * A closed part of a mesh: its triangles, its cores (its inner boxes) and the box around its
     * triangles.
     *
     * @param triangles  the part's triangles in the mesh, in order
     * @param box        the box around the part's triangles, as {@link TriangleMesh#bounds(double[], int)} writes it
     * @param innerBoxes the part's inner boxes ({@link InnerBoxes}), six numbers each, at least one
     * @param capBoxes   the boxes of the caps over the part's holes ({@link HoleCaps}), six numbers
     *                   each, none for a part closed by itself: a ray that meets none of them and
     *                   passes through a core crosses the part's triangles
     */
    record Part(int[] triangles, double[] box, double[] innerBoxes, double[] capBoxes) {
        /** {@return the size of the part's largest core: half the shortest side of its largest inner box} */
        double coreSize() {
            double size = 0;
            for (int b = 0; b < innerBoxes.length; b += 6)
                size = Math.max(size, InnerBoxes.halfShortestSide(innerBoxes, b));
            return size;
        }
    }

    /** Not instantiable. */
    private ClosedParts() {
    }

    /**
     * The closed parts of a mesh that have a core (an inner box), found on the first call and kept.
     *
     * @param mesh the mesh
     * @return its parts (none for a mesh without a closed part), not to be changed
     */
    static List<Part> of(TriangleMesh mesh) {
        List<Part> parts = FOUND.get(mesh);
        if (parts == null) {
            parts = find(mesh);
            FOUND.put(mesh, parts);
        }
        return parts;
    }

    /** {@return the closed parts of a mesh with a core, found anew} */
    private static List<Part> find(TriangleMesh mesh) {
        int[] welded = weld(mesh);
        int[] indices = mesh.indices();
        int[] partOf = connectedParts(welded, indices);
        List<Part> parts = new ArrayList<>();
        int[] renumbered = new int[welded.length];
        Arrays.fill(renumbered, -1);
        for (int[] triangles : partsToClose(welded, partOf)) {
            HoleCaps caps = null;
            if (!isClosed(welded, indices, triangles)) {
                caps = HoleCaps.of(mesh, welded, indices, triangles);
                if (caps == null)
                    continue;
            }
            TriangleMesh part = subMesh(mesh, welded, triangles, caps, renumbered);
            double[] innerBoxes = InnerBoxes.of(part);
            if (innerBoxes.length > 0) {
                double[] box = new double[6];
                part.bounds(box, 0);
                parts.add(new Part(triangles, box, innerBoxes, caps == null ? new double[0] : caps.boxes));
            }
        }
        return List.copyOf(parts);
    }

    /**
     * Welds the vertices of a mesh that have the same coordinates, to the bit: an open-addressing
     * table of the vertices by their coordinates' bits.
     *
     * @param mesh the mesh
     * @return per vertex, the first vertex with its coordinates
     */
    static int[] weld(TriangleMesh mesh) {
        int count = mesh.getVerticesCount();
        long[] bits = new long[3 * count];
        for (int v = 0; v < count; ++v) {
            Point3D p = mesh.getVertex(v);
            bits[3 * v] = Double.doubleToLongBits(p.getX());
            bits[3 * v + 1] = Double.doubleToLongBits(p.getY());
            bits[3 * v + 2] = Double.doubleToLongBits(p.getZ());
        }
        int[] table = new int[Integer.highestOneBit(Math.max(2 * count, 2)) << 1];
        Arrays.fill(table, -1);
        int mask = table.length - 1;
        int[] welded = new int[count];
        for (int v = 0; v < count; ++v) {
            int slot = (int) mix(bits[3 * v] ^ 31 * (bits[3 * v + 1] ^ 31 * bits[3 * v + 2])) & mask;
            while (table[slot] >= 0 && !sameBits(bits, table[slot], v))
                slot = slot + 1 & mask;
            if (table[slot] < 0)
                table[slot] = v;
            welded[v] = table[slot];
        }
        return welded;
    }

    private static boolean sameBits(long[] bits, int a, int b) {
        return bits[3 * a] == bits[3 * b] && bits[3 * a + 1] == bits[3 * b + 1] && bits[3 * a + 2] == bits[3 * b + 2];
    }

    /**
     * Numbers the connected parts of a mesh's triangles: two triangles are in one part when a chain of
     * triangles sharing welded vertices joins them.
     *
     * @param welded  per vertex, its welded vertex
     * @param indices the triangles' vertex indices, three per triangle
     * @return per triangle, its part: the root of its corners' set
     */
    private static int[] connectedParts(int[] welded, int[] indices) {
        int[] parent = new int[welded.length];
        for (int v = 0; v < parent.length; ++v)
            parent[v] = v;
        for (int i = 0; i < indices.length; i += 3) {
            union(parent, welded[indices[i]], welded[indices[i + 1]]);
            union(parent, welded[indices[i]], welded[indices[i + 2]]);
        }
        int[] partOf = new int[indices.length / 3];
        for (int t = 0; t < partOf.length; ++t)
            partOf[t] = root(parent, welded[indices[3 * t]]);
        return partOf;
    }

    /** Joins the sets of two vertices (union–find). */
    static void union(int[] parent, int a, int b) {
        int ra = root(parent, a);
        int rb = root(parent, b);
        if (ra != rb)
            parent[Math.max(ra, rb)] = Math.min(ra, rb);
    }

    /** {@return the root of a vertex's set, halving the path on the way} */
    static int root(int[] parent, int v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    }

    /**
     * The connected parts of a mesh large enough to close a volume.
     *
     * @param welded per vertex, its welded vertex
     * @param partOf per triangle, its part
     * @return the triangles of each part of {@value #MIN_TRIANGLES} or more, in order
     */
    private static List<int[]> partsToClose(int[] welded, int[] partOf) {
        int[] sizes = new int[welded.length];
        for (int part : partOf)
            ++sizes[part];
        // the triangles grouped by part (a counting sort), only for parts large enough
        int[] start = new int[welded.length + 1];
        for (int p = 0; p < welded.length; ++p)
            start[p + 1] = start[p] + (sizes[p] >= MIN_TRIANGLES ? sizes[p] : 0);
        int[] grouped = new int[start[welded.length]];
        int[] next = Arrays.copyOf(start, welded.length);
        for (int t = 0; t < partOf.length; ++t)
            if (start[partOf[t] + 1] > start[partOf[t]])
                grouped[next[partOf[t]]++] = t;
        List<int[]> parts = new ArrayList<>();
        for (int p = 0; p < welded.length; ++p)
            if (start[p + 1] > start[p])
                parts.add(Arrays.copyOfRange(grouped, start[p], start[p + 1]));
        return parts;
    }

    /**
     * Whether some triangles are closed: every edge, by vertex, used an even number of times. An
     * exclusive or of the edges' mixed keys sets most open sets aside in one pass (an edge used an even
     * number of times cancels out); only sets that pass it have their edges sorted and counted.
     *
     * @param vertexOf  per vertex index, the vertex it stands for (itself, or its welded vertex)
     * @param indices   the triangles' vertex indices, three per triangle
     * @param triangles the triangles
     * @return true when every edge is used an even number of times
     */
    static boolean isClosed(int[] vertexOf, int[] indices, int[] triangles) {
        long mixed = 0;
        for (int t : triangles)
            for (int k = 0; k < 3; ++k)
                mixed ^= mix(edgeKey(vertexOf, indices, 3 * t + k));
        if (mixed != 0)
            return false;
        long[] edges = sortedEdges(vertexOf, indices, triangles);
        for (int i = 0; i < edges.length; i += 2)
            if (edges[i] != edges[i + 1])
                return false;
        return true;
    }

    /**
     * The edges of some triangles, by vertex, sorted: each the smaller vertex in the high bits and the
     * larger in the low ones, once per triangle that uses it.
     *
     * @param vertexOf  per vertex index, the vertex it stands for (itself, or its welded vertex)
     * @param indices   the triangles' vertex indices, three per triangle
     * @param triangles the triangles
     * @return their edges' keys, sorted
     */
    static long[] sortedEdges(int[] vertexOf, int[] indices, int[] triangles) {
        long[] edges = new long[3 * triangles.length];
        for (int i = 0; i < triangles.length; ++i)
            for (int k = 0; k < 3; ++k)
                edges[3 * i + k] = edgeKey(vertexOf, indices, 3 * triangles[i] + k);
        Arrays.sort(edges);
        return edges;
    }

    /** {@return a key's bits well mixed (SplitMix64's finaliser), so different keys rarely cancel} */
    static long mix(long key) {
        long z = key + 0x9E3779B97F4A7C15L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** {@return the key of the edge from corner i to the next corner of its triangle, by vertex, either way round} */
    private static long edgeKey(int[] vertexOf, int[] indices, int i) {
        int a = vertexOf[indices[i]];
        int b = vertexOf[indices[i % 3 == 2 ? i - 2 : i + 1]];
        return (long) Math.min(a, b) << 32 | Math.max(a, b);
    }

    /**
     * The mesh of some of a mesh's triangles over its welded vertices, each corner in its order, and
     * of the caps over their holes.
     *
     * @param mesh       the mesh
     * @param welded     per vertex, its welded vertex
     * @param triangles  the triangles
     * @param caps       the caps over their holes, or null
     * @param renumbered scratch space, per welded vertex −1, as it is left again: a mesh's parts are
     *                   many, and most are small
     * @return the part's own mesh (its vertices the same doubles), closed when capped
     */
    private static TriangleMesh subMesh(TriangleMesh mesh, int[] welded, int[] triangles, HoleCaps caps,
            int[] renumbered) {
        int capCount = caps == null ? 0 : caps.triangles.length / 3;
        int holes = caps == null ? 0 : caps.centroids.length / 3;
        double[] vertices = new double[9 * triangles.length + 3 * holes];
        int[] indices = new int[3 * (triangles.length + capCount)];
        int count = 0;
        for (int i = 0; i < triangles.length; ++i)
            for (int k = 0; k < 3; ++k) {
                int v = welded[mesh.getVertexIndex(triangles[i], k)];
                if (renumbered[v] < 0) {
                    Point3D p = mesh.getVertex(v);
                    vertices[3 * count] = p.getX();
                    vertices[3 * count + 1] = p.getY();
                    vertices[3 * count + 2] = p.getZ();
                    renumbered[v] = count++;
                }
                indices[3 * i + k] = renumbered[v];
            }
        if (caps != null) {
            System.arraycopy(caps.centroids, 0, vertices, 3 * count, 3 * holes);
            for (int c = 0; c < capCount; ++c) {
                int at = 3 * (triangles.length + c);
                indices[at] = count + caps.triangles[3 * c];
                indices[at + 1] = renumbered[caps.triangles[3 * c + 1]];
                indices[at + 2] = renumbered[caps.triangles[3 * c + 2]];
            }
            count += holes;
        }
        for (int i = 0; i < triangles.length; ++i)
            for (int k = 0; k < 3; ++k)
                renumbered[welded[mesh.getVertexIndex(triangles[i], k)]] = -1;
        return new TriangleMesh(Arrays.copyOf(vertices, 3 * count), indices);
    }
}
