package accel;

import geometries.Geometry;
import geometries.TriangleMesh;
import java.util.Arrays;
import java.util.Comparator;
import java.util.stream.IntStream;

import primitives.Parallel;

/**
 * The top-down build by the binned surface-area heuristic: bodies are reordered so every leaf
 * holds a run of them. The top of the tree is split on the calling thread down to subtrees of at
 * most a share of the bodies; these are built side by side, largest first, each into node arrays
 * of its own, and then copied after the top's nodes. A split depends only on the bodies of its
 * node, so the tree is the same whatever the number of threads: only where its nodes lie in the
 * arrays differs. Everything lives in flat arrays; nothing is allocated per body or per node.
 * The bodies' boxes and centroids move with them when they are partitioned, so every pass over a
 * node's bodies reads memory in order; a child's box and the box around its centroids come from
 * the bins of its parent's split.
 */
final class BvhBuilder {
    private static final int BINS = 16;
    private static final int MAX_LEAF_SIZE = 4;
    private static final int MAX_DEPTH = 64;
    /** The cost of visiting a node, relative to testing one body, in the surface-area heuristic. */
    private static final double TRAVERSAL_COST = 1.0;
    /** Boxes grow by this fraction of their size (plus an absolute bit) so flat bodies are hit. */
    private static final double PADDING = 1e-9;
    /** The name of the threads that share the build's work. */
    static final String BUILD_THREADS = "hierarchy-build";
    /** The bodies of one chunk of the work shared out among threads during the build. */
    private static final int CHUNK = 8192;
    /**
     * About how many nodes a tree has per body, with a little to spare: a fresh array is zeroed,
     * so room for nodes that are never used costs time (a tree of leaves of up to
     * {@value #MAX_LEAF_SIZE} bodies has 0.5 to 0.6 nodes per body).
     */
    private static final double NODES_PER_BODY = 0.75;
    /** Each thread gets about this many subtrees, so that one large subtree does not hold up the rest. */
    private static final int SUBTREES_PER_THREAD = 4;

    final Geometry[] owners;
    private final int threads;
    /**
     * The padded box and the centroid of every body, in the order of {@link #order}: once built,
     * the boxes are in leaf order, a result.
     */
    final double[] boxes;
    private final double[] centroids;
    /**
     * The bodies: each one's geometry (its place in {@link #owners}) and its part (a mesh's
     * triangle, or −1), partitioned into leaf order: results.
     */
    final int[] order;
    final int[] parts;
    /** The subtrees left for the threads, four ints each: node, first body, end, level. */
    private int[] subtrees = new int[4 * SUBTREES_PER_THREAD];
    private int subtreesCount;
    /** The nodes and the depth: the results, with the padded boxes of the bodies in leaf order. */
    double[] nodeBounds;
    int[] nodeLinks;
    int nodesCount;
    int depth;

    BvhBuilder(Geometry[] owners, int threads) {
        this.owners = owners;
        this.threads = threads;
        int count = 0;
        for (Geometry owner : owners)
            count += owner instanceof TriangleMesh mesh ? mesh.getTrianglesCount() : 1;
        this.boxes = new double[6 * count];
        this.centroids = new double[3 * count];
        this.order = new int[count];
        this.parts = new int[count];
        this.nodeBounds = new double[0];
        this.nodeLinks = new int[0];
        int i = 0;
        for (int o = 0; o < owners.length; ++o) {
            if (owners[o] instanceof TriangleMesh mesh)
                for (int t = 0; t < mesh.getTrianglesCount(); ++t, ++i) {
                    order[i] = o;
                    parts[i] = t;
                }
            else {
                order[i] = o;
                parts[i++] = -1;
            }
        }
    }

    void build() {
        int count = order.length;
        if (count == 0)
            return;
        runInChunks(count, threads, this::measure);
        Splitter top = new Splitter(1, threads == 1 ? count : count / (SUBTREES_PER_THREAD * threads));
        top.splitRoot(0, 0, count, 1);
        Splitter[] parts = new Splitter[subtreesCount];
        int[] largestFirst = IntStream.range(0, subtreesCount).boxed()
                .sorted(Comparator.comparingInt(t -> subtrees[4 * t + 1] - subtrees[4 * t + 2]))
                .mapToInt(Integer::intValue).toArray();
        Parallel.forEach(subtreesCount, threads, BUILD_THREADS, k -> {
            int t = largestFirst[k];
            parts[t] = new Splitter(subtrees[4 * t + 2] - subtrees[4 * t + 1], 0);
            parts[t].splitRoot(0, subtrees[4 * t + 1], subtrees[4 * t + 2], subtrees[4 * t + 3]);
        });
        depth = top.depth;
        for (Splitter part : parts)
            depth = Math.max(depth, part.depth);
        assemble(top, parts);
    }

    /** Sets the padded boxes and the centroids of bodies [from, to). */
    private void measure(int from, int to) {
        for (int i = from; i < to; ++i) {
            if (parts[i] < 0)
                owners[order[i]].bounds(boxes, 6 * i);
            else
                ((TriangleMesh) owners[order[i]]).bounds(parts[i], boxes, 6 * i);
            for (int k = 0; k < 3; ++k)
                centroids[3 * i + k] = (boxes[6 * i + k] + boxes[6 * i + 3 + k]) / 2;
            pad(boxes, 6 * i);
        }
    }

    /** Leaves the subtree of node over bodies [start, end) for the threads. */
    private void defer(int node, int start, int end, int level) {
        if (4 * subtreesCount == subtrees.length)
            subtrees = Arrays.copyOf(subtrees, 2 * subtrees.length);
        subtrees[4 * subtreesCount] = node;
        subtrees[4 * subtreesCount + 1] = start;
        subtrees[4 * subtreesCount + 2] = end;
        subtrees[4 * subtreesCount + 3] = level;
        ++subtreesCount;
    }

    /**
     * Sets the nodes: the top's, then each subtree's below its root, which takes the place the
     * top left for it.
     *
     * @param top   the top of the tree
     * @param parts the subtrees, in the order they were left for the threads
     */
    private void assemble(Splitter top, Splitter[] parts) {
        nodesCount = top.next;
        for (Splitter part : parts)
            nodesCount += part.next - 1;
        nodeBounds = new double[6 * nodesCount];
        nodeLinks = new int[2 * nodesCount];
        System.arraycopy(top.bounds, 0, nodeBounds, 0, 6 * top.next);
        System.arraycopy(top.links, 0, nodeLinks, 0, 2 * top.next);
        int free = top.next;
        for (int t = 0; t < parts.length; ++t) {
            place(parts[t], 0, subtrees[4 * t], free);
            for (int node = 1; node < parts[t].next; ++node)
                place(parts[t], node, free + node - 1, free);
            free += parts[t].next - 1;
        }
    }

    /**
     * Copies a node of a subtree into the tree.
     *
     * @param part   the subtree
     * @param node   the node in the subtree
     * @param target the node in the tree
     * @param first  where the subtree's node 1 goes in the tree (its nodes after the root follow)
     */
    private void place(Splitter part, int node, int target, int first) {
        System.arraycopy(part.bounds, 6 * node, nodeBounds, 6 * target, 6);
        int link = part.links[2 * node];
        int count = part.links[2 * node + 1];
        nodeLinks[2 * target] = count < 0 ? first + link - 1 : link;
        nodeLinks[2 * target + 1] = count;
    }

    /** One thread's part of the build: its scratch space, and where its next nodes go. */
    private final class Splitter {
        /** Subtrees of at most this many bodies are left for the threads (0: none is). */
        private final int limit;
        /** The splitter's nodes, node 0 its root, in the layout of the tree's, and the next free one. */
        private double[] bounds;
        private int[] links;
        private int next = 1;
        private int depth;
        private final int[] binCounts = new int[BINS];
        private final double[] binBoxes = new double[6 * BINS];
        private final double[] binCentroids = new double[6 * BINS];
        private final double[] rightAreas = new double[BINS];
        private final double[] sweep = new double[6];
        /** The boxes around the centroids of the two children of a node at each level. */
        private final double[] centroidBoxes = new double[12 * (MAX_DEPTH + 2)];

        /**
         * Creates a splitter.
         *
         * @param bodies about how many bodies it splits: its first room for nodes is for
         *               {@link #NODES_PER_BODY} nodes per body (it grows when more are needed)
         * @param limit  subtrees of at most this many bodies are left for the threads (0: none is)
         */
        Splitter(int bodies, int limit) {
            int nodes = Math.max(1, (int) (NODES_PER_BODY * bodies));
            this.bounds = new double[6 * nodes];
            this.links = new int[2 * nodes];
            this.limit = limit;
        }

        /** {@link #split} for a node whose box is not known yet. */
        void splitRoot(int node, int start, int end, int level) {
            if (deferred(node, start, end, level))
                return;
            int c = 12 * level;
            enclose(node, start, end, c);
            split(node, start, end, level, c);
        }

        /** Leaves the subtree of node over bodies [start, end) for the threads when it is small enough. */
        private boolean deferred(int node, int start, int end, int level) {
            if (end - start > limit)
                return false;
            defer(node, start, end, level);
            return true;
        }

        /** Makes room for two more nodes. */
        private void growNodes() {
            if (2 * (next + 2) > links.length) {
                int nodes = 2 * (next + 2);
                bounds = Arrays.copyOf(bounds, 6 * nodes);
                links = Arrays.copyOf(links, 2 * nodes);
            }
        }

        /**
         * Makes node the parent of bodies [start, end), splitting it further while that pays off.
         *
         * @param c where the box around the bodies' centroids lies in {@link #centroidBoxes}
         */
        private void split(int node, int start, int end, int level, int c) {
            if (deferred(node, start, end, level))
                return;
            int count = end - start;
            depth = Math.max(depth, level);
            int axis = Boxes.widestAxis(centroidBoxes, c);
            double low = centroidBoxes[c + axis];
            double extent = centroidBoxes[c + 3 + axis] - low;
            double binsPerUnit = BINS / extent;
            int bin = count <= MAX_LEAF_SIZE || level >= MAX_DEPTH || !(extent > 0) ? -1
                    : bestSplit(node, start, end, axis, low, binsPerUnit);
            if (bin < 0) {
                links[2 * node] = start;
                links[2 * node + 1] = count;
                return;
            }
            int middle = partition(start, end, axis, low, binsPerUnit, bin);
            growNodes();
            int left = next;
            next += 2;
            links[2 * node] = left;
            links[2 * node + 1] = -1 - axis;
            int leftCentroids = 12 * (level + 1);
            int rightCentroids = leftCentroids + 6;
            unionOfBins(binBoxes, 0, bin + 1, bounds, 6 * left);
            unionOfBins(binBoxes, bin + 1, BINS, bounds, 6 * left + 6);
            unionOfBins(binCentroids, 0, bin + 1, centroidBoxes, leftCentroids);
            unionOfBins(binCentroids, bin + 1, BINS, centroidBoxes, rightCentroids);
            split(left, start, middle, level + 1, leftCentroids);
            split(left + 1, middle, end, level + 1, rightCentroids);
        }

        /** Sets a node's box around bodies [start, end) and the box at c around their centroids. */
        private void enclose(int node, int start, int end, int c) {
            int b = 6 * node;
            Boxes.clear(bounds, b);
            Boxes.clear(centroidBoxes, c);
            for (int i = start; i < end; ++i) {
                Boxes.grow(bounds, b, boxes, 6 * i);
                growByPoint(centroidBoxes, c, i);
            }
        }

        /** Grows the box at b around the centroid of the body at place i. */
        private void growByPoint(double[] box, int b, int i) {
            Boxes.include(box, b, centroids[3 * i], centroids[3 * i + 1], centroids[3 * i + 2]);
        }

        /** Sets the box at b of target around the boxes of bins [from, to) of bins. */
        private void unionOfBins(double[] bins, int from, int to, double[] target, int b) {
            Boxes.clear(target, b);
            for (int k = from; k < to; ++k)
                Boxes.grow(target, b, bins, 6 * k);
        }

        private int binOf(int i, int axis, double low, double binsPerUnit) {
            return Math.min(BINS - 1, (int) ((centroids[3 * i + axis] - low) * binsPerUnit));
        }

        /**
         * The bin after which splitting costs least by the surface-area heuristic, or -1 when no split
         * is cheaper than a leaf. Leaves the bins' bodies counted and their boxes and the boxes
         * around their centroids set.
         */
        private int bestSplit(int node, int start, int end, int axis, double low, double binsPerUnit) {
            Arrays.fill(binCounts, 0);
            for (int k = 0; k < BINS; ++k) {
                Boxes.clear(binBoxes, 6 * k);
                Boxes.clear(binCentroids, 6 * k);
            }
            for (int i = start; i < end; ++i) {
                int k = binOf(i, axis, low, binsPerUnit);
                ++binCounts[k];
                Boxes.grow(binBoxes, 6 * k, boxes, 6 * i);
                growByPoint(binCentroids, 6 * k, i);
            }
            Boxes.clear(sweep, 0);
            for (int k = BINS - 1; k > 0; --k) {
                Boxes.grow(sweep, 0, binBoxes, 6 * k);
                rightAreas[k] = Boxes.halfArea(sweep, 0);
            }
            Boxes.clear(sweep, 0);
            int leftCount = 0;
            int best = -1;
            // split when TRAVERSAL_COST·A + Σ n·A(child) beats the leaf's count·A
            double bestCost = (end - start - TRAVERSAL_COST) * Boxes.halfArea(bounds, 6 * node);
            for (int k = 0; k < BINS - 1; ++k) {
                Boxes.grow(sweep, 0, binBoxes, 6 * k);
                leftCount += binCounts[k];
                int rightCount = end - start - leftCount;
                if (leftCount == 0 || rightCount == 0)
                    continue;
                double cost = leftCount * Boxes.halfArea(sweep, 0) + rightCount * rightAreas[k + 1];
                if (cost < bestCost) {
                    bestCost = cost;
                    best = k;
                }
            }
            return best;
        }

        /**
         * Moves the bodies of bins up to and including bin to the front, their boxes and centroids
         * with them; returns where the rest start.
         */
        private int partition(int start, int end, int axis, double low, double binsPerUnit, int bin) {
            int i = start;
            int j = end - 1;
            while (i <= j) {
                if (binOf(i, axis, low, binsPerUnit) <= bin)
                    ++i;
                else
                    swap(i, j--);
            }
            return i;
        }

        /** Swaps the bodies at places i and j, with their boxes and centroids. */
        private void swap(int i, int j) {
            int owner = order[i];
            order[i] = order[j];
            order[j] = owner;
            int part = parts[i];
            parts[i] = parts[j];
            parts[j] = part;
            swapRun(boxes, 6 * i, 6 * j, 6);
            swapRun(centroids, 3 * i, 3 * j, 3);
        }

        private void swapRun(double[] values, int a, int b, int length) {
            for (int k = 0; k < length; ++k) {
                double value = values[a + k];
                values[a + k] = values[b + k];
                values[b + k] = value;
            }
        }
    }

    /**
     * Grows a body's box by {@link #PADDING}, so that flat bodies are hit.
     *
     * @param box the array
     * @param b   where the box lies in it
     */
    private static void pad(double[] box, int b) {
        for (int k = 0; k < 3; ++k) {
            double low = box[b + k];
            double high = box[b + 3 + k];
            double pad = PADDING * (1 + Math.abs(low) + Math.abs(high));
            box[b + k] = low - pad;
            box[b + 3 + k] = high + pad;
        }
    }

    /**
     * Runs a job over ranges [from, to) of count items, a chunk at a time, on up to threads threads.
     *
     * @param count   the number of items
     * @param threads the number of threads
     * @param job     the job, called with each chunk's first item and one past its last
     */
    static void runInChunks(int count, int threads, ChunkJob job) {
        int chunks = (count + CHUNK - 1) / CHUNK;
        Parallel.forEach(chunks, threads, BUILD_THREADS, c -> job.run(c * CHUNK, Math.min(count, (c + 1) * CHUNK)));
    }

    /** A job over a range of items, see {@link #runInChunks}. */
    @FunctionalInterface
    interface ChunkJob {
        void run(int from, int to);
    }
}
