package renderer;

import java.util.Arrays;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import primitives.Color;

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
    /** The shadow rays of this thread whose bundle a closed opaque mesh blocked whole. */
    long blockedShadowRays;
    /** The nanoseconds this thread spent tracing the rays of soft-shadow bundles neither open nor blocked. */
    long bundleTracingNanos;
    /** The reflected and refracted rays spread by glossy and blurry surfaces on this thread. */
    long spreadRays;
    /** Whether this thread is tracing the rays of a glossy or blurry beam (which spread no beam of their own). */
    boolean inSpreadBeam;
    private double[] points = new double[0];
    private double[] spreadPoints = new double[0];
    /** Room for the one jittered point of a spread ray inside a beam. */
    private final double[] spreadPoint = new double[2];
    private BoundingVolumeHierarchy queried;
    private Query query;
    private double[] pixelPoints = new double[0];
    private double[] aperturePoints = new double[0];
    /** The colours seen through the lattice points of the pixel being sampled adaptively. */
    private Color[] lattice = new Color[0];
    /** The pixel a lattice point's colour belongs to: its entry is current when it equals {@link #latticePixel}. */
    private int[] latticeStamps = new int[0];
    private int latticePixel;
    private final LightSquare lightSquare = new LightSquare();

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
        return points = room(points, grid);
    }

    /**
     * Room for the sample points of a pixel (anti-aliasing), apart from those of shadows and aperture.
     *
     * @param grid the pixel's grid
     * @return an array of at least 2 k² doubles
     */
    double[] pixelPoints(JitteredGrid grid) {
        return pixelPoints = room(pixelPoints, grid);
    }

    /**
     * Room for the sample points of the camera's aperture (depth of field), apart from the others.
     *
     * @param grid the aperture's grid
     * @return an array of at least 2 k² doubles
     */
    double[] aperturePoints(JitteredGrid grid) {
        return aperturePoints = room(aperturePoints, grid);
    }

    private static double[] room(double[] array, JitteredGrid grid) {
        int length = 2 * grid.getSamplesCount();
        return array.length < length ? new double[length] : array;
    }

    /**
     * Starts a pixel's lattice of sample points (adaptive super-sampling): every point is unknown.
     *
     * @param size the number of points in the lattice
     */
    void startLattice(int size) {
        if (lattice.length < size) {
            lattice = new Color[size];
            latticeStamps = new int[size];
        }
        if (++latticePixel == 0) { // after 2³² pixels: forget every stamp rather than take an old one for current
            Arrays.fill(latticeStamps, 0);
            latticePixel = 1;
        }
    }

    /**
     * The colour seen through a lattice point of the current pixel.
     *
     * @param point the point's index
     * @return its colour, or null when it has not been traced for this pixel yet
     */
    Color latticeColor(int point) {
        return latticeStamps[point] == latticePixel ? lattice[point] : null;
    }

    /**
     * Keeps the colour seen through a lattice point of the current pixel.
     *
     * @param point the point's index
     * @param color its colour
     * @return the colour
     */
    Color keepLatticeColor(int point, Color color) {
        lattice[point] = color;
        latticeStamps[point] = latticePixel;
        return color;
    }

    /**
     * Room for the sample points of a glossy or blurry beam, reused from call to call and apart from
     * {@link #points(JitteredGrid)}, which the shadow rays of the beam's rays use meanwhile.
     *
     * @param grid the grid
     * @return an array of at least 2 k² doubles
     */
    double[] spreadPoints(JitteredGrid grid) {
        return spreadPoints = room(spreadPoints, grid);
    }

    /** {@return room for the one jittered point of a spread ray inside a beam (2 doubles)} */
    double[] spreadPoint() {
        return spreadPoint;
    }

    /** {@return this thread's light square, set again for every lit point: the shadow path allocates nothing} */
    LightSquare lightSquare() {
        return lightSquare;
    }

    /**
     * Starts a tile of pixels: the query forgets what its last gather kept ({@link Query#forgetLastGather}),
     * so the tile's pixels depend on nothing rendered before.
     */
    void startTile() {
        if (query != null)
            query.forgetLastGather();
    }

    /**
     * Scratch space for queries on a hierarchy, reused while the hierarchy stays the same.
     *
     * @param bvh the hierarchy
     * @return this thread's query for it
     */
    Query query(BoundingVolumeHierarchy bvh) {
        if (queried != bvh) {
            query = bvh.newQuery();
            queried = bvh;
        }
        return query;
    }
}
