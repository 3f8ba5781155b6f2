package renderer;

import java.util.MissingResourceException;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongConsumer;

import primitives.Color;
import primitives.Parallel;
import scene.Scene;

import static primitives.Util.requireNonNull;

/**
 * Renders a picture: casts a ray from the camera through every pixel, traces it, and writes the
 * colour to the image. Pixels are rendered in square tiles by several threads (all cores by
 * default); each pixel's colour depends on nothing but the pixel, so the picture is the same bit
 * for bit whatever the number of threads.
 * <p>
 * With anti-aliasing, a pixel is the average of k × k jittered rays, or, with adaptive super-sampling,
 * of as few rays as its content needs. A camera with an aperture (depth of field) turns every ray
 * through a point of the pixel into n × n rays through its aperture, all aimed at the same point of
 * the focal plane, and the colour seen through the pixel's point is their average: k² · n² rays per
 * pixel in all (the aperture's points drawn anew for each point of the pixel).
 */
public class Render {
    /**
     * How much, in colour levels (0 to 255 on each of red, green and blue), the colour seen through a
     * square's centre may differ from that seen through one of its corners before adaptive
     * super-sampling divides the square.
     */
    public static final double ADAPTIVE_THRESHOLD = 4;

    /** The edge of a square tile of pixels handed to a thread at a time. */
    private static final int TILE = 16;
    /** How often, in milliseconds, the debug print reports progress. */
    private static final long PROGRESS_INTERVAL = 1000;

    private ImageWriter imageWriter;
    private Camera camera;
    private RayTracerBase rayTracer;
    /** The {@link RayTracerBasic} over the scene set with {@link #setScene}, used when no ray tracer is set. */
    private RayTracerBase sceneTracer;
    private int threadsCount = Runtime.getRuntime().availableProcessors();
    private boolean debugPrint;
    private JitteredGrid pixelGrid;
    private boolean adaptiveSuperSampling;
    private LongConsumer progressListener;

    /**
     * Creates a render with nothing set yet: set an image writer, a camera and a ray tracer (or a scene)
     * before rendering.
     */
    public Render() {
    }

    /**
     * Sets the image to render into.
     *
     * @param imageWriter the image
     * @return this render
     */
    public Render setImageWriter(ImageWriter imageWriter) {
        this.imageWriter = requireNonNull(imageWriter, "image writer");
        return this;
    }

    /** {@return the image rendered into (null until set)} */
    public ImageWriter getImageWriter() {
        return imageWriter;
    }

    /**
     * Sets the camera.
     *
     * @param camera the camera
     * @return this render
     */
    public Render setCamera(Camera camera) {
        this.camera = requireNonNull(camera, "camera");
        return this;
    }

    /**
     * Sets the ray tracer, which holds the scene; it is used rather than a scene set with {@link #setScene}.
     *
     * @param rayTracer the ray tracer
     * @return this render
     */
    public Render setRayTracer(RayTracerBase rayTracer) {
        this.rayTracer = requireNonNull(rayTracer, "ray tracer");
        return this;
    }

    /**
     * Sets the scene, the course's early way to render: with no ray tracer set, {@link #renderImage()}
     * traces the scene with a {@link RayTracerBasic} over it. A ray tracer set with {@link #setRayTracer}
     * is used instead, whichever of the two was set first; setting both is not an error. The settings
     * forwarded to the ray tracer ({@link #setSoftShadows} and the like) go to the one in use when they are made.
     *
     * @param scene the scene
     * @return this render
     * @throws IllegalArgumentException when the scene is null
     */
    public Render setScene(Scene scene) {
        this.sceneTracer = new RayTracerBasic(scene);
        return this;
    }

    /**
     * {@return the ray tracer rendering uses: the one set with {@link #setRayTracer}, else the
     * {@link RayTracerBasic} over the scene set with {@link #setScene} (null until either is set)}
     */
    public RayTracerBase getRayTracer() {
        return rayTracer != null ? rayTracer : sceneTracer;
    }

    /**
     * Turns soft shadows on or off in the ray tracer.
     *
     * @param softShadows true for soft shadows from lights with an area
     * @return this render
     * @throws MissingResourceException when neither a ray tracer nor a scene is set yet
     * @see RayTracerBase#setSoftShadows(boolean)
     */
    public Render setSoftShadows(boolean softShadows) {
        requireRayTracer().setSoftShadows(softShadows);
        return this;
    }

    /**
     * Sets the number of shadow rays per light in the ray tracer.
     *
     * @param sqrtBeamNum the number of cells along each side of a light's square, 1 to {@link JitteredGrid#MAX_SQRT_SAMPLES}
     * @return this render
     * @throws MissingResourceException when neither a ray tracer nor a scene is set yet
     * @see RayTracerBase#setSqrtBeamNum(int)
     */
    public Render setSqrtBeamNum(int sqrtBeamNum) {
        requireRayTracer().setSqrtBeamNum(sqrtBeamNum);
        return this;
    }

    /**
     * Sets the number of spread rays of glossy and blurry surfaces in the ray tracer.
     *
     * @param sqrtGlossRays the number of cells along each side of the square of spread rays, 1 to
     *                      {@link JitteredGrid#MAX_SQRT_SAMPLES}
     * @return this render
     * @throws MissingResourceException when neither a ray tracer nor a scene is set yet
     * @see RayTracerBase#setSqrtGlossRays(int)
     */
    public Render setSqrtGlossRays(int sqrtGlossRays) {
        requireRayTracer().setSqrtGlossRays(sqrtGlossRays);
        return this;
    }

    /**
     * Turns adaptive soft shadows on or off in the ray tracer.
     *
     * @param adaptiveSoftShadows true for adaptive sampling of lights' squares
     * @return this render
     * @throws MissingResourceException when neither a ray tracer nor a scene is set yet
     * @see RayTracerBase#setAdaptiveSoftShadows(boolean)
     */
    public Render setAdaptiveSoftShadows(boolean adaptiveSoftShadows) {
        requireRayTracer().setAdaptiveSoftShadows(adaptiveSoftShadows);
        return this;
    }

    /**
     * Sets the seed of the ray tracer's random streams.
     *
     * @param seed the seed
     * @return this render
     * @throws MissingResourceException when neither a ray tracer nor a scene is set yet
     * @see RayTracerBase#setSeed(long)
     */
    public Render setSeed(long seed) {
        requireRayTracer().setSeed(seed);
        return this;
    }

    /**
     * Sets anti-aliasing: each pixel's colour is the average of k × k rays through jittered points
     * of the pixel, one in each cell of a k × k grid.
     *
     * @param sqrtSamples k, 1 to {@link JitteredGrid#MAX_SQRT_SAMPLES}; 1 (the default) is one ray
     *                    through the pixel's centre
     * @return this render
     * @throws IllegalArgumentException when k is less than 1 or more than {@link JitteredGrid#MAX_SQRT_SAMPLES}
     */
    public Render setAntiAliasing(int sqrtSamples) {
        JitteredGrid.requireSqrtSamples(sqrtSamples, "anti-aliasing (rays along each side of a pixel)");
        this.pixelGrid = sqrtSamples == 1 ? null : new JitteredGrid(sqrtSamples);
        return this;
    }

    /** {@return k, the square root of the number of rays per pixel} */
    public int getAntiAliasing() {
        return pixelGrid == null ? 1 : pixelGrid.getSqrtSamples();
    }

    /**
     * Turns adaptive super-sampling on or off (off by default). A pixel's four corners and its centre
     * are traced first; when the centre's colour differs from a corner's by more than
     * {@link #ADAPTIVE_THRESHOLD} levels in a channel, the pixel is divided into four squares that are
     * sampled the same way, recursively, down to the anti-aliasing grid's resolution: the smallest squares
     * are two of its cells wide, so that with their centres the points are 1/k of the pixel apart, as the
     * grid's are (k × k anti-aliasing divides at most log₂ k − 1 times). The colour of a square that is not
     * divided is the average of its five points, that of a divided one the average of its quarters. Points
     * shared by squares of a pixel are traced once, so a pixel takes at most (k/2 + 1)² + (k/2)² rays
     * (about half of k² for k a power of 2, never more than k² for k ≥ 3), and flat regions take 5 a
     * pixel instead of k². With anti-aliasing off (k = 1) it is one ray through the centre, as without it.
     * <p>
     * The points are a regular lattice, not jittered; a pixel's corners are traced again by its
     * neighbours rather than shared with them, so that each pixel depends on nothing but itself (its
     * shadows and aperture rays draw from the pixel's own random stream) and the picture stays the same
     * whatever the number of threads and the order of the tiles.
     *
     * @param adaptiveSuperSampling true for adaptive super-sampling
     * @return this render
     */
    public Render setAdaptiveSuperSampling(boolean adaptiveSuperSampling) {
        this.adaptiveSuperSampling = adaptiveSuperSampling;
        return this;
    }

    /** {@return whether adaptive super-sampling is on} */
    public boolean isAdaptiveSuperSampling() {
        return adaptiveSuperSampling;
    }

    /**
     * Sets the number of rendering threads.
     *
     * @param threads the number of threads, 1 or more; 0 for one per core (the default)
     * @return this render
     */
    public Render setMultithreading(int threads) {
        if (threads < 0)
            throw new IllegalArgumentException("number of threads must not be negative, got " + threads);
        this.threadsCount = threads == 0 ? Runtime.getRuntime().availableProcessors() : threads;
        return this;
    }

    /**
     * Prints the rendering progress, in percent, to the standard output.
     *
     * @return this render
     */
    public Render setDebugPrint() {
        this.debugPrint = true;
        return this;
    }

    /**
     * Sets a listener told of the progress of a render: after each tile of pixels, a rendering thread
     * calls it with the number of pixels rendered so far (the last call gives nX × nY). Calls come
     * from several threads, so the listener must be thread-safe.
     *
     * @param progressListener the listener, or null for none
     * @return this render
     */
    public Render setProgressListener(LongConsumer progressListener) {
        this.progressListener = progressListener;
        return this;
    }

    /**
     * Renders the picture into the image (call {@link #writeToImage()} to save it).
     * <p>
     * Interrupting the thread that called it ({@link Thread#interrupt()}) stops the render: no tile is
     * started after it, and once the tiles under way are done a {@link CancellationException} says how many
     * were rendered, with the thread's interrupt flag still set; the image then holds only those tiles, so
     * do not write it. A render that was complete when the interruption came returns normally (the flag
     * set, for the caller to see).
     *
     * @throws MissingResourceException naming the image writer, camera or ray tracer when it is not set
     *                                  (a scene set with {@link #setScene} stands for the ray tracer)
     * @throws IllegalArgumentException when the scene is not complete (see {@link Scene#requireComplete()})
     * @throws CancellationException    when the calling thread is interrupted before the picture is complete
     */
    public void renderImage() {
        requireImageWriter();
        if (camera == null)
            throw new MissingResourceException("Render: the camera is not set", Render.class.getName(), "camera");
        RayTracerBase tracer = requireRayTracer();
        tracer.prepare(threadsCount);
        new TileRenderer(tracer).run();
    }

    /**
     * Draws a grid of lines over the image.
     *
     * @param interval the distance in pixels between lines, positive
     * @param color    the lines' colour
     * @throws MissingResourceException when the image writer is not set
     */
    public void printGrid(int interval, Color color) {
        requireImageWriter();
        if (interval <= 0)
            throw new IllegalArgumentException("grid interval must be positive, got " + interval);
        requireNonNull(color, "grid colour");
        int nX = imageWriter.getNx();
        int nY = imageWriter.getNy();
        for (int i = 0; i < nY; ++i)
            for (int j = 0; j < nX; ++j)
                if (i % interval == 0 || j % interval == 0)
                    imageWriter.writePixel(j, i, color);
    }

    /**
     * Writes the image to its PNG file.
     *
     * @throws MissingResourceException when the image writer is not set
     */
    public void writeToImage() {
        requireImageWriter();
        imageWriter.writeToImage();
    }

    private RayTracerBase requireRayTracer() {
        RayTracerBase tracer = getRayTracer();
        if (tracer == null)
            throw new MissingResourceException("Render: the ray tracer is not set (set one with setRayTracer,"
                    + " or a scene with setScene)", Render.class.getName(), "rayTracer");
        return tracer;
    }

    private void requireImageWriter() {
        if (imageWriter == null)
            throw new MissingResourceException("Render: the image writer is not set", Render.class.getName(), "imageWriter");
    }

    /** One rendering pass: threads take tiles from a shared counter until none is left. */
    private final class TileRenderer {
        private final RayTracerBase tracer;
        private final int nX = imageWriter.getNx();
        private final int nY = imageWriter.getNy();
        private final int tilesX = (nX + TILE - 1) / TILE;
        private final int tilesCount = tilesX * ((nY + TILE - 1) / TILE);
        /** The pixels rendered so far: what the progress listener is told and the debug print shows. */
        private final AtomicLong pixelsDone = new AtomicLong();

        TileRenderer(RayTracerBase tracer) {
            this.tracer = tracer;
        }

        void run() {
            Thread printer = debugPrint ? startProgressPrinter() : null;
            try {
                Parallel.forEach(tilesCount, threadsCount, "render", this::renderTileAndReport);
            } finally {
                if (printer != null)
                    stopProgressPrinter(printer);
            }
        }

        private Thread startProgressPrinter() {
            Thread printer = new Thread(this::printProgress, "render-progress");
            printer.setDaemon(true);
            printer.start();
            return printer;
        }

        private void stopProgressPrinter(Thread printer) {
            printer.interrupt();
            try {
                printer.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            System.out.printf("\r%3d%%%n", percentDone()); // 100 %, or where an interruption stopped
        }

        /** {@return the share of the pixels rendered so far, in percent} */
        private long percentDone() {
            return 100L * pixelsDone.get() / ((long) nX * nY);
        }

        /** Renders one tile and tells the progress listener, if any, of the pixels done so far. */
        private void renderTileAndReport(int tile) {
            long done = pixelsDone.addAndGet(renderTile(tile));
            if (progressListener != null)
                progressListener.accept(done);
        }

        /** Renders one tile and returns its number of pixels. */
        private long renderTile(int tile) {
            int x0 = (tile % tilesX) * TILE;
            int y0 = (tile / tilesX) * TILE;
            int x1 = Math.min(x0 + TILE, nX);
            int y1 = Math.min(y0 + TILE, nY);
            tracer.threadState().startTile(); // the thread's last tile must not shape this one's shadows
            for (int i = y0; i < y1; ++i)
                for (int j = x0; j < x1; ++j)
                    imageWriter.writePixel(j, i, renderPixel(j, i));
            return (long) (x1 - x0) * (y1 - y0);
        }

        /** The colour of a pixel: seen through its centre, or the average of its jittered or adaptive samples. */
        private Color renderPixel(int j, int i) {
            ThreadState state = tracer.startPixel(j, i);
            if (pixelGrid == null)
                return sample(state, j, i, 0.5, 0.5);
            if (adaptiveSuperSampling)
                return new AdaptivePixel(state, j, i).color();
            return average(pixelGrid, state.pixelPoints(pixelGrid), state, (dx, dy) -> sample(state, j, i, dx, dy));
        }

        /**
         * The colour seen through a point of a pixel: along the camera's ray through it, or, with an
         * aperture, the average of the rays from the aperture's jittered points to its focal point.
         */
        private Color sample(ThreadState state, int j, int i, double dx, double dy) {
            if (!camera.hasAperture()) {
                ++state.primaryRays;
                return tracer.traceRay(camera.constructRayThroughPixel(nX, nY, j, i, dx, dy));
            }
            JitteredGrid apertureGrid = camera.getApertureGrid();
            state.primaryRays += apertureGrid.getSamplesCount();
            return average(apertureGrid, state.aperturePoints(apertureGrid), state,
                    (u, v) -> tracer.traceRay(camera.constructRayThroughAperture(nX, nY, j, i, dx, dy, u, v)));
        }

        /**
         * The average of the colours at a grid's jittered points, drawn from the pixel's random stream.
         *
         * @param grid    the grid
         * @param points  room for its points
         * @param state   the thread's state, its stream the pixel's
         * @param colorAt the colour at a point of the unit square
         * @return the average colour
         */
        private static Color average(JitteredGrid grid, double[] points, ThreadState state, PointColor colorAt) {
            grid.sampleUnchecked(state.random, points);
            int count = grid.getSamplesCount();
            Color color = Color.BLACK;
            for (int s = 0; s < count; ++s)
                color = color.add(colorAt.at(points[2 * s], points[2 * s + 1]));
            return color.reduce(count);
        }

        /**
         * One pixel sampled adaptively: its points lie on a lattice of 2^(depth + 1) + 1 points a side
         * (the centres of the smallest squares are points too), each traced at most once.
         */
        private final class AdaptivePixel {
            private final ThreadState state;
            private final int j;
            private final int i;
            /**
             * How many times the pixel may be halved: the smallest squares are at least two anti-aliasing cells
             * wide, so that with their centres the points are no closer than the cells (1/k apart).
             */
            private final int maxDepth = Math.max(0, 30 - Integer.numberOfLeadingZeros(pixelGrid.getSqrtSamples()));
            /** The number of lattice intervals along a side. */
            private final int side = 2 << maxDepth;

            AdaptivePixel(ThreadState state, int j, int i) {
                this.state = state;
                this.j = j;
                this.i = i;
                state.startLattice((side + 1) * (side + 1));
            }

            Color color() {
                return square(0, 0, side, 0);
            }

            /** The colour of the square of a lattice edge at a corner (x, y), divided while its points differ. */
            private Color square(int x, int y, int edge, int depth) {
                int half = edge / 2;
                Color centre = point(x + half, y + half);
                Color c00 = point(x, y);
                Color c10 = point(x + edge, y);
                Color c01 = point(x, y + edge);
                Color c11 = point(x + edge, y + edge);
                if (depth == maxDepth || !(differ(centre, c00) || differ(centre, c10) || differ(centre, c01)
                        || differ(centre, c11)))
                    return centre.add(c00, c10, c01, c11).reduce(5);
                return square(x, y, half, depth + 1).add(square(x + half, y, half, depth + 1),
                        square(x, y + half, half, depth + 1), square(x + half, y + half, half, depth + 1)).reduce(4);
            }

            /** The colour seen through a lattice point, traced the first time it is asked for. */
            private Color point(int x, int y) {
                int index = y * (side + 1) + x;
                Color color = state.latticeColor(index);
                return color != null ? color
                        : state.keepLatticeColor(index, sample(state, j, i, (double) x / side, (double) y / side));
            }

            private static boolean differ(Color a, Color b) {
                return Math.abs(a.getR() - b.getR()) > ADAPTIVE_THRESHOLD
                        || Math.abs(a.getG() - b.getG()) > ADAPTIVE_THRESHOLD
                        || Math.abs(a.getB() - b.getB()) > ADAPTIVE_THRESHOLD;
            }
        }

        /** The colour seen at a point (u, v) of the unit square: of a pixel, or of the camera's aperture. */
        @FunctionalInterface
        private interface PointColor {
            Color at(double u, double v);
        }

        private void printProgress() {
            try {
                while (!Thread.currentThread().isInterrupted()) {
                    System.out.printf("\r%3d%%", percentDone());
                    System.out.flush();
                    Thread.sleep(PROGRESS_INTERVAL);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
