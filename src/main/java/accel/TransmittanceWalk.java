package accel;

import geometries.Geometry;
import geometries.TriangleMesh;

/**
 * The transmittance of a single ray (pbrt's IntersectP, with transparent bodies): the product of the
 * {@code kT} of every body the ray meets before its distance, stopped at the first body that blocks
 * it. The unbounded bodies are tested first, then the tree is walked with an explicit stack, the
 * nearer child (by the split axis) entered first.
 */
final class TransmittanceWalk {
    private final BvhNodes nodes;
    private final LeafBodies bodies;

    TransmittanceWalk(BvhNodes nodes, LeafBodies bodies) {
        this.nodes = nodes;
        this.bodies = bodies;
    }

    /**
     * The share of light that passes along a ray up to its distance: the product of the {@code kT} of
     * every intersection before it, 0 as soon as an opaque body is met or the product falls below
     * minK.
     *
     * @param query this thread's scratch space
     * @param ray   the ray
     * @param minK  below this product the answer is 0
     * @return the transparency in [0, 1]
     */
    double transmittance(Query query, RayState ray, double minK) {
        ray.startTransmittance(minK);
        return throughTree(query, ray) ? bodies.throughOthers(ray, ray.ktr) : 0;
    }

    /** Attenuates the ray by the unbounded bodies and the tree's; false when they block it. */
    private boolean throughTree(Query query, RayState ray) {
        for (Geometry body : bodies.unbounded)
            if (!ray.attenuateBy(body))
                return false;
        return nodes.count == 0 || walk(query, ray, 0);
    }

    /**
     * Attenuates the ray by the bodies of the subtree below a node whose boxes it meets.
     *
     * @param query this thread's scratch space
     * @param ray   the ray, its transmittance started
     * @param root  the subtree's root
     * @return false when the ray is blocked (the walk stopped early)
     */
    boolean walk(Query query, RayState ray, int root) {
        ray.invert();
        double maxT = ray.maxT;
        if (nodes.entry(root, ray, maxT) == RayState.MISSED)
            return true;
        int negative = ray.negative;
        int[] links = nodes.links;
        int[] stack = query.stack;
        int top = 0;
        int node = root;
        while (true) {
            int first = links[2 * node];
            int count = links[2 * node + 1];
            if (count < 0) {
                int near = first + (negative >> (-1 - count) & 1);
                int far = 2 * first + 1 - near;
                boolean nearMeets = nodes.entry(near, ray, maxT) != RayState.MISSED;
                boolean farMeets = nodes.entry(far, ray, maxT) != RayState.MISSED;
                if (nearMeets) {
                    if (farMeets)
                        stack[top++] = far;
                    node = near;
                    continue;
                }
                if (farMeets) {
                    node = far;
                    continue;
                }
            } else
                for (int b = first; b < first + count; ++b)
                    if (!visit(ray, b))
                        return false;
            if (top == 0)
                return true;
            node = stack[--top];
        }
    }

    /**
     * Attenuates the ray by body b of the tree; a mesh's triangle is tested from the mesh's arrays,
     * and the mesh's material read only on a hit.
     *
     * @return false when the ray is blocked
     */
    private boolean visit(RayState ray, int b) {
        int part = bodies.bodyPart[b];
        if (part < 0)
            return ray.attenuateBy(bodies.owner(b));
        TriangleMesh mesh = (TriangleMesh) bodies.owner(b);
        double t = mesh.triangleHit(part, ray);
        return t == Geometry.NO_HIT || ray.attenuate(bodies.kT(mesh, part));
    }
}
