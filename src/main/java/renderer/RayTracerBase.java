package renderer;

import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.ToLongFunction;

import primitives.Color;
import primitives.Ray;
import scene.Scene;

import static primitives.Util.requireNonNull;

/**
 * A ray tracer: finds the colour a ray sees in a scene. It also holds the soft-shadow settings and
 * the random streams: every pixel gets its own stream, seeded from the pixel's position and the
 * tracer's seed, so a picture is the same bit for bit whatever the number of threads.
 */
public abstract class RayTracerBase {
    /** The default square root of the number of shadow rays per light: 9 × 9 = 81 rays. */
    public static final int DEFAULT_SQRT_BEAM_NUM = 9;
    /**
     * The default square root of the number of spread rays of a glossy or blurry surface: 5 × 5 = 25
     * reflected (or refracted) rays.
     */
    public static final int DEFAULT_SQRT_GLOSS_RAYS = 5;
    /** The default seed of the random streams. */
    public static final long DEFAULT_SEED = 20_210_621L;

    /** The scene traced. */
    protected final Scene scene;
    private JitteredGrid beamGrid = new JitteredGrid(DEFAULT_SQRT_BEAM_NUM);
    private JitteredGrid glossGrid = new JitteredGrid(DEFAULT_SQRT_GLOSS_RAYS);
    private boolean softShadows;
    private boolean adaptiveSoftShadows;
    private long seed = DEFAULT_SEED;
    private final Queue<ThreadState> threadStates = new ConcurrentLinkedQueue<>();
    private final ThreadLocal<ThreadState> threadState = ThreadLocal.withInitial(this::newThreadState);

    /**
     * Creates a ray tracer for a scene.
     *
     * @param scene the scene
     */
    protected RayTracerBase(Scene scene) {
        this.scene = requireNonNull(scene, "scene");
    }

    /**
     * The colour seen along a ray.
     *
     * @param ray the ray
     * @return the colour it sees (the background when it hits nothing)
     * @throws IllegalArgumentException when the ray is null
     */
    public abstract Color traceRay(Ray ray);

    /**
     * Gets ready to trace the scene as it is now: {@link Render} calls this before every render.
     * Nothing to do by default; a ray tracer with an acceleration structure builds it here.
     */
    protected void prepare() {
    }

    /**
     * Gets ready to trace the scene as it is now, on up to a number of threads: {@link Render} calls
     * this before every render, with its own number of threads. By default {@link #prepare()}.
     *
     * @param threads the number of threads the work may be shared among, 1 or more
     */
    protected void prepare(int threads) {
        prepare();
    }

    /**
     * Sets the number of shadow rays per light for soft shadows: sqrtBeamNum² rays to the light's
     * square, plus one to its centre.
     *
     * @param sqrtBeamNum the number of cells along each side of the light's square, 1 to
     *                    {@link JitteredGrid#MAX_SQRT_SAMPLES}
     * @return this ray tracer
     * @throws IllegalArgumentException when sqrtBeamNum is less than 1 or more than
     *                                  {@link JitteredGrid#MAX_SQRT_SAMPLES}
     */
    public RayTracerBase setSqrtBeamNum(int sqrtBeamNum) {
        JitteredGrid.requireSqrtSamples(sqrtBeamNum, "sqrtBeamNum");
        this.beamGrid = new JitteredGrid(sqrtBeamNum);
        return this;
    }

    /**
     * Sets the number of spread rays of glossy reflection and blurry transparency (materials with
     * {@code kG} or {@code kB} above 0): sqrtGlossRays² reflected (or refracted) rays through the
     * square around the sharp ray, at the first glossy or blurry surface a path meets. Below it, every
     * further glossy or blurry surface of the path spreads one jittered ray, so the rays of a pixel
     * grow linearly, not exponentially, with the depth of the recursion.
     *
     * @param sqrtGlossRays the number of cells along each side of the square, 1 to
     *                      {@link JitteredGrid#MAX_SQRT_SAMPLES}
     * @return this ray tracer
     * @throws IllegalArgumentException when sqrtGlossRays is less than 1 or more than
     *                                  {@link JitteredGrid#MAX_SQRT_SAMPLES}
     */
    public RayTracerBase setSqrtGlossRays(int sqrtGlossRays) {
        JitteredGrid.requireSqrtSamples(sqrtGlossRays, "sqrtGlossRays");
        this.glossGrid = new JitteredGrid(sqrtGlossRays);
        return this;
    }

    /**
     * Turns soft shadows on or off (off by default; when off, the size of lights is ignored).
     *
     * @param softShadows true for soft shadows from lights with an area
     * @return this ray tracer
     */
    public RayTracerBase setSoftShadows(boolean softShadows) {
        this.softShadows = softShadows;
        return this;
    }

    /**
     * Turns adaptive soft shadows on or off (off by default): the outline of the light's square is
     * sampled first, and when every ray agrees (all reach the light, or none does) the rest of the
     * square is skipped.
     *
     * @param adaptiveSoftShadows true for adaptive sampling
     * @return this ray tracer
     */
    public RayTracerBase setAdaptiveSoftShadows(boolean adaptiveSoftShadows) {
        this.adaptiveSoftShadows = adaptiveSoftShadows;
        return this;
    }

    /**
     * Sets the seed of the random streams: the same seed gives the same picture.
     *
     * @param seed the seed
     * @return this ray tracer
     */
    public RayTracerBase setSeed(long seed) {
        this.seed = seed;
        return this;
    }

    /** {@return the square root of the number of shadow rays per light} */
    public int getSqrtBeamNum() {
        return beamGrid.getSqrtSamples();
    }

    /** {@return the grid the shadow rays' points on a light's square come from} */
    public JitteredGrid getBeamGrid() {
        return beamGrid;
    }

    /** {@return the square root of the number of spread rays of a glossy or blurry surface} */
    public int getSqrtGlossRays() {
        return glossGrid.getSqrtSamples();
    }

    /** {@return the grid the spread rays of glossy and blurry surfaces pass through} */
    public JitteredGrid getGlossGrid() {
        return glossGrid;
    }

    /** {@return whether soft shadows are on} */
    public boolean isSoftShadows() {
        return softShadows;
    }

    /** {@return whether adaptive soft shadows are on} */
    public boolean isAdaptiveSoftShadows() {
        return adaptiveSoftShadows;
    }

    /** {@return the seed of the random streams} */
    public long getSeed() {
        return seed;
    }

    /** {@return the number of rays traced from the camera by renders of this ray tracer so far} */
    public long getPrimaryRaysCount() {
        return sum(state -> state.primaryRays);
    }

    /** {@return the number of shadow rays traced by this ray tracer so far} */
    public long getShadowRaysCount() {
        return sum(state -> state.shadowRays);
    }

    /**
     * The shadow rays of soft shadows whose whole bundle (the rays from one point to a light's square)
     * was found open: nothing can block any of them, so no body was tested. They are counted in
     * {@link #getShadowRaysCount()} too.
     *
     * @return the number of such rays traced by this ray tracer so far
     */
    public long getOpenShadowRaysCount() {
        return sum(state -> state.openShadowRays);
    }

    /**
     * The shadow rays of soft shadows whose whole bundle was found blocked: every ray passes through
     * the inside of a closed opaque mesh, so none was tested. They are counted in
     * {@link #getShadowRaysCount()} too.
     *
     * @return the number of such rays traced by this ray tracer so far
     */
    public long getBlockedShadowRaysCount() {
        return sum(state -> state.blockedShadowRays);
    }

    /**
     * The time the rendering threads of this ray tracer spent tracing the shadow rays of soft-shadow
     * bundles that were neither open nor blocked: the rays that walk the hierarchy (as packets, or
     * one by one against a gather). Elapsed time on each thread, summed: on a busy machine it also
     * counts the time a thread waited for a core.
     *
     * @return the nanoseconds so far
     */
    public long getBundleTracingNanos() {
        return sum(state -> state.bundleTracingNanos);
    }

    /**
     * The reflected and refracted rays spread by glossy and blurry surfaces (the sharp rays of
     * mirrors and clear glass are not counted).
     *
     * @return the number of such rays traced by this ray tracer so far
     */
    public long getSpreadRaysCount() {
        return sum(state -> state.spreadRays);
    }

    private long sum(ToLongFunction<ThreadState> counter) {
        long count = 0;
        for (ThreadState state : threadStates)
            count += counter.applyAsLong(state);
        return count;
    }

    /**
     * Starts a pixel on the calling thread: its random stream is reseeded from the seed and the
     * pixel's position.
     *
     * @param j the pixel's column
     * @param i the pixel's row
     * @return the thread's state, its stream now the pixel's
     */
    ThreadState startPixel(int j, int i) {
        ThreadState state = threadState.get();
        state.random.reseed(pixelSeed(j, i));
        return state;
    }

    /** {@return the calling thread's state} */
    ThreadState threadState() {
        return threadState.get();
    }

    /** Mixes the seed with a pixel's position (multipliers of the SplitMix64 finaliser). */
    private long pixelSeed(int j, int i) {
        long h = (seed ^ i) * 0xBF58476D1CE4E5B9L;
        h = (h ^ (h >>> 31) ^ j) * 0x94D049BB133111EBL;
        return h ^ (h >>> 29);
    }

    private ThreadState newThreadState() {
        ThreadState state = new ThreadState(new SplitMix64(seed));
        threadStates.add(state);
        return state;
    }
}
