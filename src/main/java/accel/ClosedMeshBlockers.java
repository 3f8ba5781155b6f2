package accel;

import geometries.Geometry;
import geometries.TriangleMesh;
import java.util.Arrays;
import java.util.Comparator;

import primitives.Parallel;

/**
 * The tree's closed opaque meshes as blockers of whole bundles: a mesh whose inner ball
 * ({@link InnerBall}) lies across every ray of a bundle blocks the bundle at the gather, and a
 * packet's ray through such a ball is blocked before the walk.
 */
final class ClosedMeshBlockers {
    /** The most closed meshes whose inner balls the gather tries: those of the largest balls. */
    static final int MAX_BLOCKERS = 16;

    /** The tree's closed meshes that have an inner ball, the largest balls first, their balls and their boxes. */
    private final TriangleMesh[] meshes;
    private final InnerBall[] balls;
    private final double[] boxes;

    /**
     * Finds the blockers among the tree's geometries.
     *
     * @param owners  the tree's geometries (none for a brute-force scan)
     * @param threads the number of threads the meshes look for their balls on
     */
    ClosedMeshBlockers(Geometry[] owners, int threads) {
        this.meshes = closedMeshesOf(owners, threads);
        this.balls = new InnerBall[meshes.length];
        this.boxes = new double[6 * meshes.length];
        for (int s = 0; s < meshes.length; ++s) {
            balls[s] = meshes[s].innerBall();
            meshes[s].bounds(boxes, 6 * s);
        }
    }

    /**
     * The closed meshes among the bodies of the tree that have an inner ball, at most
     * {@value #MAX_BLOCKERS} of them: those of the largest balls, in that order. The meshes look for
     * their balls (once each, see {@link TriangleMesh#innerBall}) on the build's threads.
     */
    private static TriangleMesh[] closedMeshesOf(Geometry[] owners, int threads) {
        TriangleMesh[] closed = Arrays.stream(owners).filter(TriangleMesh.class::isInstance)
                .map(TriangleMesh.class::cast).toArray(TriangleMesh[]::new);
        Parallel.forEach(closed.length, threads, BvhBuilder.BUILD_THREADS, m -> closed[m].innerBall());
        return Arrays.stream(closed).filter(mesh -> mesh.innerBall() != null)
                .sorted(Comparator.comparingDouble((TriangleMesh mesh) -> mesh.innerBall().radius).reversed())
                .limit(MAX_BLOCKERS).toArray(TriangleMesh[]::new);
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
        for (int s = 0; s < meshes.length; ++s) {
            InnerBall ball = balls[s];
            if (meshes[s].getMaterial().getKt() != 0 || !frustum.meetsBox(ball.box(), 0))
                continue;
            if (frustum.crossesClosedMesh(ball, boxes, 6 * s)) {
                query.blocked = true;
                return true;
            }
            if (frustum.baseOutside(boxes, 6 * s))
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
            InnerBall ball = balls[query.blockerList[k]];
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
