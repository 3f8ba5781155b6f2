package accel;

import geometries.TriangleMesh;
import geometries.Triangle;
import geometries.Intersectable;
import geometries.Geometry;
import geometries.Geometries;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.stream.IntStream;

import geometries.Intersectable.GeoPoint;
import primitives.Parallel;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

import static primitives.Util.requireNonNull;

/**
 * A bounding volume hierarchy over the bodies of a composite, the way a ray tracer finds what a ray
 * hits without testing every body. Built from the scene's {@link Geometries}, which stays the
 * user-facing composite, once per scene: again only when bodies are added (see {@link #isBuiltFrom}).
 * The build can share its work among threads ({@link #build(Intersectable, int)}).
 * <p>
 * The tree lives in flat arrays (a node's box, its first body or first child, its body count and
 * split axis; the two children of a node are neighbours) and is walked with an explicit stack: at an
 * inner node both children's boxes are tested, and the nearer child (by the split axis) is entered
 * first. It is built top down with the binned surface-area heuristic. A {@link TriangleMesh} gives
 * the tree one body per triangle, held by reference (the mesh and the triangle's index, two ints,
 * and its box in floats), with no object and no copy of its vertices per triangle: a single ray
 * tests the tree's triangles straight from the mesh's arrays, while a bundle copies the numbers of
 * each triangle's test once (a gathered triangle into the query, a packet's leaf triangle for the
 * leaf's rays). Other bodies (a {@link Triangle} object
 * among them) are tested through their own methods. Unbounded bodies (planes, tubes) stay outside the tree and are tested
 * on every ray, as are intersectables that are not {@link Geometry}s.
 * <p>
 * The shadow rays of one soft shadow can be traced as a bundle: {@link #gather} walks the tree once
 * with the bundle's pyramid (a {@link ShadowFrustum}) and keeps the few bodies that may meet it, or
 * their smallest subtree when they are many; {@link #gatheredTransmittance} then tests a ray against
 * those alone, and {@link #gatheredTransmittances} all the rays of the bundle at once, walking a kept
 * subtree as one packet. A closed opaque mesh whose inner ball ({@link InnerBall}) lies across every
 * ray of a bundle blocks the whole bundle at the gather ({@link #blocksBundle}), and a packet's ray
 * through such a ball is blocked before the walk.
 * <p>
 * Queries take a {@link Query}, the caller's per-thread scratch space, and allocate nothing but
 * the {@link GeoPoint} a closest-hit query returns.
 */
public final class BoundingVolumeHierarchy {
    private static final int BINS = 16;
    private static final int MAX_LEAF_SIZE = 4;
    private static final int MAX_DEPTH = 64;
    /** The cost of visiting a node, relative to testing one body, in the surface-area heuristic. */
    private static final double TRAVERSAL_COST = 1.0;
    /** Boxes grow by this fraction of their size (plus an absolute bit) so flat bodies are hit. */
    private static final double PADDING = 1e-9;
    /** The box around nothing, which any box grows: copied, never changed. */
    private static final double[] EMPTY_BOX = { Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY };
    /** What {@link #slabEntry} answers for a ray that misses the box: no entry distance is negative. */
    public static final double MISSED = -1;
    /** The most bodies of the tree a bundle of shadow rays is tested against one by one. */
    private static final int MAX_GATHERED = 32;
    /** The places of all gathered bodies, in order. */
    private static final int[] ALL_GATHERED = IntStream.range(0, MAX_GATHERED).toArray();
    /**
     * The numbers a gathered mesh triangle keeps for the bundle's rays: the ten of its test (see
     * {@link TriangleMesh#triangleData}) and its mesh's {@code kT}.
     */
    private static final int GATHERED_TRIANGLE = TriangleMesh.TRIANGLE_DATA + 1;

    /** The most closed meshes whose inner balls {@link #gather} tries: those of the largest balls. */
    private static final int MAX_SOLIDS = 16;
    /** The name of the threads that share the build's work. */
    private static final String BUILD_THREADS = "hierarchy-build";
    /** The bodies of one chunk of the work shared out among threads during the build. */
    private static final int CHUNK = 8192;

    /** The composite the hierarchy was built over, and the version of its contents then. */
    private final Intersectable source;
    private final long version;
    /** The geometries whose bodies are in the tree: each a body, or a mesh of many. */
    private final Geometry[] owners;
    /** Per body of the tree, in leaf order: its geometry in {@link #owners}. */
    private final int[] bodyOwner;
    /**
     * Per body of the tree, in leaf order: its triangle when its geometry is a mesh; else −1 − the
     * place of its box in {@link #wholeBounds}.
     */
    private final int[] bodyPart;
    /**
     * The padded boxes of the tree's bodies that are whole geometries, not a mesh's triangles (whose
     * boxes are in {@link #triangleBounds}).
     */
    private final double[] wholeBounds;
    /**
     * Per body of the tree that is a mesh's triangle, in leaf order: its padded box in floats, rounded
     * outward (so it holds the box in doubles), for {@link #bodyMeets}: half the memory of doubles.
     * A bundle may then gather a triangle more, never one less: every ray's answer stays the same.
     */
    private final float[] triangleBounds;
    private final Geometry[] unbounded;
    private final Intersectable[] others;
    /** Whether {@link #gather} culls bodies: false for the brute-force {@link #scan}. */
    private final boolean culling;
    /**
     * Per node: its box, in floats rounded outward like {@link #triangleBounds}: a ray or a bundle may
     * then enter a node more, never one less, so every answer stays the same, and the walks read half
     * the memory.
     */
    private final float[] nodeBounds;
    /**
     * Two ints per node: a leaf's first body and its body count (positive); an inner node's left
     * child (its right child is the node after it) and −1 − its split axis.
     */
    private final int[] nodeLinks;
    private final int nodesCount;
    private final int depth;
    /** The tree's closed meshes that have an inner ball, the largest balls first, their balls and their boxes. */
    private final TriangleMesh[] solids;
    private final InnerBall[] solidBalls;
    private final double[] solidBoxes;

    /**
     * Per-thread scratch space of queries: the traversal stack, the running result and a packet of
     * shadow rays. Get one from {@link #newQuery()} and use it on one thread at a time.
     */
    public static final class Query {
        private final int[] stack;
        /** Where the ray of a walk enters the box of each node on the stack. */
        private final double[] entries;
        private double maxT;
        private Geometry geometry;
        /** The part of {@link #geometry} hit (a mesh's triangle), or −1. */
        private int part;
        private double ktr;
        private final ShadowFrustum frustum = new ShadowFrustum();
        /**
         * The tree's bodies {@link #gather} found, in leaf order; a mesh's triangle is −1 here, its
         * numbers in {@link #gatheredTriangles}.
         */
        private final int[] gathered = new int[MAX_GATHERED];
        /** Per body {@link #gather} found that is a mesh's triangle, at its place: its {@value #GATHERED_TRIANGLE} numbers. */
        private final double[] gatheredTriangles = new double[GATHERED_TRIANGLE * MAX_GATHERED];
        /** How many bodies {@link #gather} found, or −1 when they were too many (a subtree was kept). */
        private int gatheredCount;
        /**
         * When the frustum's starts are set: per start of a ray, {@link ShadowFrustum#ABOVE} or
         * {@link ShadowFrustum#BELOW} as its {@link ShadowFrustum#startOf} tells, the places in
         * {@link #gathered} of the bodies a ray from there tests, in order (not the triangles behind
         * that start), and how many. Place 0 is not used: a ray from neither start tests them all.
         */
        private final int[][] startLists = new int[3][MAX_GATHERED];
        private final int[] startCounts = new int[3];
        /** When {@link #gather} found too many bodies: the node below which all of them lie. */
        private int subtree;
        /** The unbounded bodies {@link #gather} found, and how many. */
        private final Geometry[] gatheredUnbounded;
        private int unboundedCount;
        /** The first and the last ray of the packet that may meet each node on the stack of a packet walk. */
        private final int[] firstRays;
        private final int[] lastRays;
        /** The rays of the packet that meet the leaf a packet walk is at, in order. */
        private int[] rays = new int[0];
        /** A mesh's triangle's data (p1, e1, e2, the parallel limit), read once per leaf of a packet walk. */
        private final double[] triangle = new double[TriangleMesh.TRIANGLE_DATA];
        /** The rays of the packet: origins, unit directions, their inverses, distances and transparencies. */
        private double[] ox = new double[0];
        private double[] oy = ox;
        private double[] oz = ox;
        private double[] dx = ox;
        private double[] dy = ox;
        private double[] dz = ox;
        private double[] ix = ox;
        private double[] iy = ox;
        private double[] iz = ox;
        private double[] maxTs = ox;
        private double[] ktrs = ox;
        private int packetSize;
        /** The solids ({@link #solids}) {@link #gather} found across some of the bundle's rays, and how many. */
        private final int[] solidList = new int[MAX_SOLIDS];
        private int solidCount;
        /** Whether the last {@link #gather} tried the solids, and found one that blocks every ray of the bundle. */
        private boolean solidsTried;
        private boolean blocked;

        private Query(int stackSize, int unboundedLength) {
            this.stack = new int[stackSize];
            this.entries = new double[stackSize];
            this.firstRays = new int[stackSize];
            this.lastRays = new int[stackSize];
            this.gatheredUnbounded = new Geometry[unboundedLength];
        }

        /** {@return the pyramid of the shadow bundle the next {@link #gather} looks at} */
        public ShadowFrustum getFrustum() {
            return frustum;
        }

        /**
         * Whether the last {@link #gather} kept a subtree, its bodies too many to keep one by one: the
         * bundle's rays are then best traced together, by {@link #gatheredTransmittances}.
         *
         * @return true when a subtree was kept
         */
        public boolean isSubtreeGathered() {
            return gatheredCount < 0;
        }

        /** Empties the packet of rays {@link #gatheredTransmittances} traces. */
        public void clearPacket() {
            packetSize = 0;
        }

        /** {@return the number of rays in the packet} */
        public int getPacketSize() {
            return packetSize;
        }

        /**
         * Adds a ray of the bundle of the last {@link #gather} to the packet, as for
         * {@link #gatheredTransmittance}: its answer is the ray's number in the packet, from 0.
         *
         * @param ox   the ray's origin, x
         * @param oy   the ray's origin, y
         * @param oz   the ray's origin, z
         * @param dx   the ray's unit direction, x
         * @param dy   the ray's unit direction, y
         * @param dz   the ray's unit direction, z
         * @param maxT the distance along the ray (to its point of the light's square)
         */
        public void addToPacket(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
            if (packetSize == maxTs.length)
                growPacket(Math.max(16, 2 * packetSize));
            int r = packetSize++;
            this.ox[r] = ox;
            this.oy[r] = oy;
            this.oz[r] = oz;
            this.dx[r] = dx;
            this.dy[r] = dy;
            this.dz[r] = dz;
            this.maxTs[r] = maxT;
        }

        private void growPacket(int capacity) {
            ox = Arrays.copyOf(ox, capacity);
            oy = Arrays.copyOf(oy, capacity);
            oz = Arrays.copyOf(oz, capacity);
            dx = Arrays.copyOf(dx, capacity);
            dy = Arrays.copyOf(dy, capacity);
            dz = Arrays.copyOf(dz, capacity);
            ix = Arrays.copyOf(ix, capacity);
            iy = Arrays.copyOf(iy, capacity);
            iz = Arrays.copyOf(iz, capacity);
            maxTs = Arrays.copyOf(maxTs, capacity);
            ktrs = Arrays.copyOf(ktrs, capacity);
            rays = Arrays.copyOf(rays, capacity);
        }

        /**
         * The answer of a ray of the packet, once {@link #gatheredTransmittances} has traced it.
         *
         * @param ray the ray's number in the packet, from 0
         * @return its transparency in [0, 1]
         * @throws IllegalArgumentException when there is no such ray in the packet
         */
        public double getTransmittance(int ray) {
            if (ray < 0 || ray >= packetSize)
                throw new IllegalArgumentException("the packet has rays 0 to " + (packetSize - 1) + ", got " + ray);
            return ktrs[ray];
        }
    }

    private BoundingVolumeHierarchy(Intersectable scene, boolean tree, int threads) {
        if (threads < 1)
            throw new IllegalArgumentException("threads must be 1 or more, got " + threads);
        this.source = requireNonNull(scene, "geometries");
        this.version = versionOf(scene);
        List<Geometry> bounded = new ArrayList<>();
        List<Geometry> infinite = new ArrayList<>();
        List<Intersectable> generic = new ArrayList<>();
        flatten(scene, bounded, infinite, generic, new double[6]);
        if (!tree) {
            infinite.addAll(bounded);
            bounded.clear();
        }
        this.owners = bounded.toArray(new Geometry[0]);
        this.unbounded = infinite.toArray(new Geometry[0]);
        this.others = generic.toArray(new Intersectable[0]);
        this.culling = tree;
        Builder builder = new Builder(owners, threads);
        builder.build();
        this.nodeBounds = new float[6 * builder.nodesCount];
        for (int node = 0; node < builder.nodesCount; ++node)
            roundOutward(builder.nodeBounds, nodeBounds, 6 * node);
        this.nodeLinks = builder.nodeLinks;
        this.nodesCount = builder.nodesCount;
        this.depth = builder.depth;
        this.bodyOwner = builder.order;
        this.bodyPart = builder.parts;
        this.wholeBounds = wholeBounds(builder.boxes);
        this.triangleBounds = new float[6 * bodyPart.length];
        runInChunks(bodyPart.length, threads, (from, to) -> placeTriangles(builder.boxes, from, to));
        this.solids = tree ? solidsOf(owners, threads) : new TriangleMesh[0];
        this.solidBalls = new InnerBall[solids.length];
        this.solidBoxes = new double[6 * solids.length];
        for (int s = 0; s < solids.length; ++s) {
            solidBalls[s] = solids[s].innerBall();
            solids[s].bounds(solidBoxes, 6 * s);
        }
    }

    /**
     * The closed meshes among the bodies of the tree that have an inner ball, at most
     * {@value #MAX_SOLIDS} of them: those of the largest balls, in that order. The meshes look for
     * their balls (once each, see {@link TriangleMesh#innerBall}) on the build's threads.
     */
    private static TriangleMesh[] solidsOf(Geometry[] owners, int threads) {
        TriangleMesh[] meshes = Arrays.stream(owners).filter(TriangleMesh.class::isInstance)
                .map(TriangleMesh.class::cast).toArray(TriangleMesh[]::new);
        Parallel.forEach(meshes.length, threads, BUILD_THREADS, m -> meshes[m].innerBall());
        return Arrays.stream(meshes).filter(mesh -> mesh.innerBall() != null)
                .sorted(Comparator.comparingDouble((TriangleMesh mesh) -> mesh.innerBall().radius).reversed())
                .limit(MAX_SOLIDS).toArray(TriangleMesh[]::new);
    }

    /**
     * Sets the boxes of the mesh's triangles among bodies [from, to) of the tree, in leaf order.
     *
     * @param boxes the padded box of every body of the tree, in leaf order
     * @param from  the first body
     * @param to    one past the last
     */
    private void placeTriangles(double[] boxes, int from, int to) {
        for (int b = from; b < to; ++b) {
            int part = bodyPart[b];
            if (part >= 0)
                roundOutward(boxes, triangleBounds, 6 * b);
        }
    }

    /**
     * Copies a box from doubles into floats, each bound rounded outward, so the box in floats holds
     * the one in doubles.
     *
     * @param boxes  the boxes in doubles
     * @param target the boxes in floats
     * @param b      where the box lies in both
     */
    private static void roundOutward(double[] boxes, float[] target, int b) {
        for (int k = 0; k < 3; ++k) {
            float low = (float) boxes[b + k];
            float high = (float) boxes[b + 3 + k];
            target[b + k] = low > boxes[b + k] ? Math.nextDown(low) : low;
            target[b + 3 + k] = high < boxes[b + 3 + k] ? Math.nextUp(high) : high;
        }
    }

    /**
     * Keeps the boxes of the tree's whole bodies, and numbers them in {@link #bodyPart}.
     *
     * @param boxes the padded box of every body of the tree, in leaf order
     * @return the boxes of the bodies that are not a mesh's triangles, in leaf order
     */
    private double[] wholeBounds(double[] boxes) {
        int count = 0;
        for (int part : bodyPart)
            if (part < 0)
                ++count;
        double[] whole = new double[6 * count];
        int slot = 0;
        for (int b = 0; b < bodyPart.length; ++b)
            if (bodyPart[b] < 0) {
                System.arraycopy(boxes, 6 * b, whole, 6 * slot, 6);
                bodyPart[b] = -1 - slot++;
            }
        return whole;
    }

    /**
     * Builds the hierarchy over a composite's bodies on the calling thread.
     *
     * @param geometries the composite (or a single body)
     * @return the hierarchy
     */
    public static BoundingVolumeHierarchy build(Intersectable geometries) {
        return build(geometries, 1);
    }

    /**
     * Builds the hierarchy over a composite's bodies on several threads: the top of the tree on the
     * calling thread, then its subtrees side by side. The tree answers every query as the one built
     * on one thread does.
     *
     * @param geometries the composite (or a single body)
     * @param threads    the number of threads, 1 or more (the calling thread is one of them)
     * @return the hierarchy
     */
    public static BoundingVolumeHierarchy build(Intersectable geometries, int threads) {
        return new BoundingVolumeHierarchy(geometries, true, threads);
    }

    /**
     * A brute-force stand-in with the same queries: no tree, every body tested on every ray.
     *
     * @param geometries the composite (or a single body)
     * @return the linear scan
     */
    public static BoundingVolumeHierarchy scan(Intersectable geometries) {
        return new BoundingVolumeHierarchy(geometries, false, 1);
    }

    /**
     * Whether the hierarchy was built over this composite as it is now: the same object, and no body
     * added to it, or to a composite in it, since. Renders build once and ask this before each frame.
     *
     * @param geometries the composite
     * @return true when the hierarchy is up to date for it
     */
    public boolean isBuiltFrom(Intersectable geometries) {
        return geometries == source && versionOf(geometries) == version;
    }

    /** {@return the version of a composite's contents (0 for a single body, which never changes)} */
    private static long versionOf(Intersectable geometries) {
        return geometries instanceof Geometries composite ? composite.version() : 0;
    }

    private static void flatten(Intersectable item, List<Geometry> bounded, List<Geometry> infinite,
                                List<Intersectable> generic, double[] box) {
        if (item instanceof Geometries composite)
            for (Intersectable child : composite.getGeometries())
                flatten(child, bounded, infinite, generic, box);
        else if (item instanceof Geometry geometry)
            (geometry.bounds(box, 0) ? bounded : infinite).add(geometry);
        else
            generic.add(item);
    }

    /**
     * Runs a job over ranges [from, to) of count items, a chunk at a time, on up to threads threads.
     *
     * @param count   the number of items
     * @param threads the number of threads
     * @param job     the job, called with each chunk's first item and one past its last
     */
    private static void runInChunks(int count, int threads, ChunkJob job) {
        int chunks = (count + CHUNK - 1) / CHUNK;
        Parallel.forEach(chunks, threads, BUILD_THREADS, c -> job.run(c * CHUNK, Math.min(count, (c + 1) * CHUNK)));
    }

    /** A job over a range of items, see {@link #runInChunks}. */
    @FunctionalInterface
    private interface ChunkJob {
        void run(int from, int to);
    }


    /** {@return a fresh scratch space for queries on this hierarchy} */
    public Query newQuery() {
        return new Query(depth + 2, unbounded.length);
    }

    /** {@return the number of nodes of the tree (0 when no body is bounded)} */
    public int getNodesCount() {
        return nodesCount;
    }

    /** {@return the depth of the tree (1 for a single leaf, 0 for none)} */
    public int getDepth() {
        return depth;
    }

    /** {@return the number of bodies in the tree} */
    public int getBoundedCount() {
        return bodyOwner.length;
    }

    /**
     * The nearest intersection of a ray.
     *
     * @param ray   the ray
     * @param query this thread's scratch space
     * @return the nearest intersection, or null when the ray hits nothing
     */
    public GeoPoint closestHit(Ray ray, Query query) {
        Point3D p0 = ray.getP0();
        Vector dir = ray.getDir();
        query.maxT = Geometry.NO_HIT;
        query.geometry = null;
        traverse(query, p0.getX(), p0.getY(), p0.getZ(), dir.getX(), dir.getY(), dir.getZ(), false, 0);
        GeoPoint nearest = query.geometry == null ? null : query.geometry.hitPoint(ray, query.maxT, query.part);
        for (Intersectable other : others)
            nearest = nearer(ray, nearest, other.findGeoIntersections(ray));
        return nearest;
    }

    private static GeoPoint nearer(Ray ray, GeoPoint nearest, List<GeoPoint> candidates) {
        if (candidates == null)
            return nearest;
        List<GeoPoint> all = new ArrayList<>(candidates);
        if (nearest != null)
            all.add(nearest);
        return ray.findClosestGeoPoint(all);
    }

    /**
     * The share of light that passes along a ray up to a distance: the product of the {@code kT} of
     * every intersection before it, 0 as soon as an opaque body is met or the product falls below
     * a limit.
     *
     * @param ox   the ray's origin, x
     * @param oy   the ray's origin, y
     * @param oz   the ray's origin, z
     * @param dx   the ray's unit direction, x
     * @param dy   the ray's unit direction, y
     * @param dz   the ray's unit direction, z
     * @param maxT the distance along the ray (to the light)
     * @param minK below this product the answer is 0
     * @param query this thread's scratch space
     * @return the transparency in [0, 1]
     */
    public double transmittance(double ox, double oy, double oz, double dx, double dy, double dz, double maxT,
                                double minK, Query query) {
        query.maxT = maxT;
        query.ktr = 1;
        return traverse(query, ox, oy, oz, dx, dy, dz, true, minK)
                ? throughOthers(query.ktr, ox, oy, oz, dx, dy, dz, maxT, minK) : 0;
    }

    /**
     * Gathers the bodies a bundle of shadow rays may meet, for {@link #gatheredTransmittance}: the
     * unbounded bodies and the tree's bodies that may meet the query's
     * {@link Query#getFrustum() frustum} (set it first): the planes of unbounded ones and of
     * polygons must cross it, a triangle must not lie outside one of its faces (its back face among
     * them) nor behind both of the rays' starts ({@link ShadowFrustum#setStarts}), and the boxes of
     * bounded ones must meet it. When more than a few of the tree's
     * bodies meet it, their smallest subtree is kept instead. A brute-force {@link #scan} gathers
     * every body.
     * <p>
     * Once the first body is gathered, the tree's closed opaque meshes are tried: when one lies across
     * every ray of the bundle, the gather stops, and the bundle is blocked ({@link #blocksBundle});
     * otherwise those whose inner balls the pyramid meets are kept, and a ray of the packet through
     * one of those balls is answered at once ({@link #gatheredTransmittances}).
     *
     * @param query this thread's scratch space, its frustum set to the bundle's pyramid
     * @return false when no ray of the bundle can meet anything: then no ray needs to be tested (never
     *         when a triangle was left out behind the starts, which a ray from neither may meet)
     */
    public boolean gather(Query query) {
        ShadowFrustum frustum = query.frustum;
        int found = 0;
        for (Geometry body : unbounded)
            if (!culling || body.mayMeet(frustum))
                query.gatheredUnbounded[found++] = body;
        query.unboundedCount = found;
        query.solidCount = 0;
        query.solidsTried = false;
        query.blocked = false;
        query.gatheredCount = 0;
        query.startCounts[ShadowFrustum.ABOVE] = 0;
        query.startCounts[ShadowFrustum.BELOW] = 0;
        if (nodesCount > 0 && frustum.meetsBox(nodeBounds, 0))
            gatherTree(query);
        return found > 0 || query.gatheredCount != 0 || others.length > 0 || frustum.leftBehindStarts()
                || query.blocked;
    }

    /**
     * Whether the last {@link #gather} found a closed opaque mesh that blocks every ray of its bundle:
     * every ray passes through the mesh's inner ball on its way to a base outside the mesh's box
     * ({@link ShadowFrustum#crossesSolid}), so each crosses the mesh's surface, and each ray's
     * transparency is 0, as {@link #gatheredTransmittance} (which then answers 0) would find one ray
     * at a time. A point in a body's umbra needs no ray traced. A brute-force {@link #scan} has no
     * such meshes.
     *
     * @param query this thread's scratch space, as the last {@link #gather} left it
     * @return true when every ray of the bundle is blocked
     */
    public boolean blocksBundle(Query query) {
        return query.blocked;
    }

    /**
     * Tries the tree's closed opaque meshes on the query's bundle: keeps those whose inner balls the
     * pyramid meets, its base outside their boxes, unless one lies across every ray (the bundle is
     * then blocked).
     *
     * @return true when one lies across every ray of the bundle
     */
    private boolean triesSolids(Query query) {
        query.solidsTried = true;
        ShadowFrustum frustum = query.frustum;
        int count = 0;
        for (int s = 0; s < solids.length; ++s) {
            InnerBall ball = solidBalls[s];
            if (solids[s].getMaterial().getKt() != 0 || !frustum.meetsBox(ball.box(), 0))
                continue;
            if (frustum.crossesSolid(ball, solidBoxes, 6 * s)) {
                query.blocked = true;
                return true;
            }
            if (frustum.baseOutside(solidBoxes, 6 * s))
                query.solidList[count++] = s;
        }
        query.solidCount = count;
        return false;
    }

    /**
     * Answers 0 for each unblocked ray of the packet that passes through the ball of a solid
     * {@link #gather} kept: it crosses that closed opaque mesh.
     *
     * @return the number of rays so blocked
     */
    private int blockBySolids(Query query) {
        int blocked = 0;
        for (int k = 0; k < query.solidCount; ++k) {
            InnerBall ball = solidBalls[query.solidList[k]];
            for (int r = 0; r < query.packetSize; ++r)
                if (query.ktrs[r] > 0 && ball.crossedBy(query.ox[r], query.oy[r], query.oz[r], query.dx[r],
                        query.dy[r], query.dz[r], query.maxTs[r])) {
                    query.ktrs[r] = 0;
                    ++blocked;
                }
        }
        return blocked;
    }

    /**
     * Walks the nodes whose boxes meet the frustum and gathers the bodies of their leaves, or when
     * they are too many, the node where the walk first had to enter both children.
     */
    private void gatherTree(Query query) {
        ShadowFrustum frustum = query.frustum;
        int[] stack = query.stack;
        int top = 0;
        int node = 0;
        int subtree = 0;
        boolean branched = false;
        while (true) {
            int first = nodeLinks[2 * node];
            int count = nodeLinks[2 * node + 1];
            if (!branched) // still on the one path from the root
                subtree = node;
            if (count < 0) {
                boolean leftMeets = frustum.meetsBox(nodeBounds, 6 * first);
                boolean rightMeets = frustum.meetsBox(nodeBounds, 6 * first + 6);
                if (leftMeets || rightMeets) {
                    if (leftMeets && rightMeets) {
                        stack[top++] = first + 1;
                        branched = true;
                    }
                    node = leftMeets ? first : first + 1;
                    continue;
                }
            } else if (!gatherLeaf(query, first, count)) {
                if (!query.blocked) {
                    query.gatheredCount = -1;
                    query.subtree = subtree;
                }
                return;
            }
            if (top == 0)
                return;
            node = stack[--top];
        }
    }

    /**
     * Adds a leaf's bodies that may meet the frustum ({@link #bodyMeets}), a mesh's triangle with the
     * numbers of its test; false when there is no room for them, or when the solids, tried at the
     * first body found, block the bundle.
     */
    private boolean gatherLeaf(Query query, int first, int count) {
        for (int b = first; b < first + count; ++b)
            if (bodyMeets(query, b)) {
                if (!query.solidsTried && triesSolids(query))
                    return false;
                int slot = query.gatheredCount;
                if (slot == MAX_GATHERED)
                    return false;
                int part = bodyPart[b];
                if (part >= 0) {
                    TriangleMesh mesh = (TriangleMesh) owners[bodyOwner[b]];
                    int d = GATHERED_TRIANGLE * slot;
                    mesh.triangleData(part, query.gatheredTriangles, d);
                    query.gatheredTriangles[d + TriangleMesh.TRIANGLE_DATA] = mesh.getMaterial().getKt();
                }
                query.gathered[slot] = part >= 0 ? -1 : b;
                query.gatheredCount = slot + 1;
                if (query.frustum.hasStarts())
                    listByStarts(query, slot, part >= 0 ? query.frustum.startsBehind(query.gatheredTriangles,
                            GATHERED_TRIANGLE * slot) : 0);
            }
        return true;
    }

    /**
     * Lists a gathered body for the rays from each start it does not lie behind.
     *
     * @param slot   its place among the gathered bodies
     * @param behind the starts it lies behind, as {@link ShadowFrustum#startsBehind} tells
     */
    private static void listByStarts(Query query, int slot, int behind) {
        for (int start = ShadowFrustum.ABOVE; start <= ShadowFrustum.BELOW; ++start)
            if ((behind & start) == 0)
                query.startLists[start][query.startCounts[start]++] = slot;
    }

    /**
     * Whether body b of the tree may meet the query's frustum: its padded box does, and then the body
     * itself may ({@link Geometry#mayMeet}: a polygon's plane, and a mesh's triangle's). A mesh's
     * triangle's box is kept in floats, rounded outward: a little larger, never smaller.
     *
     * @param query this thread's scratch space, its frustum set
     * @param b     the body, in leaf order
     * @return false when no ray of the bundle can meet the body
     */
    private boolean bodyMeets(Query query, int b) {
        int part = bodyPart[b];
        ShadowFrustum frustum = query.frustum;
        if (part < 0)
            return frustum.meetsBox(wholeBounds, 6 * (-1 - part)) && owners[bodyOwner[b]].mayMeet(frustum);
        return frustum.meetsBox(triangleBounds, 6 * b) && ((TriangleMesh) owners[bodyOwner[b]]).mayMeet(part, frustum);
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
     * {@link #transmittance} for a ray of the bundle of the last {@link #gather}: only the gathered
     * bodies are tested (a gathered triangle not when it lies behind the ray's start), and the answer
     * is the same (up to the order in which the {@code kT} of several transparent bodies are
     * multiplied, which may move its last bit). A ray from neither of the frustum's starts, when they
     * are set, is traced alone through the whole hierarchy.
     *
     * @param ox    the ray's origin, x
     * @param oy    the ray's origin, y
     * @param oz    the ray's origin, z
     * @param dx    the ray's unit direction, x
     * @param dy    the ray's unit direction, y
     * @param dz    the ray's unit direction, z
     * @param maxT  the distance along the ray (to its point of the light's square)
     * @param minK  below this product the answer is 0
     * @param query this thread's scratch space, as the last {@link #gather} left it
     * @return the transparency in [0, 1]
     */
    public double gatheredTransmittance(double ox, double oy, double oz, double dx, double dy, double dz,
                                        double maxT, double minK, Query query) {
        if (query.blocked)
            return 0;
        return query.frustum.hasStarts() ? fromStart(ox, oy, oz, dx, dy, dz, maxT, minK, query)
                : throughBundle(0, ox, oy, oz, dx, dy, dz, maxT, minK, query);
    }

    /**
     * {@link #gatheredTransmittance} when the frustum's starts are set: a ray from neither start is
     * traced alone through the whole hierarchy, as the gather left out bodies only the rays from the
     * starts miss.
     */
    private double fromStart(double ox, double oy, double oz, double dx, double dy, double dz, double maxT,
                             double minK, Query query) {
        int start = query.frustum.startOf(ox, oy, oz, dx, dy, dz);
        return start == 0 ? transmittance(ox, oy, oz, dx, dy, dz, maxT, minK, query)
                : throughBundle(start, ox, oy, oz, dx, dy, dz, maxT, minK, query);
    }

    /**
     * The transparency along a ray of the bundle from a start through what the last {@link #gather}
     * found: the unbounded bodies, the gathered ones and the intersectables that are not geometries.
     *
     * @param start where the ray starts, as the frustum's {@link ShadowFrustum#startOf} tells (0 when
     *              no starts are set)
     */
    private double throughBundle(int start, double ox, double oy, double oz, double dx, double dy, double dz,
                                 double maxT, double minK, Query query) {
        if (!throughGatheredUnbounded(query, ox, oy, oz, dx, dy, dz, maxT, minK)
                || !throughGathered(query, start, ox, oy, oz, dx, dy, dz, minK))
            return 0;
        return throughOthers(query.ktr, ox, oy, oz, dx, dy, dz, maxT, minK);
    }

    /**
     * Dims the query's transparency by the gathered bodies along a ray of the bundle: the kept subtree,
     * walked, or the bodies a ray from its start tests (every gathered body when no starts are set).
     *
     * @param start where the ray starts, as the frustum's {@link ShadowFrustum#startOf} tells
     * @return false when they block the ray
     */
    private boolean throughGathered(Query query, int start, double ox, double oy, double oz, double dx, double dy,
                                    double dz, double minK) {
        if (query.gatheredCount < 0)
            return walk(query, query.subtree, ox, oy, oz, dx, dy, dz, true, minK);
        int[] list = start == 0 ? ALL_GATHERED : query.startLists[start];
        int count = start == 0 ? query.gatheredCount : query.startCounts[start];
        for (int k = 0; k < count; ++k)
            if (!visitGathered(query, list[k], ox, oy, oz, dx, dy, dz, minK))
                return false;
        return true;
    }

    /**
     * {@link #gatheredTransmittance} for every ray of the query's packet at once (read the answers
     * with {@link Query#getTransmittance}), each the same as that ray's alone up to the order in which
     * the {@code kT} of several transparent bodies multiply (the packet enters the nearer child by its
     * first ray's direction, which may move the last bit; opaque blockers give exactly 0). When the last
     * {@link #gather} kept a subtree, the rays walk it together as a packet: each node is visited
     * once for all of them, set aside when it does not meet the bundle's pyramid, and entered when
     * one of the rays still unblocked meets its box; a leaf's bodies are tested on every such ray
     * that meets the leaf's box. A ray leaves the walk as soon as it is blocked.
     *
     * @param minK  below this product a ray's answer is 0
     * @param query this thread's scratch space, as the last {@link #gather} left it, its packet filled
     */
    public void gatheredTransmittances(double minK, Query query) {
        int n = query.packetSize;
        if (query.blocked) {
            Arrays.fill(query.ktrs, 0, n, 0);
            return;
        }
        if (query.gatheredCount >= 0) {
            for (int r = 0; r < n; ++r)
                query.ktrs[r] = gatheredTransmittance(query.ox[r], query.oy[r], query.oz[r], query.dx[r], query.dy[r],
                        query.dz[r], query.maxTs[r], minK, query);
            return;
        }
        int active = 0;
        for (int r = 0; r < n; ++r) {
            query.ktrs[r] = throughUnbounded(query, r, minK);
            if (query.ktrs[r] > 0)
                ++active;
        }
        active -= blockBySolids(query);
        if (active > 0)
            walkPacket(query, active, minK);
        for (int r = 0; r < n; ++r)
            if (query.ktrs[r] > 0)
                query.ktrs[r] = throughOthers(query.ktrs[r], query.ox[r], query.oy[r], query.oz[r], query.dx[r],
                        query.dy[r], query.dz[r], query.maxTs[r], minK);
    }

    /** The transparency of the gathered unbounded bodies along ray r of the packet, 0 when they block it. */
    private static double throughUnbounded(Query query, int r, double minK) {
        return throughGatheredUnbounded(query, query.ox[r], query.oy[r], query.oz[r], query.dx[r], query.dy[r],
                query.dz[r], query.maxTs[r], minK) ? query.ktr : 0;
    }

    /**
     * Starts a transmittance query up to a distance and dims it by the gathered unbounded bodies.
     *
     * @return false when they block the ray; else the query's ktr holds their transparency
     */
    private static boolean throughGatheredUnbounded(Query query, double ox, double oy, double oz, double dx,
                                                    double dy, double dz, double maxT, double minK) {
        query.maxT = maxT;
        query.ktr = 1;
        for (int i = 0; i < query.unboundedCount; ++i)
            if (!visit(query.gatheredUnbounded[i], query, ox, oy, oz, dx, dy, dz, true, minK))
                return false;
        return true;
    }

    /**
     * Walks the subtree the last {@link #gather} kept with the packet's rays still unblocked: a node is
     * visited with the first and the last of them that meet its box (the rays before the first and
     * after the last do not), a child's looked for between its parent's (a child's box lies inside its
     * parent's: the same numbers or nearer in, so a ray that misses the parent misses the child), and
     * children are entered nearer first by the first ray's direction. A leaf lists the rays between
     * them that meet its box and tests its bodies on them ({@link #leafOnPacket}).
     *
     * @param active the number of unblocked rays
     */
    private void walkPacket(Query query, int active, double minK) {
        int n = query.packetSize;
        invertDirections(query);
        int node = query.subtree;
        int first = firstRayMeeting(query, node, 0, n - 1);
        int last = lastRayMeeting(query, node, first, n - 1);
        int[] stack = query.stack;
        int[] firstRays = query.firstRays;
        int[] lastRays = query.lastRays;
        int top = 0;
        while (first < n) {
            int link = nodeLinks[2 * node];
            int count = nodeLinks[2 * node + 1];
            if (count < 0) {
                int near = link + (negativeAxes(query, first) >> (-1 - count) & 1);
                int far = 2 * link + 1 - near;
                int nearFirst = packetMeets(query, near, first, last);
                int farFirst = packetMeets(query, far, first, last);
                if (nearFirst < n) {
                    if (farFirst < n) {
                        stack[top] = far;
                        firstRays[top] = farFirst;
                        lastRays[top++] = last;
                    }
                    node = near;
                    first = nearFirst;
                    last = lastRayMeeting(query, node, first, last);
                    continue;
                }
                if (farFirst < n) {
                    node = far;
                    first = farFirst;
                    last = lastRayMeeting(query, node, first, last);
                    continue;
                }
            } else {
                active -= leafOnPacket(query, link, count, raysMeeting(query, node, first, last), minK);
                if (active == 0)
                    return;
            }
            first = n;
            while (top > 0 && first == n) {
                node = stack[--top];
                last = lastRays[top];
                first = query.ktrs[firstRays[top]] > 0 ? firstRays[top]
                        : firstRayMeeting(query, node, firstRays[top], last);
                if (first < n)
                    last = lastRayMeeting(query, node, first, last);
            }
        }
    }

    /** Sets the inverses of the packet's directions. */
    private static void invertDirections(Query query) {
        for (int r = 0; r < query.packetSize; ++r) {
            query.ix[r] = 1 / query.dx[r];
            query.iy[r] = 1 / query.dy[r];
            query.iz[r] = 1 / query.dz[r];
        }
    }

    /** {@return the axes along which ray r of the packet goes backwards: bit 0 for x, 1 for y, 2 for z} */
    private static int negativeAxes(Query query, int r) {
        return (query.dx[r] < 0 ? 1 : 0) | (query.dy[r] < 0 ? 2 : 0) | (query.dz[r] < 0 ? 4 : 0);
    }

    /** The first unblocked ray of rays [from, to] that meets a node's box, n when none does or the pyramid misses it. */
    private int packetMeets(Query query, int node, int from, int to) {
        return query.frustum.meetsBox(nodeBounds, 6 * node) ? firstRayMeeting(query, node, from, to) : query.packetSize;
    }

    /** The first unblocked ray of rays [from, to] that meets a node's box, or the packet's size when none does. */
    private int firstRayMeeting(Query query, int node, int from, int to) {
        for (int r = from; r <= to; ++r)
            if (query.ktrs[r] > 0 && rayMeets(query, r, node))
                return r;
        return query.packetSize;
    }

    /** The last unblocked ray of rays (from, to] that meets an inner node's box, else from; to for a leaf. */
    private int lastRayMeeting(Query query, int node, int from, int to) {
        if (nodeLinks[2 * node + 1] >= 0)
            return to;
        for (int r = to; r > from; --r)
            if (query.ktrs[r] > 0 && rayMeets(query, r, node))
                return r;
        return from;
    }

    /**
     * Lists in {@link Query#rays} ray first and the unblocked rays after it up to ray last that meet a
     * leaf's box, in order.
     *
     * @return the list's length
     */
    private int raysMeeting(Query query, int node, int first, int last) {
        int[] rays = query.rays;
        int count = 0;
        rays[count++] = first;
        for (int r = first + 1; r <= last; ++r)
            if (query.ktrs[r] > 0 && rayMeets(query, r, node))
                rays[count++] = r;
        return count;
    }

    /** Whether ray r of the packet meets a node's box before its distance. */
    private boolean rayMeets(Query query, int r, int node) {
        return boxEntry(node, query.ox[r], query.oy[r], query.oz[r], query.ix[r], query.iy[r], query.iz[r],
                query.maxTs[r]) != MISSED;
    }

    /**
     * Tests a leaf's bodies on the rays listed in {@link Query#rays}, all of which meet its box: body
     * after body, each on the rays not blocked yet, so each ray meets the bodies in their order and
     * stops at the body that blocks it, as alone. The list keeps the rays still unblocked.
     *
     * @param firstBody the leaf's first body
     * @param bodies    its body count
     * @param count     the list's length
     * @return the number of rays the leaf blocked
     */
    private int leafOnPacket(Query query, int firstBody, int bodies, int count, double minK) {
        int left = count;
        for (int b = firstBody; b < firstBody + bodies && left > 0; ++b) {
            int part = bodyPart[b];
            Geometry owner = owners[bodyOwner[b]];
            left = part < 0 ? bodyOnPacket(query, owner, left, minK)
                    : triangleOnPacket(query, (TriangleMesh) owner, part, left, minK);
        }
        return count - left;
    }

    /**
     * Tests a body (not a mesh's triangle) on the rays listed in {@link Query#rays} through its own
     * {@link Geometry#transmittance}, keeping those it does not block.
     *
     * @param count the list's length
     * @return the number of rays kept
     */
    private static int bodyOnPacket(Query query, Geometry body, int count, double minK) {
        int[] rays = query.rays;
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            int r = rays[i];
            if (dimRay(query, r, body.transmittance(query.ox[r], query.oy[r], query.oz[r], query.dx[r], query.dy[r],
                    query.dz[r], query.maxTs[r]), minK))
                rays[kept++] = r;
        }
        return kept;
    }

    /**
     * Tests a mesh's triangle on the rays listed in {@link Query#rays}, its data read once from the
     * mesh, keeping the rays it does not block: a ray it meets is dimmed by the mesh's {@code kT}.
     *
     * @param part  the triangle in its mesh
     * @param count the list's length
     * @return the number of rays kept
     */
    private static int triangleOnPacket(Query query, TriangleMesh mesh, int part, int count, double minK) {
        double[] data = query.triangle;
        mesh.triangleData(part, data, 0);
        // in locals, not read from the array for each ray: the JIT cannot tell that the rays' arrays,
        // doubles too, do not overlap it, and would read the ten numbers again per ray
        double p1x = data[0];
        double p1y = data[1];
        double p1z = data[2];
        double e1x = data[3];
        double e1y = data[4];
        double e1z = data[5];
        double e2x = data[6];
        double e2y = data[7];
        double e2z = data[8];
        double limit = data[9];
        double kT = mesh.getMaterial().getKt();
        int[] rays = query.rays;
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            int r = rays[i];
            if (Triangle.intersect(p1x, p1y, p1z, e1x, e1y, e1z, e2x, e2y, e2z, limit, query.ox[r], query.oy[r],
                    query.oz[r], query.dx[r], query.dy[r], query.dz[r], query.maxTs[r]) == Geometry.NO_HIT
                    || dimRay(query, r, kT, minK))
                rays[kept++] = r;
        }
        return kept;
    }

    /** Multiplies ray r's transparency by a factor, as {@link #dim}; false (its transparency 0) once it is blocked. */
    private static boolean dimRay(Query query, int r, double factor, double minK) {
        double ktr = query.ktrs[r] * factor;
        boolean through = ktr > 0 && ktr >= minK;
        query.ktrs[r] = through ? ktr : 0;
        return through;
    }

    /** Multiplies a transparency by the {@code kT} of every hit of the intersectables that are not geometries. */
    private double throughOthers(double ktr, double ox, double oy, double oz, double dx, double dy, double dz,
                                 double maxT, double minK) {
        if (others.length == 0)
            return ktr;
        Ray ray = new Ray(new Point3D(ox, oy, oz), new Vector(dx, dy, dz));
        for (Intersectable other : others) {
            List<GeoPoint> hits = other.findGeoIntersections(ray, maxT);
            if (hits != null)
                for (GeoPoint hit : hits)
                    ktr *= hit.geometry.getMaterial().getKt();
            if (ktr < minK)
                return 0;
        }
        return ktr;
    }

    /**
     * Walks the unbounded bodies and the tree. A closest-hit walk shrinks the query's maxT to each
     * nearer hit; a transmittance walk multiplies the query's ktr and stops when it falls below minK.
     *
     * @return false when a transmittance walk stopped early (the light is blocked)
     */
    private boolean traverse(Query query, double ox, double oy, double oz, double dx, double dy, double dz,
                             boolean transmittance, double minK) {
        for (Geometry body : unbounded)
            if (!visit(body, query, ox, oy, oz, dx, dy, dz, transmittance, minK))
                return false;
        return nodesCount == 0 || walk(query, 0, ox, oy, oz, dx, dy, dz, transmittance, minK);
    }

    /**
     * Walks the subtree below a node, the way {@link #traverse} walks the tree. The stack keeps with
     * each node set aside the distance where the ray enters its box, so a closest-hit walk skips it
     * when a nearer hit has been found since (the box test again, with the shrunk distance, would
     * fail: the answer is the same, found with fewer tests).
     *
     * @return false when a transmittance walk stopped early (the light is blocked)
     */
    private boolean walk(Query query, int root, double ox, double oy, double oz, double dx, double dy, double dz,
                         boolean transmittance, double minK) {
        double ix = 1 / dx;
        double iy = 1 / dy;
        double iz = 1 / dz;
        if (boxEntry(root, ox, oy, oz, ix, iy, iz, query.maxT) == MISSED)
            return true;
        int negative = (dx < 0 ? 1 : 0) | (dy < 0 ? 2 : 0) | (dz < 0 ? 4 : 0);
        int[] stack = query.stack;
        double[] entries = query.entries;
        int top = 0;
        int node = root;
        while (true) {
            int first = nodeLinks[2 * node];
            int count = nodeLinks[2 * node + 1];
            if (count < 0) {
                int near = first + (negative >> (-1 - count) & 1);
                int far = 2 * first + 1 - near;
                double nearEntry = boxEntry(near, ox, oy, oz, ix, iy, iz, query.maxT);
                double farEntry = boxEntry(far, ox, oy, oz, ix, iy, iz, query.maxT);
                if (nearEntry != MISSED) {
                    if (farEntry != MISSED) {
                        entries[top] = farEntry;
                        stack[top++] = far;
                    }
                    node = near;
                    continue;
                }
                if (farEntry != MISSED) {
                    node = far;
                    continue;
                }
            } else
                for (int b = first; b < first + count; ++b)
                    if (!visitBody(b, query, ox, oy, oz, dx, dy, dz, transmittance, minK))
                        return false;
            do {
                if (top == 0)
                    return true;
                node = stack[--top];
            } while (entries[top] > query.maxT);
        }
    }

    /**
     * {@link #visitBody} in a transmittance walk for the body at a place of the query's gathered ones:
     * a mesh's triangle is tested on the numbers {@link #gatherLeaf} kept, the same as the mesh's.
     */
    private boolean visitGathered(Query query, int i, double ox, double oy, double oz, double dx, double dy,
                                  double dz, double minK) {
        int b = query.gathered[i];
        if (b >= 0)
            return visit(owners[bodyOwner[b]], query, ox, oy, oz, dx, dy, dz, true, minK);
        double[] data = query.gatheredTriangles;
        int d = GATHERED_TRIANGLE * i;
        return Triangle.intersect(data, d, ox, oy, oz, dx, dy, dz, query.maxT) == Geometry.NO_HIT
                || dim(query, data[d + TriangleMesh.TRIANGLE_DATA], minK);
    }

    /** {@link #visit} for body b of the tree. */
    private boolean visitBody(int b, Query query, double ox, double oy, double oz, double dx, double dy, double dz,
                              boolean transmittance, double minK) {
        int part = bodyPart[b];
        return part < 0 ? visit(owners[bodyOwner[b]], query, ox, oy, oz, dx, dy, dz, transmittance, minK)
                : visitTriangle(b, part, query, ox, oy, oz, dx, dy, dz, transmittance, minK);
    }

    /**
     * {@link #visit} for a mesh's triangle of the tree, tested from the mesh's arrays; the mesh's
     * material is read only on a hit.
     */
    private boolean visitTriangle(int b, int part, Query query, double ox, double oy, double oz, double dx,
                                  double dy, double dz, boolean transmittance, double minK) {
        TriangleMesh mesh = (TriangleMesh) owners[bodyOwner[b]];
        double t = mesh.triangleHit(part, ox, oy, oz, dx, dy, dz, query.maxT);
        if (t == Geometry.NO_HIT)
            return true;
        return transmittance ? dim(query, mesh.getMaterial().getKt(), minK) : keepNearer(query, t, mesh, part);
    }

    /**
     * Tests one body: a transmittance walk multiplies the query's ktr by the body's transparency, a
     * closest-hit walk keeps the body when it is hit nearer.
     *
     * @return false when the transmittance walk must stop (the light is blocked)
     */
    private static boolean visit(Geometry body, Query query, double ox, double oy, double oz,
                                 double dx, double dy, double dz, boolean transmittance, double minK) {
        return transmittance ? dim(query, body.transmittance(ox, oy, oz, dx, dy, dz, query.maxT), minK)
                : keepNearer(query, body.nearestHit(ox, oy, oz, dx, dy, dz, query.maxT), body, -1);
    }

    /** Multiplies the query's ktr by a factor; false once the light is blocked (below minK or 0). */
    private static boolean dim(Query query, double factor, double minK) {
        query.ktr *= factor;
        return query.ktr > 0 && query.ktr >= minK;
    }

    /** Keeps a body (and its part, or −1) hit at distance t when it is nearer than the nearest so far; always true. */
    private static boolean keepNearer(Query query, double t, Geometry body, int part) {
        if (t < query.maxT) {
            query.maxT = t;
            query.geometry = body;
            query.part = part;
        }
        return true;
    }

    /**
     * Where a ray enters a node's box between its start and maxT, or {@link #MISSED}: the slab test
     * ({@link #slabEntry}) on the box's numbers.
     */
    private double boxEntry(int node, double ox, double oy, double oz, double ix, double iy, double iz,
                            double maxT) {
        float[] box = nodeBounds;
        int b = 6 * node;
        return slabEntry(box[b], box[b + 1], box[b + 2], box[b + 3], box[b + 4], box[b + 5], ox, oy, oz, ix, iy, iz,
                maxT);
    }

    /**
     * Where a ray enters a box [x0, x1] × [y0, y1] × [z0, z1] between its start and maxT (the slab
     * test), or {@link #MISSED} when it does not meet the box there. Each slab is entered at its near
     * face (the low one for a positive direction component, so for +0.0, and the high one for a
     * negative component, so for −0.0) and left at the far one. A direction component of ±0 makes the
     * inverse ±∞: a ray outside the slab then gets an empty interval, one inside it (−∞, +∞), and one
     * lying exactly in a face's plane gets 0·∞ = NaN there, which the comparisons below skip, so the
     * slab (closed) does not restrict the interval. Small enough for the JIT to inline into every walk.
     *
     * @param ix   the inverse of the ray's direction, x
     * @param iy   the same for y
     * @param iz   the same for z
     * @param maxT the largest distance that counts
     * @return the distance (0 or more) where the ray enters the box, or {@link #MISSED}
     */
    public static double slabEntry(double x0, double y0, double z0, double x1, double y1, double z1, double ox,
                                    double oy, double oz, double ix, double iy, double iz, double maxT) {
        double near = ((ix < 0 ? x1 : x0) - ox) * ix;
        double far = ((ix < 0 ? x0 : x1) - ox) * ix;
        near = near > 0 ? near : 0;
        far = far < maxT ? far : maxT;
        double lo = ((iy < 0 ? y1 : y0) - oy) * iy;
        double hi = ((iy < 0 ? y0 : y1) - oy) * iy;
        near = lo > near ? lo : near;
        far = hi < far ? hi : far;
        lo = ((iz < 0 ? z1 : z0) - oz) * iz;
        hi = ((iz < 0 ? z0 : z1) - oz) * iz;
        near = lo > near ? lo : near;
        far = hi < far ? hi : far;
        return near <= far ? near : MISSED;
    }

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
    private static final class Builder {
        /**
         * About how many nodes a tree has per body, with a little to spare: a fresh array is zeroed,
         * so room for nodes that are never used costs time (a tree of leaves of up to
         * {@value #MAX_LEAF_SIZE} bodies has 0.5 to 0.6 nodes per body).
         */
        private static final double NODES_PER_BODY = 0.75;
        /** Each thread gets about this many subtrees, so that one large subtree does not hold up the rest. */
        private static final int SUBTREES_PER_THREAD = 4;

        private final Geometry[] owners;
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

        Builder(Geometry[] owners, int threads) {
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
                int axis = widestAxis(centroidBoxes, c);
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
                System.arraycopy(EMPTY_BOX, 0, bounds, b, 6);
                System.arraycopy(EMPTY_BOX, 0, centroidBoxes, c, 6);
                for (int i = start; i < end; ++i) {
                    growBox(bounds, b, boxes, 6 * i);
                    growByPoint(centroidBoxes, c, i);
                }
            }

            /** Grows the box at b around the centroid of the body at place i. */
            private void growByPoint(double[] box, int b, int i) {
                for (int k = 0; k < 3; ++k) {
                    box[b + k] = Math.min(box[b + k], centroids[3 * i + k]);
                    box[b + 3 + k] = Math.max(box[b + 3 + k], centroids[3 * i + k]);
                }
            }

            /** Sets the box at b of target around the boxes of bins [from, to) of bins. */
            private void unionOfBins(double[] bins, int from, int to, double[] target, int b) {
                System.arraycopy(EMPTY_BOX, 0, target, b, 6);
                for (int k = from; k < to; ++k)
                    growBox(target, b, bins, 6 * k);
            }

            private int widestAxis(double[] box, int b) {
                double x = box[b + 3] - box[b];
                double y = box[b + 4] - box[b + 1];
                double z = box[b + 5] - box[b + 2];
                return x >= y && x >= z ? 0 : y >= z ? 1 : 2;
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
                    System.arraycopy(EMPTY_BOX, 0, binBoxes, 6 * k, 6);
                    System.arraycopy(EMPTY_BOX, 0, binCentroids, 6 * k, 6);
                }
                for (int i = start; i < end; ++i) {
                    int k = binOf(i, axis, low, binsPerUnit);
                    ++binCounts[k];
                    growBox(binBoxes, 6 * k, boxes, 6 * i);
                    growByPoint(binCentroids, 6 * k, i);
                }
                System.arraycopy(EMPTY_BOX, 0, sweep, 0, 6);
                for (int k = BINS - 1; k > 0; --k) {
                    growBox(sweep, 0, binBoxes, 6 * k);
                    rightAreas[k] = area(sweep, 0);
                }
                System.arraycopy(EMPTY_BOX, 0, sweep, 0, 6);
                int leftCount = 0;
                int best = -1;
                // split when TRAVERSAL_COST·A + Σ n·A(child) beats the leaf's count·A
                double bestCost = (end - start - TRAVERSAL_COST) * area(bounds, 6 * node);
                for (int k = 0; k < BINS - 1; ++k) {
                    growBox(sweep, 0, binBoxes, 6 * k);
                    leftCount += binCounts[k];
                    int rightCount = end - start - leftCount;
                    if (leftCount == 0 || rightCount == 0)
                        continue;
                    double cost = leftCount * area(sweep, 0) + rightCount * rightAreas[k + 1];
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

        private static void growBox(double[] box, int b, double[] other, int o) {
            if (other[o] > other[o + 3])
                return; // an empty box
            for (int k = 0; k < 3; ++k) {
                box[b + k] = Math.min(box[b + k], other[o + k]);
                box[b + 3 + k] = Math.max(box[b + 3 + k], other[o + 3 + k]);
            }
        }

        /** Half the surface area of a box (the factor 2 does not change which split is best). */
        private static double area(double[] box, int b) {
            double x = box[b + 3] - box[b];
            double y = box[b + 4] - box[b + 1];
            double z = box[b + 5] - box[b + 2];
            return x * y + y * z + z * x;
        }
    }
}
