package accel;

import geometries.Geometry;
import geometries.Triangle;
import geometries.TriangleMesh;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;

import primitives.Parallel;

/**
 * The closed parts of the tree's opaque meshes as blockers of whole bundles: a part one of whose
 * cores, its inner boxes ({@link InnerBoxes}), lies across every ray of a bundle blocks the bundle
 * at the gather ({@link CoreCrossing}), and a packet's ray through such a core is blocked before
 * the walk. A part closed by caps over its holes ({@link HoleCaps}) blocks so only the bundles and
 * rays that meet none of its caps' boxes.
 */
final class ClosedMeshBlockers {
    /** The most closed meshes whose cores the gather tries: those of the largest cores. */
    static final int MAX_BLOCKERS = 16;
    /** The most cores, of all the blockers together, the gather tries: the largest. */
    static final int MAX_CORES = 64;
    /**
     * The smallest core tried, relative to the tree's largest extent: a smaller one rarely holds a
     * bundle's cross-section or meets a packet's ray, and each costs the gather its tests (on ogre's
     * 36 small closed parts, 7 % of a frame, for no bundle blocked).
     */
    static final double MIN_CORE = 0.01;

    /**
     * The closed parts that have a core, the largest cores first: of the tree's meshes
     * ({@link ClosedParts}), its course-style {@link Triangle} objects among them ({@link PackedTriangles}).
     */
    private final Blocker[] blockers;
    /** The blockers' cores, the largest first. */
    private final Core[] cores;
    /** Per blocker of triangles: whether all of them were opaque when {@link #readMaterials} last looked. */
    private final boolean[] opaque;

    /**
     * A closed part: its mesh (whose material says whether it is opaque), or null for packed
     * triangles, then the triangles; and the part, with its cores and its box.
     */
    private record Blocker(TriangleMesh mesh, Triangle[] triangles, ClosedParts.Part part) {
    }

    /**
     * A core of a blocker: one of its inner boxes.
     *
     * @param blocker the blocker's place in {@link #blockers}
     * @param box     the inner box, {minX, minY, minZ, maxX, maxY, maxZ}
     */
    private record Core(int blocker, double[] box) {
        /** {@return the core's size: half its box's shortest side} */
        double size() {
            return InnerBoxes.halfShortestSide(box, 0);
        }
    }

    /**
     * Finds the blockers among the tree's geometries.
     *
     * @param owners  the tree's geometries (none for a brute-force scan)
     * @param packed  the tree's course-style triangles packed into one of its meshes, or null
     * @param threads the number of threads the meshes look for their closed parts on
     * @param extent  the largest extent of the tree's box: cores below {@value #MIN_CORE} of it are left out
     */
    ClosedMeshBlockers(Geometry[] owners, PackedTriangles packed, int threads, double extent) {
        TriangleMesh[] all = Arrays.stream(owners).filter(TriangleMesh.class::isInstance)
                .map(TriangleMesh.class::cast).toArray(TriangleMesh[]::new);
        Parallel.forEach(all.length, threads, BvhBuilder.BUILD_THREADS, m -> ClosedParts.of(all[m]));
        List<Blocker> found = new ArrayList<>();
        for (TriangleMesh mesh : all)
            for (ClosedParts.Part part : ClosedParts.of(mesh)) {
                boolean isPacked = packed != null && packed.isMesh(mesh);
                Triangle[] triangles = isPacked ? Arrays.stream(part.triangles()).mapToObj(t -> packed.triangles[t])
                        .toArray(Triangle[]::new) : null;
                found.add(new Blocker(isPacked ? null : mesh, triangles, part));
            }
        this.blockers = found.stream().sorted(Comparator.comparingDouble((Blocker blocker) -> blocker.part.coreSize())
                .reversed()).limit(MAX_BLOCKERS).toArray(Blocker[]::new);
        this.cores = cores(blockers, MIN_CORE * extent);
        this.opaque = new boolean[blockers.length];
        readMaterials();
    }

    /** {@return the largest {@value #MAX_CORES} cores of some blockers not smaller than least, the largest first} */
    private static Core[] cores(Blocker[] blockers, double least) {
        List<Core> all = new ArrayList<>();
        for (int s = 0; s < blockers.length; ++s) {
            ClosedParts.Part part = blockers[s].part;
            double[] inner = part.innerBoxes();
            for (int b = 0; b < inner.length; b += 6)
                all.add(new Core(s, Arrays.copyOfRange(inner, b, b + 6)));
        }
        return all.stream().filter(core -> core.size() >= least).sorted(Comparator.comparingDouble(Core::size).reversed())
                .limit(MAX_CORES).toArray(Core[]::new);
    }

    /**
     * Reads again whether the parts of course-style triangles are opaque: every triangle's {@code kT}
     * 0 (a mesh's part reads its one material at every gather).
     */
    void readMaterials() {
        for (int s = 0; s < blockers.length; ++s)
            opaque[s] = blockers[s].triangles != null
                    && Arrays.stream(blockers[s].triangles).allMatch(triangle -> triangle.getMaterial().getKt() == 0);
    }

    /** {@return whether blocker s is opaque} */
    private boolean isOpaque(int s) {
        TriangleMesh mesh = blockers[s].mesh;
        return mesh != null ? mesh.getMaterial().getKt() == 0 : opaque[s];
    }

    /**
     * Tries the cores of the closed opaque meshes on the query's bundle: keeps those the pyramid meets,
     * of meshes whose boxes it meets with its base outside them, unless one lies across every ray (the
     * bundle is then blocked).
     *
     * @param query this thread's scratch space, its frustum set
     * @return true when one lies across every ray of the bundle
     */
    boolean tryOn(Query query) {
        query.blockersTried = true;
        ShadowFrustum frustum = query.frustum;
        int candidates = 0; // a bit per blocker: opaque, its box met by the pyramid, the base outside it
        for (int s = 0; s < blockers.length; ++s) {
            double[] box = blockers[s].part.box();
            if (isOpaque(s) && frustum.meetsBox(box, 0) && CoreCrossing.baseOutside(frustum, box, 0))
                candidates |= 1 << s;
        }
        int count = 0;
        for (int c = 0; c < cores.length && candidates != 0; ++c) {
            Core core = cores[c];
            if ((candidates & 1 << core.blocker) == 0 || !frustum.meetsBox(core.box, 0))
                continue;
            if (CoreCrossing.crossesBox(frustum, core.box, 0) && !meetsCaps(frustum, core)) {
                query.blocked = true;
                return true;
            }
            query.coreList[count++] = c;
        }
        query.coreCount = count;
        return false;
    }

    /** {@return whether a bundle's pyramid meets the box of a cap over a hole of the core's part: a ray may leave through it} */
    private boolean meetsCaps(ShadowFrustum frustum, Core core) {
        double[] caps = blockers[core.blocker].part.capBoxes();
        for (int b = 0; b < caps.length; b += 6)
            if (frustum.meetsBox(caps, b))
                return true;
        return false;
    }

    /** {@return whether a ray meets the box of a cap over a hole of the core's part: it may leave through it} */
    private boolean meetsCaps(RayState ray, Core core) {
        double[] caps = blockers[core.blocker].part.capBoxes();
        for (int b = 0; b < caps.length; b += 6)
            if (ray.boxEntry(caps, b, ray.maxT) != RayState.MISSED)
                return true;
        return false;
    }

    /**
     * Answers 0 for each unblocked ray of the packet, {@link RayState#invert inverted}, that passes
     * through a core the gather kept: it crosses that core's closed opaque mesh.
     *
     * @param query this thread's scratch space, as the last gather left it, its packet filled
     * @return the number of rays so blocked
     */
    int blockPacket(Query query) {
        Packet packet = query.packet;
        int blocked = 0;
        for (int k = 0; k < query.coreCount; ++k) {
            Core core = cores[query.coreList[k]];
            for (int r = 0; r < packet.size; ++r) {
                RayState ray = packet.rays[r];
                if (ray.ktr > 0 && ray.boxEntry(core.box, 0, ray.maxT) != RayState.MISSED && !meetsCaps(ray, core)) {
                    ray.ktr = 0;
                    ++blocked;
                }
            }
        }
        return blocked;
    }
}
