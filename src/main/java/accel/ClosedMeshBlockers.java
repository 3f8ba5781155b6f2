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
 * The closed parts of the tree's opaque meshes as blockers of whole bundles: a part whose inner ball
 * ({@link InnerBall}) lies across every ray of a bundle blocks the bundle at the gather, and a
 * packet's ray through such a ball is blocked before the walk.
 */
final class ClosedMeshBlockers {
    /** The most closed meshes whose inner balls the gather tries: those of the largest balls. */
    static final int MAX_BLOCKERS = 16;

    /**
     * The closed parts that have an inner ball, the largest balls first: of the tree's meshes
     * ({@link ClosedParts}), its course-style {@link Triangle} objects among them ({@link PackedTriangles}).
     */
    private final Blocker[] blockers;
    /** Per blocker of triangles: whether all of them were opaque when {@link #readMaterials} last looked. */
    private final boolean[] opaque;

    /**
     * A closed part: its mesh (whose material says whether it is opaque), or null for packed
     * triangles, then the triangles; its ball and its box.
     */
    private record Blocker(TriangleMesh mesh, Triangle[] triangles, InnerBall ball, double[] box) {
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
                found.add(new Blocker(isPacked ? null : mesh, triangles, part.ball(), part.box()));
            }
        this.blockers = found.stream().sorted(Comparator.comparingDouble((Blocker blocker) -> blocker.ball.radius)
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
     * Tries the closed opaque meshes on the query's bundle: keeps those whose inner balls the pyramid
     * meets, its base outside their boxes, unless one lies across every ray (the bundle is then
     * blocked).
     *
     * @param query this thread's scratch space, its frustum set
     * @return true when one lies across every ray of the bundle
     */
    boolean tryOn(Query query) {
        query.blockersTried = true;
        ShadowFrustum frustum = query.frustum;
        int count = 0;
        for (int s = 0; s < blockers.length; ++s) {
            InnerBall ball = blockers[s].ball;
            double[] box = blockers[s].box;
            if (!isOpaque(s) || !frustum.meetsBox(ball.box(), 0))
                continue;
            if (frustum.crossesClosedMesh(ball, box, 0)) {
                query.blocked = true;
                return true;
            }
            if (frustum.baseOutside(box, 0))
                query.blockerList[count++] = s;
        }
        query.blockerCount = count;
        return false;
    }

    /**
     * Answers 0 for each unblocked ray of the packet that passes through the ball of a closed mesh
     * the gather kept: it crosses that closed opaque mesh.
     *
     * @param query this thread's scratch space, as the last gather left it, its packet filled
     * @return the number of rays so blocked
     */
    int blockPacket(Query query) {
        RayState[] rays = query.packet.rays;
        int size = query.packet.size;
        int blocked = 0;
        for (int k = 0; k < query.blockerCount; ++k) {
            InnerBall ball = blockers[query.blockerList[k]].ball;
            for (int r = 0; r < size; ++r) {
                RayState ray = rays[r];
                if (ray.ktr > 0 && ball.crossedBy(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz, ray.maxT)) {
                    ray.ktr = 0;
                    ++blocked;
                }
            }
        }
        return blocked;
    }
}
