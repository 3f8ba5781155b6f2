package accel;

/**
 * The tree's nodes in flat arrays: per node its box, in floats, and two ints (a leaf's first body and
 * body count, an inner node's left child and split axis; the two children of a node are neighbours).
 */
final class BvhNodes {
    /**
     * Per node: its box, in floats rounded outward like {@link LeafBodies#triangleBounds}: a ray or a
     * bundle may then enter a node more, never one less, so every answer stays the same, and the walks
     * read half the memory.
     */
    final float[] bounds;
    /**
     * Two ints per node: a leaf's first body and its body count (positive); an inner node's left
     * child (its right child is the node after it) and −1 − its split axis.
     */
    final int[] links;
    final int count;
    final int depth;

    /** Keeps the nodes the builder made, their boxes rounded outward into floats. */
    BvhNodes(BvhBuilder builder) {
        this.bounds = new float[6 * builder.nodesCount];
        for (int node = 0; node < builder.nodesCount; ++node)
            roundOutward(builder.nodeBounds, bounds, 6 * node);
        this.links = builder.nodeLinks;
        this.count = builder.nodesCount;
        this.depth = builder.depth;
    }

    /**
     * Where a ray enters a node's box between its origin and maxT, or {@link RayState#MISSED}: the slab
     * test on the box's numbers.
     *
     * @param node the node
     * @param ray  the ray, {@link RayState#invert inverted}
     * @param maxT the largest distance that counts
     * @return the distance (0 or more) where the ray enters the box, or {@link RayState#MISSED}
     */
    double entry(int node, RayState ray, double maxT) {
        return ray.boxEntry(bounds, 6 * node, maxT);
    }

    /** {@return the largest extent of the root's box, 0 for a tree without nodes} */
    double largestExtent() {
        return count == 0 ? 0 : Math.max(bounds[3] - bounds[0], Math.max(bounds[4] - bounds[1], bounds[5] - bounds[2]));
    }

    /**
     * Copies a box from doubles into floats, each bound rounded outward, so the box in floats holds
     * the one in doubles.
     *
     * @param boxes  the boxes in doubles
     * @param target the boxes in floats
     * @param b      where the box lies in both
     */
    static void roundOutward(double[] boxes, float[] target, int b) {
        for (int k = 0; k < 3; ++k) {
            float low = (float) boxes[b + k];
            float high = (float) boxes[b + 3 + k];
            target[b + k] = low > boxes[b + k] ? Math.nextDown(low) : low;
            target[b + 3 + k] = high < boxes[b + 3 + k] ? Math.nextUp(high) : high;
        }
    }
}
