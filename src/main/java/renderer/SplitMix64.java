package renderer;

import java.util.random.RandomGenerator;

/**
 * The random stream of a pixel: SplitMix64, the generator behind {@link java.util.SplittableRandom},
 * whose {@link #nextLong()} and {@link #nextDouble()} give the same numbers for the same seed. It adds
 * what the JDK's class lacks: reseeding in place (one stream per thread, reseeded per pixel) and
 * skipping draws in constant time, so that sample points nobody needs are not drawn while the
 * numbers drawn after them stay the same.
 */
final class SplitMix64 implements RandomGenerator {
    /** The odd increment of the seed per draw: 2^64 divided by the golden ratio. */
    private static final long GOLDEN_GAMMA = 0x9e3779b97f4a7c15L;
    /** 2^-53: turns the top 53 bits of a long into a double in [0, 1). */
    private static final double DOUBLE_UNIT = 0x1.0p-53;

    private long seed;

    /**
     * Creates a stream.
     *
     * @param seed the seed, as for {@code new SplittableRandom(seed)}
     */
    SplitMix64(long seed) {
        this.seed = seed;
    }

    /**
     * Starts the stream again from a seed.
     *
     * @param seed the seed, as for {@code new SplittableRandom(seed)}
     */
    void reseed(long seed) {
        this.seed = seed;
    }

    /**
     * Moves the stream past some draws without making them.
     *
     * @param draws the number of {@link #nextLong()} or {@link #nextDouble()} calls skipped
     */
    void skip(long draws) {
        seed += draws * GOLDEN_GAMMA;
    }

    @Override
    public long nextLong() {
        seed += GOLDEN_GAMMA;
        return mix(seed);
    }

    @Override
    public double nextDouble() {
        return unit(nextLong());
    }

    /**
     * Draws a run of doubles: the same numbers as as many {@link #nextDouble()} calls, the stream's
     * state kept in a register meanwhile rather than stored after every draw.
     *
     * @param into  the array the numbers go to, from index 0
     * @param count how many to draw, at most the array's length
     */
    void nextDoubles(double[] into, int count) {
        long state = seed;
        for (int i = 0; i < count; ++i) {
            state += GOLDEN_GAMMA;
            into[i] = unit(mix(state));
        }
        seed = state;
    }

    /** The number drawn when the stream's state becomes z: the finaliser of SplitMix64. */
    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    /** The double in [0, 1) made of a long's top 53 bits. */
    private static double unit(long bits) {
        return (bits >>> 11) * DOUBLE_UNIT;
    }
}
