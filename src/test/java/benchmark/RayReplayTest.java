package benchmark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static testutil.TestAssertions.assertMessage;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import accel.BoundingVolumeHierarchy;

/**
 * Unit tests for {@link benchmark.RayReplay}: reading a file of rays in bundles, and replaying it
 * through scene S's hierarchy against the answers the file holds.
 */
class RayReplayTest {
    private static final Path FOLDER = Path.of("target", "ray-replay");
    /** Straight down into S's first sphere (centre (−40, −20, 0), radius 30) from above it: blocked. */
    private static final double[] INTO_SPHERE = { -40, 20, 0, 0, -1, 0, 100, 0 };
    /** Straight up from far beside the spheres: not blocked. */
    private static final double[] PAST_SPHERES = { 200, 0, 0, 0, 1, 0, 50, 1 };
    private static BoundingVolumeHierarchy bvh;

    @BeforeAll
    static void buildScene() throws IOException {
        Files.createDirectories(FOLDER);
        bvh = BoundingVolumeHierarchy.build(Benchmark.buildScene("S").geometries);
    }

    /** Test method for {@link RayReplay#read(Path)}. */
    @Test
    void testRead() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: a bundle of two rays, then one of one: 2 bundles, 3 rays, the numbers in their order
        Path file = write("two-bundles.bin", bundle(INTO_SPHERE, PAST_SPHERES), bundle(PAST_SPHERES));
        RayReplay.Rays rays = RayReplay.read(file);
        assertEquals(2, rays.bundles(), "TC01: wrong bundles count");
        assertEquals(3, rays.count(), "TC01: wrong rays count");
        assertArrayEquals(new int[] { 0, 2, 3 }, rays.starts(), "TC01: wrong bundle starts");
        assertEquals(PAST_SPHERES[0], rays.numbers()[2 * RayReplay.RAY_DOUBLES], 0, "TC01: wrong third ray");

        // ===== Boundary Values Tests =====
        // TC11: one ray alone: 1 bundle, 1 ray
        assertEquals(1, RayReplay.read(write("one-ray.bin", bundle(INTO_SPHERE))).count(), "TC11: one ray");
        // TC12: a bundle cut short: rejected, naming the bundle
        byte[] whole = bundle(INTO_SPHERE, PAST_SPHERES);
        byte[] cut = new byte[whole.length - 1];
        System.arraycopy(whole, 0, cut, 0, cut.length);
        Path cutFile = write("cut.bin", cut);
        assertMessage(assertThrows(IllegalArgumentException.class, () -> RayReplay.read(cutFile), "TC12"),
                "cut short", "TC12");
        // TC13: an empty file: rejected, no rays
        Path empty = write("empty.bin");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> RayReplay.read(empty), "TC13"),
                "no rays", "TC13");
        // TC14: no such file: rejected, naming it
        Path missing = FOLDER.resolve("missing.bin");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> RayReplay.read(missing), "TC14"),
                "missing.bin", "TC14");
    }

    /** Test method for {@link RayReplay#replay(BoundingVolumeHierarchy, RayReplay.Rays, int)}. */
    @Test
    void testReplay() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: a blocked and an unblocked ray with the right answers, on 1 and 2 threads: 0 differing
        RayReplay.Rays rays = RayReplay.read(write("right.bin", bundle(INTO_SPHERE, PAST_SPHERES),
                bundle(PAST_SPHERES)));
        assertEquals(0, RayReplay.replay(bvh, rays, 1), "TC01: one thread");
        assertEquals(0, RayReplay.replay(bvh, rays, 2), "TC01: two threads");
        // TC02: both answers of the file wrong: 2 differing
        double[] unblockedInto = INTO_SPHERE.clone();
        unblockedInto[7] = 1;
        double[] blockedPast = PAST_SPHERES.clone();
        blockedPast[7] = 0;
        RayReplay.Rays wrong = RayReplay.read(write("wrong.bin", bundle(unblockedInto, blockedPast)));
        assertEquals(2, RayReplay.replay(bvh, wrong, 2), "TC02: both answers differ");

        // ===== Boundary Values Tests =====
        // TC11: more threads than bundles: every ray still traced once, 0 differing
        assertEquals(0, RayReplay.replay(bvh, rays, 4), "TC11: four threads, two bundles");
    }

    /** {@return a bundle of rays as a file holds it: the count, then each ray's doubles, little-endian} */
    private static byte[] bundle(double[]... rays) {
        ByteBuffer bytes = ByteBuffer.allocate(Integer.BYTES + rays.length * RayReplay.RAY_DOUBLES * Double.BYTES)
                .order(ByteOrder.LITTLE_ENDIAN).putInt(rays.length);
        for (double[] ray : rays)
            for (double x : ray)
                bytes.putDouble(x);
        return bytes.array();
    }

    /** {@return a file of the target folder holding some bundles one after another} */
    private static Path write(String name, byte[]... bundles) throws IOException {
        Path file = FOLDER.resolve(name);
        Files.deleteIfExists(file);
        Files.createFile(file);
        for (byte[] bundle : bundles)
            Files.write(file, bundle, StandardOpenOption.APPEND);
        return file;
    }
}
