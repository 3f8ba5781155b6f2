package renderer;

import geometries.BoundingVolumeHierarchy;

/**
 * What one rendering thread keeps for itself in a ray tracer, so that the per-pixel path takes no
 * lock: the current pixel's random stream, room for sample points, and the thread's ray counts.
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
    /** The reflected and refracted rays spread by glossy and blurry surfaces on this thread. */
    long spreadRays;
    /** Whether this thread is tracing the rays of a glossy or blurry beam (which spread no beam of their own). */
    boolean inSpreadBeam;
    private double[] points = new double[0];
    private double[] spreadPoints = new double[0];
    /** Room for the one jittered point of a spread ray inside a beam. */
    private final double[] spreadPoint = new double[2];
    private BoundingVolumeHierarchy queried;
    private BoundingVolumeHierarchy.Query query;

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

    /**
     * Room for the sample points of a glossy or blurry beam, reused from call to call and apart from
     * {@link #points(JitteredGrid)}, which the shadow rays of the beam's rays use meanwhile.
     *
     * @param grid the grid
     * @return an array of at least 2 k² doubles
     */
    double[] spreadPoints(JitteredGrid grid) {
        int length = 2 * grid.getSamplesCount();
        if (spreadPoints.length < length)
            spreadPoints = new double[length];
        return spreadPoints;
    }

    /** {@return room for the one jittered point of a spread ray inside a beam (2 doubles)} */
    double[] spreadPoint() {
        return spreadPoint;
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
