package renderer;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Unit tests for {@link SplitMix64}: the numbers of {@link SplittableRandom}, reseeding and skipping.
 */
class SplitMix64Test {

    /** Test method for {@link SplitMix64#nextLong()} and {@link SplitMix64#nextDouble()}: SplittableRandom's numbers. */
    @Test
    void testSameNumbersAsSplittableRandom() {
        // ===== Equivalence Partitions Tests =====
        // TC01: ordinary seeds: the same 1000 longs as new SplittableRandom(seed)
        for (long seed : new long[] { 1, 42, 20240611, -987654321987L }) {
            SplitMix64 random = new SplitMix64(seed);
            SplittableRandom reference = new SplittableRandom(seed);
            for (int i = 0; i < 1000; ++i)
                assertEquals(reference.nextLong(), random.nextLong(), "TC01: seed " + seed + ", draw " + i);
        }
        // TC02: the same 1000 doubles, each in [0, 1)
        SplitMix64 random = new SplitMix64(7);
        SplittableRandom reference = new SplittableRandom(7);
        for (int i = 0; i < 1000; ++i) {
            double d = random.nextDouble();
            assertEquals(reference.nextDouble(), d, 0, "TC02: draw " + i);
            assertTrue(d >= 0 && d < 1, "TC02: draw " + i + " outside [0, 1): " + d);
        }

        // ===== Boundary Values Tests =====
        // TC11: the extreme seeds 0, Long.MIN_VALUE and Long.MAX_VALUE
        for (long seed : new long[] { 0, Long.MIN_VALUE, Long.MAX_VALUE }) {
            SplitMix64 extreme = new SplitMix64(seed);
            SplittableRandom twin = new SplittableRandom(seed);
            for (int i = 0; i < 100; ++i)
                assertEquals(twin.nextDouble(), extreme.nextDouble(), 0, "TC11: seed " + seed + ", draw " + i);
        }
    }

    /** Test method for {@link SplitMix64#reseed(long)}: the stream starts again as if new. */
    @Test
    void testReseed() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a used stream reseeded with 5 gives the numbers of new SplittableRandom(5)
        SplitMix64 random = new SplitMix64(3);
        for (int i = 0; i < 17; ++i)
            random.nextDouble();
        random.reseed(5);
        SplittableRandom reference = new SplittableRandom(5);
        for (int i = 0; i < 100; ++i)
            assertEquals(reference.nextLong(), random.nextLong(), "TC01: draw " + i + " after reseeding");

        // ===== Boundary Values Tests =====
        // TC11: reseeding with the seed it was made with repeats the first numbers
        SplitMix64 again = new SplitMix64(9);
        long first = again.nextLong();
        again.reseed(9);
        assertEquals(first, again.nextLong(), "TC11: reseeding with the same seed must repeat the first draw");
    }

    /** Test method for {@link SplitMix64#skip(long)}: the same stream as after that many draws. */
    @Test
    void testSkip() {
        // ===== Equivalence Partitions Tests =====
        // TC01: skipping 162 draws (a 9 × 9 grid's points) leaves the stream where 162 draws would
        for (long draws : new long[] { 1, 2, 162, 1000 }) {
            SplitMix64 skipped = new SplitMix64(11);
            SplitMix64 drawn = new SplitMix64(11);
            skipped.skip(draws);
            for (long i = 0; i < draws; ++i)
                drawn.nextDouble();
            for (int i = 0; i < 10; ++i)
                assertEquals(drawn.nextLong(), skipped.nextLong(), "TC01: skip " + draws + ", draw " + i);
        }

        // ===== Boundary Values Tests =====
        // TC11: skipping 0 draws changes nothing
        SplitMix64 random = new SplitMix64(12);
        random.skip(0);
        assertEquals(new SplittableRandom(12).nextLong(), random.nextLong(), "TC11: skip(0) must not move the stream");
        // TC12: skipping 2^40 draws at once equals skipping 2^0 + 2^1 + … + 2^39 + 1 draws
        SplitMix64 far = new SplitMix64(13);
        far.skip(1L << 40);
        SplitMix64 stepwise = new SplitMix64(13);
        for (int i = 0; i < 40; ++i)
            stepwise.skip(1L << i);
        stepwise.skip(1);
        assertEquals(stepwise.nextLong(), far.nextLong(), "TC12: one long skip must equal the sum of shorter ones");
    }

    /** Test method for {@link SplitMix64#nextDoubles(double[], int)}: the numbers of as many nextDouble() calls. */
    @Test
    void testNextDoubles() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 162 doubles (a 9 × 9 grid's draws) are those of 162 nextDouble() calls, bit for bit,
        // and the stream is then where those calls leave it
        SplitMix64 run = new SplitMix64(21);
        SplitMix64 oneByOne = new SplitMix64(21);
        double[] doubles = new double[162];
        run.nextDoubles(doubles, doubles.length);
        for (int i = 0; i < doubles.length; ++i)
            assertEquals(oneByOne.nextDouble(), doubles[i], 0, "TC01: draw " + i);
        assertEquals(oneByOne.nextLong(), run.nextLong(), "TC01: the stream must be past the 162 draws");

        // ===== Boundary Values Tests =====
        // TC11: no draw: the array stays as it was (-1) and the stream does not move
        SplitMix64 none = new SplitMix64(22);
        double[] untouched = { -1 };
        none.nextDoubles(untouched, 0);
        assertEquals(-1, untouched[0], 0, "TC11: drawing nothing must leave the array as it was");
        assertEquals(new SplittableRandom(22).nextLong(), none.nextLong(),
                "TC11: drawing nothing must not move the stream");
        // TC12: fewer draws than the array holds: the rest stays as it was (-1)
        double[] longer = { -1, -1, -1 };
        new SplitMix64(23).nextDoubles(longer, 2);
        assertEquals(new SplittableRandom(23).nextDouble(), longer[0], 0, "TC12: the first draw");
        assertEquals(-1, longer[2], 0, "TC12: the room past the draws must be left as it was");
    }
}
