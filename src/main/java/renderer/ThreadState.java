package renderer;

import geometries.BoundingVolumeHierarchy;

/**
 * What one rendering thread keeps for itself in a ray tracer, so that the per-pixel path takes no
 * lock: the current pixel's random stream, room for sample points and shadow rays, and the thread's ray
 * counts.
 */
final class ThreadState {
    /** The random stream of the pixel being rendered. */
    final SplitMix64 random;
    /** The rays traced from the camera by this thread. */
    long primaryRays;
    /** The shadow rays traced by this thread. */
    long shadowRays;
    /** The shadow rays of this thread whose bundle nothing could block. */
    long openShadowRays;
    private double[] points = new double[0];
    private BoundingVolumeHierarchy queried;
    private BoundingVolumeHierarchy.Query query;
    private RayTracerBasic.LightSquare lightSquare;

    /**
     * Creates the state of a thread.
     *
     * @param random the stream for rays traced before any pixel is started
     */
    ThreadState(SplitMix64 random) {
        this.random = random;
    }

    /**
     * Room for a grid's sample points, reused from call to call.
     *
     * @param grid the grid
     * @return an array of at least 2 k² doubles
     */
    double[] points(JitteredGrid grid) {
        int length = 2 * grid.getSamplesCount();
        if (points.length < length)
            points = new double[length];
        return points;
    }

    /** {@return this thread's light square, set again for every lit point: the shadow path allocates nothing} */
    RayTracerBasic.LightSquare lightSquare() {
        if (lightSquare == null)
            lightSquare = new RayTracerBasic.LightSquare();
        return lightSquare;
    }

    /**
     * Scratch space for queries on a hierarchy, reused while the hierarchy stays the same.
     *
     * @param bvh the hierarchy
     * @return this thread's query for it
     */
    BoundingVolumeHierarchy.Query query(BoundingVolumeHierarchy bvh) {
        if (queried != bvh) {
            query = bvh.newQuery();
            queried = bvh;
        }
        return query;
    }
}
