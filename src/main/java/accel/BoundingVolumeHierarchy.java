package accel;

import geometries.Geometries;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Intersectable.GeoPoint;
import geometries.Triangle;
import geometries.TriangleMesh;
import java.util.ArrayList;
import java.util.List;

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
 * The tree lives in flat arrays ({@link BvhNodes}: a node's box, its first body or first child, its
 * body count and split axis; the two children of a node are neighbours) and is walked with an
 * explicit stack: at an inner node both children's boxes are tested, and the nearer child (by the
 * split axis) is entered first ({@link ClosestHitWalk}, {@link TransmittanceWalk}). It is built top
 * down with the binned surface-area heuristic ({@link BvhBuilder}). A {@link TriangleMesh} gives the
 * tree one body per triangle, held by reference ({@link LeafBodies}: the mesh and the triangle's
 * index, two ints, and its box in floats), with no object and no copy of its vertices per triangle:
 * a single ray tests the tree's triangles straight from the mesh's arrays, while a bundle copies the
 * numbers of each triangle's test once (a gathered triangle into the query, a packet's leaf triangle
 * for the leaf's rays). Other bodies (a {@link Triangle} object among them) are tested through their
 * own methods. Unbounded bodies (planes, tubes) stay outside the tree and are tested on every ray, as
 * are intersectables that are not {@link Geometry}s.
 * <p>
 * The shadow rays of one soft shadow can be traced as a bundle: {@link #gather} walks the tree once
 * with the bundle's pyramid (a {@link ShadowFrustum}) and keeps the few bodies that may meet it, or
 * their smallest subtree when they are many ({@link BundleGather}); {@link #bundleRayTransmittance}
 * then tests a ray against those alone, and {@link #packetTransmittances} all the rays of the bundle
 * at once, walking a kept subtree as one packet ({@link PacketWalk}). A closed opaque mesh one of
 * whose cores, its inner boxes ({@link InnerBoxes}), lies across every ray of a bundle blocks the
 * whole bundle at the gather ({@link #blocksBundle}), and a packet's ray through such a core is
 * blocked before the walk ({@link ClosedMeshBlockers}).
 * <p>
 * Queries take a {@link Query}, the caller's per-thread scratch space, and allocate nothing but
 * the {@link GeoPoint} a closest-hit query returns.
 */
public final class BoundingVolumeHierarchy {
    /** The composite the hierarchy was built over, and the version of its contents then. */
    private final Intersectable source;
    private final long version;
    private final LeafBodies bodies;
    private final BvhNodes nodes;
    private final ClosedMeshBlockers blockers;
    private final ClosestHitWalk closestHitWalk;
    private final TransmittanceWalk transmittanceWalk;
    private final BundleGather bundleGather;
    private final PacketWalk packetWalk;
    /** The query of each thread for instances of the hierarchy's body ({@link #threadQuery}). */
    private final ThreadLocal<Query> threadQueries = ThreadLocal.withInitial(this::newQuery);

    private BoundingVolumeHierarchy(Intersectable scene, boolean tree, int threads) {
        if (threads < 1)
            throw new IllegalArgumentException("threads must be 1 or more, got " + threads);
        this.source = requireNonNull(scene, "geometries");
        this.version = versionOf(scene);
        List<Geometry> bounded = new ArrayList<>();
        List<Geometry> infinite = new ArrayList<>();
        List<Intersectable> generic = new ArrayList<>();
        LeafBodies.flatten(scene, bounded, infinite, generic, new double[6]);
        if (!tree) {
            infinite.addAll(bounded);
            bounded.clear();
        }
        PackedTriangles packed = PackedTriangles.take(bounded);
        Geometry[] owners = bounded.toArray(new Geometry[0]);
        BvhBuilder builder = new BvhBuilder(owners, threads);
        builder.build();
        this.nodes = new BvhNodes(builder);
        this.bodies = new LeafBodies(infinite.toArray(new Geometry[0]), generic.toArray(new Intersectable[0]),
                packed, builder, threads);
        this.blockers = new ClosedMeshBlockers(owners, packed, threads, nodes.largestExtent());
        this.closestHitWalk = new ClosestHitWalk(nodes, bodies);
        this.transmittanceWalk = new TransmittanceWalk(nodes, bodies);
        this.bundleGather = new BundleGather(nodes, bodies, blockers, transmittanceWalk, tree);
        this.packetWalk = new PacketWalk(nodes, bodies, blockers, bundleGather);
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
     * Reads again what the hierarchy keeps of the bodies' materials: whether the closed parts of
     * course-style {@link geometries.Triangle}s are opaque, so that they block whole bundles. A render
     * calls it before every frame; call it after changing such a triangle's {@code kT} between frames
     * traced without a render.
     */
    public void readMaterials() {
        blockers.readMaterials();
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
        return geometries.version();
    }

    /** {@return a fresh scratch space for queries on this hierarchy} */
    public Query newQuery() {
        return new Query(nodes.depth + 2, bodies.unbounded.length);
    }

    /** {@return the number of nodes of the tree (0 when no body is bounded)} */
    public int getNodesCount() {
        return nodes.count;
    }

    /** {@return the depth of the tree (1 for a single leaf, 0 for none)} */
    public int getDepth() {
        return nodes.depth;
    }

    /** {@return the number of bodies in the tree} */
    public int getBoundedCount() {
        return bodies.count();
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
        RayState state = query.ray.set(p0.getX(), p0.getY(), p0.getZ(), dir.getX(), dir.getY(), dir.getZ(),
                Geometry.NO_HIT);
        return closestHit(ray, query, state);
    }

    /** The nearest intersection of a ray whose numbers are in the query's ray, up to its distance. */
    private GeoPoint closestHit(Ray ray, Query query, RayState state) {
        closestHitWalk.closestHit(query, state);
        GeoPoint nearest = state.geometry == null ? null : bodies.hitPoint(ray, state);
        return bodies.nearestOfOthers(ray, nearest);
    }

    // The queries of an instance of the hierarchy's body (see geometries.Instance): a ray given in
    // the world is mapped into the body's space by the instance's inverse, and the body's tree is
    // walked there with this thread's query. Distances scale by the mapped direction's length.

    /**
     * This thread's scratch space for queries on this hierarchy, made on its first call: the one the
     * {@link geometries.Instance}s of the hierarchy's body share on this thread. Safe while no body
     * holds itself (a {@link Geometries} refuses such a cycle): an instance's walk never enters the
     * walk of its own body again.
     *
     * @return the query
     */
    public Query threadQuery() {
        return threadQueries.get();
    }

    /**
     * The box around all the hierarchy's bodies, the way an instance finds its own.
     *
     * @param box where the six numbers go: {minX, minY, minZ, maxX, maxY, maxZ}
     * @return false, with nothing written, when a body is unbounded (or not a {@link Geometry}) or there is none
     */
    public boolean bounds(double[] box) {
        if (nodes.count == 0 || bodies.unbounded.length > 0 || bodies.others.length > 0)
            return false;
        for (int k = 0; k < 6; ++k)
            box[k] = nodes.bounds[k];
        return true;
    }

    /**
     * The distance to the nearest intersection of a ray given in another space, within its distance.
     *
     * @param ray   the ray, in the space the map comes from (an instance's world)
     * @param toBody the map into the bodies' space, 12 numbers (see {@link primitives.Transform#toArray})
     * @return the distance along the given ray, or {@link Geometry#NO_HIT}
     */
    public double nearestHit(RayState ray, double[] toBody) {
        Query query = threadQuery();
        RayState mapped = query.ray;
        double scale = mapped.setMapped(ray, toBody);
        closestHitWalk.closestHit(query, mapped);
        double t = Math.min(mapped.geometry == null ? Geometry.NO_HIT : mapped.maxT, bodies.nearestOfOthers(mapped));
        return t == Geometry.NO_HIT ? t : t / scale;
    }

    /**
     * The nearest intersection of a ray given in another space, in the bodies' space.
     *
     * @param ray    the ray, in the space the map comes from (an instance's world); its distance is ignored
     * @param toBody the map into the bodies' space, 12 numbers (see {@link primitives.Transform#toArray})
     * @return the intersection, its point in the bodies' space, or null
     */
    public GeoPoint closestHit(RayState ray, double[] toBody) {
        Query query = threadQuery();
        RayState mapped = query.ray;
        mapped.setMapped(ray, toBody);
        mapped.maxT = Geometry.NO_HIT;
        return closestHit(mapped.toRay(), query, mapped);
    }

    /**
     * Whether any ray of a bundle given in another space may meet the bodies: its pyramid is carried
     * into the bodies' space ({@link MappedFrustum}) and gathered for there, as this tree's own bundles
     * are; the bundle's packets then take that gather ({@link #packetTransmittances(Query, int, double[],
     * double[])}). An instance answers {@link Geometry#mayMeet} so.
     *
     * @param frustum the bundle's pyramid, in the space the map comes from (an instance's world)
     * @param toBody  the map into the bodies' space, 12 numbers (see {@link primitives.Transform#toArray})
     * @param toWorld its inverse, 12 numbers
     * @return false only when no ray of the bundle can meet any body
     */
    public boolean mayMeet(ShadowFrustum frustum, double[] toBody, double[] toWorld) {
        return gatherCarried(threadQuery(), frustum, toBody, toWorld);
    }

    /**
     * Whether the last {@link #mayMeet} of a bundle, its pyramid carried into the bodies' space, found
     * a closed opaque mesh across every ray ({@link #blocksBundle}): then every ray of the bundle is
     * blocked by the bodies.
     *
     * @param frustum the bundle's pyramid, as {@link #mayMeet} was given it
     * @param toBody  the map into the bodies' space, as {@link #mayMeet} was given it
     * @return false when it did not, or when {@link #mayMeet} was not asked for that pyramid and map last
     */
    public boolean blocksCarried(ShadowFrustum frustum, double[] toBody) {
        Query query = threadQuery();
        return query.mapping.holds(frustum, toBody) && query.mapping.isCarried() && query.blocked;
    }

    /**
     * Carries a bundle's pyramid into the bodies' space and gathers for it there, once per pyramid
     * and map: the packets of the bundle that reach the bodies later take that gather as it is.
     *
     * @param query this thread's query on this hierarchy
     * @return false only when no ray of the bundle can meet any body (true when the pyramid cannot be carried)
     */
    private boolean gatherCarried(Query query, ShadowFrustum frustum, double[] toBody, double[] toWorld) {
        MappedFrustum mapping = query.mapping;
        if (!mapping.holds(frustum, toBody)) {
            query.forgetLastGather(); // the query serves every instance of the body, in every tile
            query.carriedMeets = !mapping.set(query.frustum, frustum, toBody, toWorld) || bundleGather.gather(query);
        }
        return query.carriedMeets;
    }

    /**
     * The share of light that passes the bodies along a ray given in another space, within its
     * distance: the product of the {@code kT} of every intersection, each body's own. The running
     * product of the given ray (its transmittance so far and its limit) sets where the walk may stop.
     *
     * @param ray    the ray, in the space the map comes from (an instance's world)
     * @param toBody the map into the bodies' space, 12 numbers (see {@link primitives.Transform#toArray})
     * @return the transparency in [0, 1]: 0 also when, times the given ray's, it falls below the ray's limit
     */
    public double transmittance(RayState ray, double[] toBody) {
        Query query = threadQuery();
        RayState mapped = query.ray;
        mapped.setMapped(ray, toBody);
        return transmittanceWalk.transmittance(query, mapped, innerLimit(ray));
    }

    /**
     * {@link #transmittance(RayState, double[])} for some rays of another hierarchy's packet at once:
     * the rays of its query's packet listed in its leaf list, all unblocked so far. The bundle's pyramid
     * is carried into the bodies' space ({@link MappedFrustum}) and gathered there (once: {@link
     * #mayMeet} did when the other hierarchy gathered the bundle), so the rays are
     * found open together, blocked together by a closed mesh's core, or traced together as a packet
     * through this tree ({@link PacketWalk#trace}). An instance answers
     * {@link geometries.Instance#packetTransmittances} so.
     *
     * @param outer  the other hierarchy's scratch space (an instance's world's), its packet and frustum set
     * @param count  how many rays are listed
     * @param toBody the map into the bodies' space, 12 numbers (see {@link primitives.Transform#toArray})
     * @param toWorld its inverse, 12 numbers
     * @return how many of the listed rays are still unblocked: the list keeps them, in order
     */
    public int packetTransmittances(Query outer, int count, double[] toBody, double[] toWorld) {
        Query query = threadQuery();
        Packet packet = outer.packet;
        int[] list = packet.leafRays;
        boolean meets = gatherCarried(query, outer.frustum, toBody, toWorld);
        if (!query.mapping.isCarried())
            return eachAlone(packet, count, toBody);
        if (!meets)
            return count;
        query.clearPacket();
        for (int k = 0; k < count; ++k) {
            RayState ray = packet.rays[list[k]];
            RayState mapped = query.packet.add();
            mapped.setMapped(ray, toBody);
            mapped.minK = innerLimit(ray);
        }
        packetWalk.trace(query);
        int kept = 0;
        for (int k = 0; k < count; ++k) {
            RayState ray = packet.rays[list[k]];
            if (PacketWalk.through(ray, ray.attenuate(query.packet.rays[k].ktr)))
                list[kept++] = list[k];
        }
        return kept;
    }

    /** {@link #packetTransmittances(Query, int, double[], double[])} ray by ray, for a pyramid that cannot be carried. */
    private int eachAlone(Packet packet, int count, double[] toBody) {
        int[] list = packet.leafRays;
        int kept = 0;
        for (int k = 0; k < count; ++k) {
            RayState ray = packet.rays[list[k]];
            if (PacketWalk.through(ray, ray.attenuate(transmittance(ray, toBody))))
                list[kept++] = list[k];
        }
        return kept;
    }

    /** {@return the limit a ray's walk in the bodies' space takes: the ray's own, divided by its transmittance so far} */
    private static double innerLimit(RayState ray) {
        return ray.ktr > 0 ? ray.minK / ray.ktr : 0;
    }

    /**
     * The share of light that passes along the query's ray ({@link Query#setRay}) up to its distance:
     * the product of the {@code kT} of every intersection before it, 0 as soon as an opaque body is
     * met or the product falls below a limit.
     *
     * @param query this thread's scratch space, its ray set
     * @param minK  below this product the answer is 0
     * @return the transparency in [0, 1]
     */
    public double transmittance(Query query, double minK) {
        return transmittanceWalk.transmittance(query, query.ray, minK);
    }

    /**
     * Gathers the bodies a bundle of shadow rays may meet, for {@link #bundleRayTransmittance}: the
     * unbounded bodies and the tree's bodies that may meet the query's
     * {@link Query#getFrustum() frustum} (set it first): the planes of unbounded ones and of
     * polygons must cross it, a triangle must not lie outside one of its faces (its back face among
     * them) nor behind both of the rays' origins ({@link ShadowFrustum#setOrigins}), and the boxes of
     * bounded ones must meet it. When more than a few of the tree's bodies meet it, their smallest
     * subtree is kept instead; so is the subtree the query's last gather kept, at once, when this
     * gather's walk first branches at its root and finds a body. A brute-force {@link #scan} gathers
     * every body.
     * <p>
     * Once the first body is gathered, the tree's closed opaque meshes are tried: when one lies across
     * every ray of the bundle, the gather stops, and the bundle is blocked ({@link #blocksBundle});
     * otherwise those whose boxes the pyramid meets are kept, and a ray of the packet through one of
     * their cores is answered at once ({@link #packetTransmittances}).
     *
     * @param query this thread's scratch space, its frustum set to the bundle's pyramid
     * @return false when no ray of the bundle can meet anything: then no ray needs to be tested (never
     *         when a triangle was left out behind the origins, which a ray from neither may meet)
     */
    public boolean gather(Query query) {
        return bundleGather.gather(query);
    }

    /**
     * Whether the last {@link #gather} found a closed opaque mesh that blocks every ray of its bundle:
     * every ray passes through one of the mesh's inner boxes on its way to a base outside the mesh's
     * box ({@link CoreCrossing}), so each crosses the mesh's surface, and each ray's
     * transparency is 0, as {@link #bundleRayTransmittance} (which then answers 0) would find one ray
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
     * {@link #transmittance} for a single ray of the bundle of the last {@link #gather}, set by
     * {@link Query#setRay}: only the gathered bodies are tested (a gathered triangle not when it lies
     * behind the ray's origin), and the answer is the same (up to the order in which the {@code kT}
     * of several transparent bodies are multiplied, which may move its last bit). A ray from neither
     * of the frustum's ray origins, when they are set, is traced alone through the whole hierarchy.
     *
     * @param query this thread's scratch space, as the last {@link #gather} left it, its ray set
     * @param minK  below this product the answer is 0
     * @return the transparency in [0, 1]
     */
    public double bundleRayTransmittance(Query query, double minK) {
        return bundleGather.rayTransmittance(query, query.ray, minK);
    }

    /**
     * {@link #bundleRayTransmittance} for every ray of the query's packet at once (read the answers
     * with {@link Query#getTransmittance}), each the same as that ray's alone up to the order in which
     * the {@code kT} of several transparent bodies multiply (the packet enters the nearer child by its
     * first ray's direction, which may move the last bit; opaque blockers give exactly 0). When the last
     * {@link #gather} kept a subtree, the rays walk it together as a packet: each node is visited
     * once for all of them, set aside when it does not meet the bundle's pyramid, and entered when
     * one of the rays still unblocked meets its box; a leaf's bodies are tested on every such ray
     * that meets the leaf's box. A ray leaves the walk as soon as it is blocked.
     *
     * @param query this thread's scratch space, as the last {@link #gather} left it, its packet filled
     * @param minK  below this product a ray's answer is 0
     */
    public void packetTransmittances(Query query, double minK) {
        packetWalk.transmittances(query, minK);
    }
}
