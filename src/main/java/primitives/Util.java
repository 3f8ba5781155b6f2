package primitives;

import java.util.concurrent.ThreadLocalRandom;

/**
 * Numeric helpers shared by the whole library: tolerant comparisons with zero and argument checks.
 */
public final class Util {
    /** Values whose magnitude is below this threshold are treated as zero. */
    private static final double EPS = 1e-10;

    private Util() {
    }

    /**
     * Tells whether a number is zero within the library's tolerance.
     *
     * @param number the value to check
     * @return true when |number| is below the tolerance
     */
    public static boolean isZero(double number) {
        return Math.abs(number) < EPS;
    }

    /**
     * Snaps a number that is zero within the tolerance to exactly zero.
     *
     * @param number the value to align
     * @return 0.0 when the number is zero within the tolerance, the number itself otherwise
     */
    public static double alignZero(double number) {
        return isZero(number) ? 0.0 : number;
    }

    /**
     * Tells whether two numbers have the same sign.
     *
     * @param n1 first number
     * @param n2 second number
     * @return true when both are positive or both are negative
     */
    public static boolean checkSign(double n1, double n2) {
        return (n1 < 0 && n2 < 0) || (n1 > 0 && n2 > 0);
    }

    /**
     * Draws a uniform random number in [min, max) from the calling thread's generator.
     * Rendering never uses it: pictures draw from seeded per-pixel streams to stay reproducible.
     *
     * @param min lower bound (inclusive)
     * @param max upper bound (exclusive)
     * @return a random number in [min, max)
     */
    public static double random(double min, double max) {
        if (!(min < max))
            throw new IllegalArgumentException("random range is empty: min " + min + " is not below max " + max);
        return min + ThreadLocalRandom.current().nextDouble() * (max - min);
    }

    /**
     * Checks that a value is a finite number.
     *
     * @param value the value to check
     * @param what  what the value is, for the error message
     * @return the value itself
     * @throws IllegalArgumentException when the value is NaN or infinite
     */
    public static double requireFinite(double value, String what) {
        if (!Double.isFinite(value))
            throw new IllegalArgumentException(what + " must be a finite number, got " + value);
        return value;
    }

    /**
     * Checks that a value is a finite positive number.
     *
     * @param value the value to check
     * @param what  what the value is, for the error message
     * @return the value itself
     * @throws IllegalArgumentException when the value is not positive or not finite
     */
    public static double requirePositive(double value, String what) {
        if (!(requireFinite(value, what) > 0))
            throw new IllegalArgumentException(what + " must be positive, got " + value);
        return value;
    }

    /**
     * Checks that a value is a finite number that is not negative.
     *
     * @param value the value to check
     * @param what  what the value is, for the error message
     * @return the value itself
     * @throws IllegalArgumentException when the value is negative or not finite
     */
    public static double requireNonNegative(double value, String what) {
        if (requireFinite(value, what) < 0)
            throw new IllegalArgumentException(what + " must not be negative, got " + value);
        return value;
    }

    /**
     * Checks that an argument is not null.
     *
     * @param value the argument
     * @param what  what the argument is, for the error message
     * @param <T>   the argument's type
     * @return the argument itself
     * @throws IllegalArgumentException when the argument is null
     */
    public static <T> T requireNonNull(T value, String what) {
        if (value == null)
            throw new IllegalArgumentException(what + " must not be null");
        return value;
    }
}
