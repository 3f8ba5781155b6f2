package accel;

import geometries.Geometry;
import geometries.Instance;
import geometries.Triangle;
import geometries.TriangleMesh;

/**
 * The shadow rays of a bundle traced together, as a packet, through the subtree the gather kept:
 * each node is visited once for all of them, and a leaf's bodies are tested on the rays that meet
 * its box.
 */
final class PacketWalk {
    private final BvhNodes nodes;
    private final LeafBodies bodies;
    private final ClosedMeshBlockers blockers;
    private final BundleGather gather;

    PacketWalk(BvhNodes nodes, LeafBodies bodies, ClosedMeshBlockers blockers, BundleGather gather) {
        this.nodes = nodes;
        this.bodies = bodies;
        this.blockers = blockers;
        this.gather = gather;
    }

    /**
     * Traces every ray of the query's packet (see {@link BoundingVolumeHierarchy#packetTransmittances}).
     *
     * @param query this thread's scratch space, as the last gather left it, its packet filled
     * @param minK  below this product a ray's answer is 0
     */
    void transmittances(Query query, double minK) {
        for (int r = 0; r < query.packet.size; ++r)
            query.packet.rays[r].minK = minK;
        trace(query);
    }

    /**
     * Traces every ray of the query's packet, each with its own limit: below its {@link RayState#minK}
     * its answer is 0.
     *
     * @param query this thread's scratch space, as the last gather left it, its packet filled
     */
    void trace(Query query) {
        RayState[] rays = query.packet.rays;
        int n = query.packet.size;
        if (query.blocked) {
            for (int r = 0; r < n; ++r)
                rays[r].ktr = 0;
            return;
        }
        if (query.gatheredCount >= 0) {
            gathered(query);
            return;
        }
        int active = 0;
        for (int r = 0; r < n; ++r) {
            RayState ray = rays[r].invert();
            if (!BundleGather.throughGatheredUnbounded(query, ray, ray.minK))
                ray.ktr = 0;
            if (ray.ktr > 0)
                ++active;
        }
        active -= blockers.blockPacket(query);
        if (active > 0)
            walk(query, active);
        for (int r = 0; r < n; ++r)
            if (rays[r].ktr > 0)
                rays[r].ktr = bodies.throughOthers(rays[r], rays[r].ktr);
    }

    /**
     * Traces the packet's rays through the bodies the last gather kept one by one: each ray through
     * those that are not instances alone (or through the whole hierarchy, from neither ray origin),
     * then the rays still unblocked through each gathered instance together
     * ({@link Instance#packetTransmittances}), as {@link BundleGather#rayTransmittance} traces a ray.
     */
    private void gathered(Query query) {
        Packet packet = query.packet;
        int[] list = packet.leafRays;
        int count = 0;
        for (int r = 0; r < packet.size; ++r)
            if (gather.throughAllButInstances(query, packet.rays[r]))
                list[count++] = r;
        for (int i = 0; i < query.instanceCount && count > 0; ++i)
            count = query.gatheredInstances[i].packetTransmittances(query, count);
        for (int k = 0; k < count; ++k) {
            RayState ray = packet.rays[list[k]];
            ray.ktr = bodies.throughOthers(ray, ray.ktr);
        }
    }

    /**
     * Walks the subtree the last gather kept with the packet's rays still unblocked: a node is
     * visited with the first and the last of them that meet its box (the rays before the first and
     * after the last do not), a child's looked for between its parent's (a child's box lies inside its
     * parent's: the same numbers or nearer in, so a ray that misses the parent misses the child), and
     * children are entered nearer first by the first ray's direction. A leaf lists the rays between
     * them that meet its box and tests its bodies on them ({@link #leaf}).
     *
     * @param active the number of unblocked rays
     */
    private void walk(Query query, int active) {
        Packet packet = query.packet;
        RayState[] rays = packet.rays;
        int n = packet.size;
        int[] links = nodes.links;
        int node = query.subtree;
        int first = firstRayMeeting(packet, node, 0, n - 1);
        int last = lastRayMeeting(packet, node, first, n - 1);
        int[] stack = query.stack;
        int[] firstRays = packet.firstRays;
        int[] lastRays = packet.lastRays;
        int top = 0;
        while (first < n) {
            int link = links[2 * node];
            int count = links[2 * node + 1];
            if (count < 0) {
                int near = link + (rays[first].negative >> (-1 - count) & 1);
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
                    last = lastRayMeeting(packet, node, first, last);
                    continue;
                }
                if (farFirst < n) {
                    node = far;
                    first = farFirst;
                    last = lastRayMeeting(packet, node, first, last);
                    continue;
                }
            } else {
                active -= leaf(query, link, count, raysMeeting(packet, node, first, last));
                if (active == 0)
                    return;
            }
            first = n;
            while (top > 0 && first == n) {
                node = stack[--top];
                last = lastRays[top];
                first = rays[firstRays[top]].ktr > 0 ? firstRays[top]
                        : firstRayMeeting(packet, node, firstRays[top], last);
                if (first < n)
                    last = lastRayMeeting(packet, node, first, last);
            }
        }
    }

    /**
     * The first unblocked ray of rays [from, to] that meets a node's box, n when none does. Ray from
     * is tried first: when it meets the box, the pyramid does too. Only then is the pyramid tried,
     * whose test sets aside at once a box that none of the other rays can meet.
     */
    private int packetMeets(Query query, int node, int from, int to) {
        Packet packet = query.packet;
        if (meets(packet.rays[from], node))
            return from;
        return from < to && query.frustum.meetsBox(nodes.bounds, 6 * node)
                ? firstRayMeeting(packet, node, from + 1, to) : packet.size;
    }

    /** The first unblocked ray of rays [from, to] that meets a node's box, or the packet's size when none does. */
    private int firstRayMeeting(Packet packet, int node, int from, int to) {
        for (int r = from; r <= to; ++r)
            if (meets(packet.rays[r], node))
                return r;
        return packet.size;
    }

    /** The last unblocked ray of rays (from, to] that meets an inner node's box, else from; to for a leaf. */
    private int lastRayMeeting(Packet packet, int node, int from, int to) {
        if (nodes.links[2 * node + 1] >= 0)
            return to;
        for (int r = to; r > from; --r)
            if (meets(packet.rays[r], node))
                return r;
        return from;
    }

    /**
     * Lists in {@link Packet#leafRays} ray first and the unblocked rays after it up to ray last that
     * meet a leaf's box, in order.
     *
     * @return the list's length
     */
    private int raysMeeting(Packet packet, int node, int first, int last) {
        int[] list = packet.leafRays;
        int count = 0;
        list[count++] = first;
        for (int r = first + 1; r <= last; ++r)
            if (meets(packet.rays[r], node))
                list[count++] = r;
        return count;
    }

    /** Whether a ray of the packet is unblocked and meets a node's box before its distance. */
    private boolean meets(RayState ray, int node) {
        return ray.ktr > 0 && nodes.entry(node, ray, ray.maxT) != RayState.MISSED;
    }

    /**
     * Tests a leaf's bodies on the rays listed in {@link Packet#leafRays}, all of which meet its box:
     * body after body, each on the rays not blocked yet, so each ray meets the bodies in their order
     * and stops at the body that blocks it, as alone; an instance's body takes them on together, in
     * its own tree ({@link Instance#packetTransmittances}). The list keeps the rays still unblocked.
     *
     * @param firstBody the leaf's first body
     * @param bodyCount its body count
     * @param count     the list's length
     * @return the number of rays the leaf blocked
     */
    private int leaf(Query query, int firstBody, int bodyCount, int count) {
        Packet packet = query.packet;
        int left = count;
        for (int b = firstBody; b < firstBody + bodyCount && left > 0; ++b) {
            int part = bodies.bodyPart[b];
            Geometry owner = bodies.owner(b);
            if (owner instanceof Instance instance)
                left = instance.packetTransmittances(query, left);
            else if (part < 0)
                left = bodyOnPacket(packet, owner, left);
            else {
                TriangleMesh mesh = (TriangleMesh) owner;
                left = triangleOnPacket(packet, mesh, part, bodies.kT(mesh, part), left);
            }
        }
        return count - left;
    }

    /**
     * Tests a body (not a mesh's triangle) on the rays listed in {@link Packet#leafRays} through its
     * own {@link Geometry#transmittance}, keeping those it does not block.
     *
     * @param count the list's length
     * @return the number of rays kept
     */
    private static int bodyOnPacket(Packet packet, Geometry body, int count) {
        int[] list = packet.leafRays;
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            int r = list[i];
            if (through(packet.rays[r], packet.rays[r].attenuateBy(body)))
                list[kept++] = r;
        }
        return kept;
    }

    /**
     * Tests a mesh's triangle on the rays listed in {@link Packet#leafRays}, its data read once from
     * the mesh, keeping the rays it does not block: a ray it meets is attenuated by the mesh's
     * {@code kT}.
     *
     * @param part  the triangle in its mesh
     * @param kT    the triangle's transparency
     * @param count the list's length
     * @return the number of rays kept
     */
    private static int triangleOnPacket(Packet packet, TriangleMesh mesh, int part, double kT, int count) {
        double[] data = packet.triangle;
        mesh.triangleData(part, data, 0);
        double limit = data[TriangleMesh.PARALLEL_LIMIT];
        int[] list = packet.leafRays;
        RayState[] rays = packet.rays;
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            int r = list[i];
            RayState ray = rays[r];
            if (Triangle.intersect(ray, data, 0, limit) == Geometry.NO_HIT || through(ray, ray.attenuate(kT)))
                list[kept++] = r;
        }
        return kept;
    }

    /** Sets a packet's ray's transmittance to 0 once it is blocked; {@return whether it was not} */
    static boolean through(RayState ray, boolean through) {
        if (!through)
            ray.ktr = 0;
        return through;
    }
}
