package benchmark;

import static testutil.BruteForce.MIN_K;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import accel.BoundingVolumeHierarchy;
import accel.Query;
import primitives.Parallel;
import scene.Scene;

/**
 * Replays a file of shadow rays through the hierarchy's single-ray transmittance walk, each ray from the
 * root, and prints the walk's ns of thread time a ray: on the rays the renderer traced (written by the
 * probe {@code tools/embree/traced-rays.patch}), it sets our walk beside Embree's on the same rays
 * ({@code embree_bench --rays}). The file holds bundles, each an int32 ray count and per ray 8 doubles
 * (origin, unit direction, length, the transmittance the renderer found), little-endian.
 *
 * <pre>
 * RayReplay --scene NAME --rays FILE [--warmup 3] [--passes 7] [--threads 2]
 * </pre>
 * NAME is one of {@link Benchmark}'s scenes, the one the rays were traced in.
 */
public final class RayReplay {
    /** The doubles per ray in a file. */
    static final int RAY_DOUBLES = 8;
    /** The bundles a thread takes at a time. */
    private static final int BUNDLES_TAKEN = 64;
    private static final String USAGE = "usage: RayReplay --scene NAME --rays FILE [--warmup N] [--passes N]"
            + " [--threads N]";

    /**
     * The rays of a file.
     *
     * @param numbers per ray, its {@value #RAY_DOUBLES} doubles
     * @param starts  per bundle, its first ray, then the number of rays
     */
    record Rays(double[] numbers, int[] starts) {
        /** {@return the number of bundles} */
        int bundles() {
            return starts.length - 1;
        }

        /** {@return the number of rays} */
        int count() {
            return starts[starts.length - 1];
        }
    }

    /** Not instantiable. */
    private RayReplay() {
    }

    /**
     * Replays a file of rays and prints its line.
     *
     * @param args the options, see the class comment
     */
    public static void main(String[] args) {
        String sceneName = null;
        Path file = null;
        int warmup = 3;
        int passes = 7;
        int threads = 2;
        for (int a = 0; a + 1 < args.length; a += 2) {
            switch (args[a]) {
                case "--scene" -> sceneName = args[a + 1];
                case "--rays" -> file = Path.of(args[a + 1]);
                case "--warmup" -> warmup = Integer.parseInt(args[a + 1]);
                case "--passes" -> passes = Integer.parseInt(args[a + 1]);
                case "--threads" -> threads = Integer.parseInt(args[a + 1]);
                default -> throw new IllegalArgumentException("unknown option " + args[a] + "; " + USAGE);
            }
        }
        if (sceneName == null || file == null || args.length % 2 != 0 || warmup < 0 || passes < 1 || threads < 1)
            throw new IllegalArgumentException(USAGE + ", at least 1 pass and 1 thread");
        Scene scene = Benchmark.buildScene(sceneName);
        BoundingVolumeHierarchy bvh = BoundingVolumeHierarchy.build(scene.geometries, threads);
        Rays rays = read(file);
        double[] seconds = new double[passes];
        long differing = 0;
        for (int p = -warmup; p < passes; ++p) {
            long start = System.nanoTime();
            differing = replay(bvh, rays, threads);
            if (p >= 0)
                seconds[p] = (System.nanoTime() - start) / 1e9;
        }
        double median = Benchmark.median(seconds);
        System.out.printf("%s: %d bundles, %d rays replayed one by one from the root, median %.4f s a pass,"
                        + " %.1f ns of thread time a ray, %d answers differing%n", file, rays.bundles(), rays.count(),
                median, threads * median * 1e9 / rays.count(), differing);
    }

    /**
     * Reads a file of rays.
     *
     * @param file the file
     * @return its rays
     * @throws IllegalArgumentException when the file cannot be read, is cut short, or holds no rays
     */
    static Rays read(Path file) {
        ByteBuffer bytes;
        try {
            bytes = ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read the rays of " + file + ": " + e.getMessage(), e);
        }
        double[] numbers = new double[bytes.capacity() / Double.BYTES]; // more than the rays' numbers
        List<Integer> starts = new ArrayList<>(List.of(0));
        int total = 0;
        while (bytes.hasRemaining()) {
            int count = bytes.remaining() >= Integer.BYTES ? bytes.getInt() : -1;
            if (count <= 0 || bytes.remaining() < (long) count * RAY_DOUBLES * Double.BYTES)
                throw new IllegalArgumentException(file + ": bundle " + (starts.size() - 1) + " at byte "
                        + bytes.position() + " is cut short or has no rays");
            for (int at = RAY_DOUBLES * total; at < RAY_DOUBLES * (total + count); ++at)
                numbers[at] = bytes.getDouble();
            total += count;
            starts.add(total);
        }
        if (total == 0)
            throw new IllegalArgumentException(file + " holds no rays");
        return new Rays(Arrays.copyOf(numbers, RAY_DOUBLES * total),
                starts.stream().mapToInt(Integer::intValue).toArray());
    }

    /**
     * Traces every ray once through a hierarchy's single-ray walk, on some threads that take runs of
     * bundles.
     *
     * @param bvh     the hierarchy of the scene the rays were traced in
     * @param rays    the rays
     * @param threads the number of threads
     * @return the rays whose answer, blocked or not, is not the file's
     */
    static long replay(BoundingVolumeHierarchy bvh, Rays rays, int threads) {
        AtomicLong differing = new AtomicLong();
        int runs = (rays.bundles() + BUNDLES_TAKEN - 1) / BUNDLES_TAKEN;
        Parallel.forEach(runs, threads, "replay", run -> differing.addAndGet(replay(bvh, bvh.threadQuery(), rays,
                run * BUNDLES_TAKEN, Math.min(rays.bundles(), (run + 1) * BUNDLES_TAKEN))));
        return differing.get();
    }

    /** Traces the rays of bundles [from, to); {@return the rays whose answer is not the file's} */
    private static long replay(BoundingVolumeHierarchy bvh, Query query, Rays rays, int from, int to) {
        double[] n = rays.numbers();
        long differing = 0;
        for (int r = rays.starts()[from]; r < rays.starts()[to]; ++r) {
            int at = RAY_DOUBLES * r;
            query.setRay(n[at], n[at + 1], n[at + 2], n[at + 3], n[at + 4], n[at + 5], n[at + 6]);
            if ((bvh.transmittance(query, MIN_K) == 0) != (n[at + 7] == 0))
                ++differing;
        }
        return differing;
    }
}
