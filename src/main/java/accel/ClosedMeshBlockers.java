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
 * The closed parts of the tree's opaque meshes as blockers of whole bundles: a part whose core, its
 * inner ball ({@link InnerBall}) or one of its inner boxes ({@link InnerBoxes}), lies across every ray
 * of a bundle blocks the bundle at the gather ({@link CoreCrossing}), and a packet's ray through such
 * a core is blocked before the walk.
 */
final class ClosedMeshBlockers {
    /** The most closed meshes whose cores the gather tries: those of the largest cores. */
    static final int MAX_BLOCKERS = 16;

    /**
     * The closed parts that have a core, the largest cores first: of the tree's meshes
     * ({@link ClosedParts}), its course-style {@link Triangle} objects among them ({@link PackedTriangles}).
     */
    private final Blocker[] blockers;
    /** Per blocker of triangles: whether all of them were opaque when {@link #readMaterials} last looked. */
    private final boolean[] opaque;

    /**
     * A closed part: its mesh (whose material says whether it is opaque), or null for packed
     * triangles, then the triangles; and the part, with its cores and its box.
     */
    private record Blocker(TriangleMesh mesh, Triangle[] triangles, ClosedParts.Part part) {
    }

    /**
     * Finds the blockers among the tree's geometries.
     *
     * @param owners  the tree's geometries (none for a brute-force scan)
     * @param packed  the tree's course-style triangles packed into one of its meshes, or null
     * @param threads the number of threads the meshes look for their closed parts on
     */
    ClosedMeshBlockers(Geometry[] owners, PackedTriangles packed, int threads) {
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
        this.opaque = new boolean[blockers.length];
        readMaterials();
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
     * Tries the closed opaque meshes on the query's bundle: keeps those whose boxes the pyramid meets,
     * its base outside them, unless the core of one lies across every ray (the bundle is then blocked).
     *
     * @param query this thread's scratch space, its frustum set
     * @return true when one lies across every ray of the bundle
     */
    boolean tryOn(Query query) {
        query.blockersTried = true;
        ShadowFrustum frustum = query.frustum;
        int count = 0;
        for (int s = 0; s < blockers.length; ++s) {
            ClosedParts.Part part = blockers[s].part;
            if (!isOpaque(s) || !frustum.meetsBox(part.box(), 0) || !CoreCrossing.baseOutside(frustum, part.box(), 0))
                continue;
            if (crossesCore(frustum, part)) {
                query.blocked = true;
                return true;
            }
            query.blockerList[count++] = s;
        }
        query.blockerCount = count;
        return false;
    }

    /** Whether every ray of the pyramid passes through the part's inner ball or one of its inner boxes. */
    private static boolean crossesCore(ShadowFrustum frustum, ClosedParts.Part part) {
        if (part.ball() != null && CoreCrossing.sectionInside(frustum, part.ball()))
            return true;
        double[] inner = part.innerBoxes();
        for (int b = 0; b < inner.length; b += 6)
            if (CoreCrossing.crossesBox(frustum, inner, b))
                return true;
        return false;
    }

    /**
     * Answers 0 for each unblocked ray of the packet, {@link RayState#invert inverted}, that passes
     * through a core of a closed mesh the gather kept (one the pyramid meets): it crosses that closed
     * opaque mesh.
     *
     * @param query this thread's scratch space, as the last gather left it, its packet filled
     * @return the number of rays so blocked
     */
    int blockPacket(Query query) {
        int blocked = 0;
        for (int k = 0; k < query.blockerCount; ++k) {
            ClosedParts.Part part = blockers[query.blockerList[k]].part;
            InnerBall ball = part.ball();
            if (ball != null && query.frustum.meetsBox(ball.box(), 0))
                blocked += blockThrough(query.packet, ball, null, 0);
            double[] inner = part.innerBoxes();
            for (int b = 0; b < inner.length; b += 6)
                if (query.frustum.meetsBox(inner, b))
                    blocked += blockThrough(query.packet, null, inner, b);
        }
        return blocked;
    }

    /**
     * Answers 0 for each unblocked ray of the packet through a ball, or else through a box.
     *
     * @param ball  the ball, or null for the box
     * @param boxes the boxes, {minX, minY, minZ, maxX, maxY, maxZ} each
     * @param b     where the box lies in them
     * @return the number of rays so blocked
     */
    private static int blockThrough(Packet packet, InnerBall ball, double[] boxes, int b) {
        int blocked = 0;
        for (int r = 0; r < packet.size; ++r) {
            RayState ray = packet.rays[r];
            if (ray.ktr > 0 && (ball != null ? ball.crossedBy(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz, ray.maxT)
                    : ray.boxEntry(boxes, b, ray.maxT) != RayState.MISSED)) {
                ray.ktr = 0;
                ++blocked;
            }
        }
        return blocked;
    }
}
