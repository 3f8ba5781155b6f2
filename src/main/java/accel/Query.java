package accel;

import geometries.Geometry;
import geometries.Instance;
import geometries.TriangleMesh;

/**
 * Per-thread scratch space of queries on a {@link BoundingVolumeHierarchy}: the ray being traced, the
 * walk's stack, what the last gather of a shadow bundle found, and a packet of shadow rays. Get one
 * from {@link BoundingVolumeHierarchy#newQuery()} and use it on one thread at a time.
 */
public final class Query {
    /** The most bodies of the tree a bundle of shadow rays is tested against one by one. */
    static final int MAX_GATHERED = 32;
    /**
     * The numbers a gathered mesh triangle keeps for the bundle's rays: the ten of its test (see
     * {@link TriangleMesh#triangleData}) and its mesh's {@code kT}.
     */
    static final int GATHERED_TRIANGLE = TriangleMesh.TRIANGLE_DATA + 1;

    /** The single ray of the next query ({@link #setRay}). */
    final RayState ray = new RayState();
    final int[] stack;
    /** Where the ray of a closest-hit walk enters the box of each node on the stack. */
    final double[] entries;
    final ShadowFrustum frustum = new ShadowFrustum();
    /** Carries another hierarchy's bundle into this one's space, into {@link #frustum} (an instance's body's). */
    final MappedFrustum mapping = new MappedFrustum();
    /**
     * Whether any ray of the bundle {@link #mapping} carried last may meet the bodies: false only when
     * its gather here found it open.
     */
    boolean carriedMeets;
    /**
     * The tree's bodies the gather found, in leaf order; a mesh's triangle is −1 here, its numbers in
     * {@link #gatheredTriangles}.
     */
    final int[] gathered = new int[MAX_GATHERED];
    /** Per body the gather found that is a mesh's triangle, at its place: its {@value #GATHERED_TRIANGLE} numbers. */
    final double[] gatheredTriangles = new double[GATHERED_TRIANGLE * MAX_GATHERED];
    /** How many bodies the gather found, or −1 when they were too many (a subtree was kept). */
    int gatheredCount;
    /**
     * The instances among the bodies the gather found, apart from {@link #gathered}: a ray tests
     * them after the others, and a packet takes each on together, in the body's own tree.
     */
    final Instance[] gatheredInstances = new Instance[MAX_GATHERED];
    int instanceCount;
    /**
     * When the frustum's ray origins are set: per origin, {@link ShadowFrustum#ABOVE} or
     * {@link ShadowFrustum#BELOW} as its {@link ShadowFrustum#originOf} tells, the places in
     * {@link #gathered} of the bodies a ray from there tests, in order (not the triangles behind
     * that origin), and how many. Place 0 is not used: a ray from neither origin tests them all.
     */
    final int[][] originLists = new int[3][MAX_GATHERED];
    final int[] originCounts = new int[3];
    /** When the gather found too many bodies: the node below which all of them lie. */
    int subtree;
    /**
     * The node whose subtree this query's last gather kept, or −1, and how many gathers in a row kept it
     * at once: the next gather whose walk first branches there keeps it too, unless
     * {@link BundleGather#MAX_KEPT} did already.
     */
    int overflowedAt = -1;
    int keptSince;
    /** The unbounded bodies the gather found, and how many. */
    final Geometry[] gatheredUnbounded;
    int unboundedCount;
    /** The cores of closed meshes ({@link ClosedMeshBlockers}) the gather found across some of the bundle's rays, and how many. */
    final int[] coreList = new int[ClosedMeshBlockers.MAX_CORES];
    int coreCount;
    /** Whether the last gather tried the closed meshes, and found one that blocks every ray of the bundle. */
    boolean blockersTried;
    boolean blocked;
    /** The packet of shadow rays. */
    final Packet packet;

    Query(int stackSize, int unboundedLength) {
        this.stack = new int[stackSize];
        this.entries = new double[stackSize];
        this.packet = new Packet(stackSize);
        this.gatheredUnbounded = new Geometry[unboundedLength];
    }

    /**
     * Sets the single ray of the next query: its origin, unit direction and the distance that counts.
     *
     * @param ox   the ray's origin, x
     * @param oy   the ray's origin, y
     * @param oz   the ray's origin, z
     * @param dx   the ray's unit direction, x
     * @param dy   the ray's unit direction, y
     * @param dz   the ray's unit direction, z
     * @param maxT the distance along the ray (to the light)
     * @return this query
     */
    public Query setRay(double ox, double oy, double oz, double dx, double dy, double dz, double maxT) {
        ray.set(ox, oy, oz, dx, dy, dz, maxT);
        return this;
    }

    /** {@return the pyramid of the shadow bundle the next {@link BoundingVolumeHierarchy#gather} looks at} */
    public ShadowFrustum getFrustum() {
        return frustum;
    }

    /**
     * Whether the last {@link BoundingVolumeHierarchy#gather} kept a subtree, its bodies too many to
     * keep one by one (or those of the gather before, whose subtree it kept again): the bundle's rays
     * are then best traced together, by {@link BoundingVolumeHierarchy#packetTransmittances}.
     *
     * @return true when a subtree was kept
     */
    public boolean isSubtreeGathered() {
        return gatheredCount < 0;
    }

    /**
     * Whether the rays of the last {@link BoundingVolumeHierarchy#gather}'s bundle are best traced
     * together, by {@link BoundingVolumeHierarchy#packetTransmittances}: a subtree was kept, or an
     * {@link Instance} was gathered (its body's tree then takes the rays on as a packet, in its own
     * space).
     *
     * @return true when the bundle's rays are best traced as a packet
     */
    public boolean isPacketTraced() {
        return gatheredCount < 0 || instanceCount > 0;
    }

    /**
     * Forgets the subtree the last {@link BoundingVolumeHierarchy#gather} kept, which the next gather
     * could keep again at once: the next gathers then depend on no earlier one. A renderer calls it at
     * the start of every tile, so that a picture does not depend on the tiles a thread rendered before
     * (through the order in which the {@code kT} of several bodies multiply).
     */
    public void forgetLastGather() {
        overflowedAt = -1;
    }

    /** Empties the packet of rays {@link BoundingVolumeHierarchy#packetTransmittances} traces. */
    public void clearPacket() {
        packet.size = 0;
    }

    /** {@return the number of rays in the packet} */
    public int getPacketSize() {
        return packet.size;
    }

    /**
     * Adds a ray of the bundle of the last {@link BoundingVolumeHierarchy#gather} to the packet, as
     * for {@link BoundingVolumeHierarchy#bundleRayTransmittance}: its answer is the ray's number in
     * the packet, from 0.
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
        packet.add().set(ox, oy, oz, dx, dy, dz, maxT);
    }

    /**
     * The answer of a ray of the packet, once {@link BoundingVolumeHierarchy#packetTransmittances}
     * has traced it.
     *
     * @param ray the ray's number in the packet, from 0
     * @return its transparency in [0, 1]
     * @throws IllegalArgumentException when there is no such ray in the packet
     */
    public double getTransmittance(int ray) {
        if (ray < 0 || ray >= packet.size)
            throw new IllegalArgumentException("the packet has rays 0 to " + (packet.size - 1) + ", got " + ray);
        return packet.rays[ray].ktr;
    }
}
