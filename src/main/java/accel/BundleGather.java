package accel;

import geometries.Geometry;
import geometries.Instance;
import geometries.Triangle;
import geometries.TriangleMesh;
import java.util.stream.IntStream;

/**
 * The gather of a bundle of shadow rays: the tree is walked once with the bundle's pyramid (a
 * {@link ShadowFrustum}), keeping the few bodies that may meet it, or their smallest subtree when
 * they are many; then each ray of the bundle is tested against those alone.
 */
final class BundleGather {
    /** The places of all gathered bodies, in order. */
    private static final int[] ALL_GATHERED = IntStream.range(0, Query.MAX_GATHERED).toArray();
    /**
     * How many gathers in a row may keep the last gather's subtree at once; the next gathers in full, to
     * check that its bundle still meets too many bodies. Bundles that meet a few bodies after many
     * would otherwise all walk the subtree as packets, each at the cost of several gathers.
     */
    static final int MAX_KEPT = 4;

    private final BvhNodes nodes;
    private final LeafBodies bodies;
    private final ClosedMeshBlockers blockers;
    private final TransmittanceWalk walk;
    /** Whether the gather culls bodies: false for the brute-force scan. */
    private final boolean culling;

    BundleGather(BvhNodes nodes, LeafBodies bodies, ClosedMeshBlockers blockers, TransmittanceWalk walk,
                 boolean culling) {
        this.nodes = nodes;
        this.bodies = bodies;
        this.blockers = blockers;
        this.walk = walk;
        this.culling = culling;
    }

    /**
     * Gathers the bodies the query's bundle may meet (see {@link BoundingVolumeHierarchy#gather}).
     *
     * @param query this thread's scratch space, its frustum set to the bundle's pyramid
     * @return false when no ray of the bundle can meet anything
     */
    boolean gather(Query query) {
        ShadowFrustum frustum = query.frustum;
        int found = 0;
        for (Geometry body : bodies.unbounded)
            if (!culling || body.mayMeet(frustum))
                query.gatheredUnbounded[found++] = body;
        query.unboundedCount = found;
        query.coreCount = 0;
        query.blockersTried = false;
        query.blocked = false;
        query.gatheredCount = 0;
        query.instanceCount = 0;
        query.originCounts[ShadowFrustum.ABOVE] = 0;
        query.originCounts[ShadowFrustum.BELOW] = 0;
        if (nodes.count > 0 && frustum.meetsBox(nodes.bounds, 0))
            gatherTree(query);
        if (query.gatheredCount >= 0)
            query.overflowedAt = -1;
        return found > 0 || query.gatheredCount != 0 || query.instanceCount > 0 || bodies.others.length > 0
                || frustum.leftBehindOrigins() || query.blocked;
    }

    /**
     * Walks the nodes whose boxes meet the frustum and gathers the bodies of their leaves, or when
     * they are too many, the node where the walk first had to enter both children. When that node is
     * where the query's last gather kept its subtree, the bundle most likely meets as many bodies
     * again (its lit point neighbours the last): the walk only looks for one body, to tell an open
     * bundle, and keeps the subtree.
     */
    private void gatherTree(Query query) {
        ShadowFrustum frustum = query.frustum;
        float[] bounds = nodes.bounds;
        int[] links = nodes.links;
        int[] stack = query.stack;
        int top = 0;
        int node = 0;
        int subtree = 0;
        boolean branched = false;
        boolean predicted = false;
        while (true) {
            int first = links[2 * node];
            int count = links[2 * node + 1];
            if (!branched) // still on the one path from the root
                subtree = node;
            if (count < 0) {
                boolean leftMeets = frustum.meetsBox(bounds, 6 * first);
                boolean rightMeets = frustum.meetsBox(bounds, 6 * first + 6);
                if (leftMeets || rightMeets) {
                    if (leftMeets && rightMeets) {
                        if (!branched) // the first branch: where the last gather may have kept its subtree
                            predicted = node == query.overflowedAt && query.keptSince < MAX_KEPT;
                        stack[top++] = first + 1;
                        branched = true;
                    }
                    node = leftMeets ? first : first + 1;
                    continue;
                }
            } else if (predicted ? leafMeets(frustum, first, count) : !gatherLeaf(query, first, count)) {
                if (!query.blocked)
                    keepSubtree(query, subtree, predicted);
                return;
            }
            if (top == 0)
                return;
            node = stack[--top];
        }
    }

    /**
     * Keeps a subtree for the bundle instead of its bodies, unless the closed meshes block it, as
     * they are tried at the first body found.
     *
     * @param predicted whether it is the last gather's subtree, kept at once
     */
    private void keepSubtree(Query query, int subtree, boolean predicted) {
        if (!query.blockersTried && blockers.tryOn(query))
            return;
        query.gatheredCount = -1;
        query.instanceCount = 0; // the subtree's walk meets them
        query.subtree = subtree;
        query.overflowedAt = subtree;
        query.keptSince = predicted ? query.keptSince + 1 : 0;
    }

    /** {@return whether a body of a leaf may meet the frustum} */
    private boolean leafMeets(ShadowFrustum frustum, int first, int count) {
        for (int b = first; b < first + count; ++b)
            if (bodies.meets(frustum, b))
                return true;
        return false;
    }

    /**
     * Adds a leaf's bodies that may meet the frustum ({@link LeafBodies#meets}), a mesh's triangle
     * with the numbers of its test, an instance apart from the others; false when there is no room for
     * them, or when the bundle is blocked: by the closed meshes, tried at the first body found, or by
     * an instance whose body's gather found one of its own closed meshes across every ray.
     */
    private boolean gatherLeaf(Query query, int first, int count) {
        ShadowFrustum frustum = query.frustum;
        for (int b = first; b < first + count; ++b)
            if (bodies.meets(frustum, b)) {
                if (!query.blockersTried && blockers.tryOn(query))
                    return false;
                if (bodies.owner(b) instanceof Instance instance) {
                    if (instance.blocksBundle(frustum)) {
                        query.blocked = true;
                        return false;
                    }
                    if (query.instanceCount == Query.MAX_GATHERED)
                        return false;
                    query.gatheredInstances[query.instanceCount++] = instance;
                    continue;
                }
                int slot = query.gatheredCount;
                if (slot == Query.MAX_GATHERED)
                    return false;
                int part = bodies.bodyPart[b];
                int d = Query.GATHERED_TRIANGLE * slot;
                double[] data = query.gatheredTriangles;
                if (part >= 0) {
                    TriangleMesh mesh = (TriangleMesh) bodies.owner(b);
                    mesh.triangleData(part, data, d);
                    data[d + TriangleMesh.TRIANGLE_DATA] = bodies.kT(mesh, part);
                }
                query.gathered[slot] = part >= 0 ? -1 : b;
                query.gatheredCount = slot + 1;
                if (frustum.hasOrigins())
                    listByOrigins(query, slot, part >= 0 ? frustum.originsBehind(data, d) : 0);
            }
        return true;
    }

    /**
     * Lists a gathered body for the rays from each origin it does not lie behind.
     *
     * @param slot   its place among the gathered bodies
     * @param behind the origins it lies behind, as {@link ShadowFrustum#originsBehind} tells
     */
    private static void listByOrigins(Query query, int slot, int behind) {
        for (int origin = ShadowFrustum.ABOVE; origin <= ShadowFrustum.BELOW; ++origin)
            if ((behind & origin) == 0)
                query.originLists[origin][query.originCounts[origin]++] = slot;
    }

    /**
     * The transmittance of a ray of the bundle of the last gather (see
     * {@link BoundingVolumeHierarchy#bundleRayTransmittance}).
     *
     * @param query this thread's scratch space, as the last gather left it
     * @param ray   the ray
     * @param minK  below this product the answer is 0
     * @return the transparency in [0, 1]
     */
    double rayTransmittance(Query query, RayState ray, double minK) {
        if (query.blocked)
            return 0;
        ray.minK = minK;
        if (!throughAllButInstances(query, ray))
            return ray.ktr;
        return throughGatheredInstances(query, ray) ? bodies.throughOthers(ray, ray.ktr) : 0;
    }

    /**
     * Starts the ray's transmittance and attenuates it by the gathered bodies but the instances: the
     * unbounded ones, then the tree's (those a ray from its origin tests).
     *
     * @param origin where the ray starts, as the frustum's {@link ShadowFrustum#originOf} tells (0
     *               when no origins are set)
     * @return false when they block the ray; else the ray's ktr holds their transparency
     */
    private boolean throughGatheredBodies(Query query, RayState ray, int origin, double minK) {
        return throughGatheredUnbounded(query, ray, minK) && throughGathered(query, ray, origin);
    }

    /**
     * Starts the ray's transmittance and attenuates it by the gathered unbounded bodies.
     *
     * @return false when they block the ray; else the ray's ktr holds their transparency
     */
    static boolean throughGatheredUnbounded(Query query, RayState ray, double minK) {
        ray.startTransmittance(minK);
        for (int i = 0; i < query.unboundedCount; ++i)
            if (!ray.attenuateBy(query.gatheredUnbounded[i]))
                return false;
        return true;
    }

    /**
     * Traces a ray of a packet through the bodies the last gather found but its instances, which the
     * packet takes on together after ({@link PacketWalk}).
     *
     * @return true when the ray is still unblocked and has the instances to meet; false when it is
     *         done, its ktr its answer: blocked (0), or from neither of the frustum's ray origins, and
     *         so traced alone through the whole hierarchy
     */
    boolean throughAllButInstances(Query query, RayState ray) {
        ShadowFrustum frustum = query.frustum;
        int origin = frustum.originOf(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz);
        if (origin == 0 && frustum.hasOrigins()) {
            ray.ktr = walk.transmittance(query, ray, ray.minK);
            return false;
        }
        if (throughGatheredBodies(query, ray, origin, ray.minK))
            return true;
        ray.ktr = 0;
        return false;
    }

    /** Attenuates the ray by the gathered instances, each walking its body's tree alone; false when they block it. */
    private static boolean throughGatheredInstances(Query query, RayState ray) {
        for (int i = 0; i < query.instanceCount; ++i)
            if (!ray.attenuateBy(query.gatheredInstances[i]))
                return false;
        return true;
    }

    /**
     * Attenuates the ray by the gathered bodies: the kept subtree, walked, or the bodies a ray from
     * its origin tests (every gathered body when no origins are set).
     *
     * @param origin where the ray starts, as the frustum's {@link ShadowFrustum#originOf} tells
     * @return false when they block the ray
     */
    private boolean throughGathered(Query query, RayState ray, int origin) {
        if (query.gatheredCount < 0)
            return walk.walk(query, ray, query.subtree);
        int[] list = origin == 0 ? ALL_GATHERED : query.originLists[origin];
        int count = origin == 0 ? query.gatheredCount : query.originCounts[origin];
        for (int k = 0; k < count; ++k)
            if (!visitGathered(query, ray, list[k]))
                return false;
        return true;
    }

    /**
     * Attenuates the ray by the body at place i of the query's gathered ones: a mesh's triangle is
     * tested on the numbers {@link #gatherLeaf} kept, the same as the mesh's.
     */
    private boolean visitGathered(Query query, RayState ray, int i) {
        int b = query.gathered[i];
        if (b >= 0)
            return ray.attenuateBy(bodies.owner(b));
        double[] data = query.gatheredTriangles;
        int d = Query.GATHERED_TRIANGLE * i;
        return Triangle.intersect(ray, data, d, data[d + TriangleMesh.PARALLEL_LIMIT]) == Geometry.NO_HIT
                || ray.attenuate(data[d + TriangleMesh.TRIANGLE_DATA]);
    }
}
