package accel;

import geometries.Geometry;
import geometries.TriangleMesh;

/**
 * The closest hit of a single ray (pbrt's Intersect): the unbounded bodies are tested first, then the
 * tree is walked with an explicit stack, the nearer child (by the split axis) entered first, and each
 * hit shrinks the ray's distance.
 */
final class ClosestHitWalk {
    private final BvhNodes nodes;
    private final LeafBodies bodies;

    ClosestHitWalk(BvhNodes nodes, LeafBodies bodies) {
        this.nodes = nodes;
        this.bodies = bodies;
    }

    /**
     * Finds the nearest body the ray hits: leaves it, its part and its distance in the ray.
     *
     * @param query this thread's scratch space
     * @param ray   the ray
     */
    void closestHit(Query query, RayState ray) {
        ray.startClosestHit();
        for (Geometry body : bodies.unbounded)
            ray.keepNearer(body.nearestHit(ray), body, -1);
        if (nodes.count > 0)
            walk(query, ray);
    }

    /**
     * Walks the tree. The stack keeps with each node set aside the distance where the ray enters its
     * box, so the walk skips it when a nearer hit has been found since (the box test again, with the
     * shrunk distance, would fail: the answer is the same, found with fewer tests).
     */
    private void walk(Query query, RayState ray) {
        ray.invert();
        double maxT = ray.maxT;
        if (nodes.entry(0, ray, maxT) == RayState.MISSED)
            return;
        int negative = ray.negative;
        int[] links = nodes.links;
        int[] stack = query.stack;
        double[] entries = query.entries;
        int top = 0;
        int node = 0;
        while (true) {
            int first = links[2 * node];
            int count = links[2 * node + 1];
            if (count < 0) {
                int near = first + (negative >> (-1 - count) & 1);
                int far = 2 * first + 1 - near;
                double nearEntry = nodes.entry(near, ray, maxT);
                double farEntry = nodes.entry(far, ray, maxT);
                if (nearEntry != RayState.MISSED) {
                    if (farEntry != RayState.MISSED) {
                        entries[top] = farEntry;
                        stack[top++] = far;
                    }
                    node = near;
                    continue;
                }
                if (farEntry != RayState.MISSED) {
                    node = far;
                    continue;
                }
            } else {
                for (int b = first; b < first + count; ++b)
                    visit(ray, b);
                maxT = ray.maxT;
            }
            do {
                if (top == 0)
                    return;
                node = stack[--top];
            } while (entries[top] > maxT);
        }
    }

    /**
     * Keeps body b of the tree when the ray hits it nearer; a mesh's triangle is tested from the
     * mesh's arrays.
     */
    private void visit(RayState ray, int b) {
        int part = bodies.bodyPart[b];
        Geometry body = bodies.owner(b);
        if (part < 0) {
            ray.keepNearer(body.nearestHit(ray), body, -1);
            return;
        }
        double t = ((TriangleMesh) body).triangleHit(part, ray);
        if (t != Geometry.NO_HIT)
            ray.keepNearer(t, body, part);
    }
}
