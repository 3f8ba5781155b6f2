package testutil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.function.Executable;

import primitives.Color;
import primitives.Vector;

/** Assertion helpers shared by the unit tests. */
public final class TestAssertions {
    /** Default tolerance for comparing colour components. */
    public static final double COLOR_DELTA = 1e-10;

    /** Not instantiable. */
    private TestAssertions() {
    }

    /**
     * Asserts that a thrown exception's message is non-null and contains a given word.
     *
     * @param e    the exception
     * @param word the word the message must contain
     * @param tc   the test-case label, named in the failure message
     */
    public static void assertMessage(Exception e, String word, String tc) {
        assertTrue(e.getMessage() != null && e.getMessage().contains(word),
                tc + ": message should name the problem (\"" + word + "\"), got: " + e.getMessage());
    }

    /**
     * Asserts that two calls, one through each of two names for the same thing, are both rejected
     * with an {@link IllegalArgumentException} carrying the same message.
     *
     * @param name      the call through one name
     * @param otherName the same call through the other name
     * @param tc        the test-case label, named in the failure messages
     */
    public static void assertSameRejection(Executable name, Executable otherName, String tc) {
        String expected = assertThrows(IllegalArgumentException.class, name, tc + ": bad value accepted").getMessage();
        assertEquals(expected, assertThrows(IllegalArgumentException.class, otherName,
                tc + ": bad value accepted by the other name").getMessage(), tc + ": a different message");
    }

    /**
     * Asserts a colour's components within {@link #COLOR_DELTA}.
     *
     * @param r       the expected red component
     * @param g       the expected green component
     * @param b       the expected blue component
     * @param c       the actual colour
     * @param message the failure message, suffixed with the component name
     */
    public static void assertColor(double r, double g, double b, Color c, String message) {
        assertEquals(r, c.getR(), COLOR_DELTA, message + " (red)");
        assertEquals(g, c.getG(), COLOR_DELTA, message + " (green)");
        assertEquals(b, c.getB(), COLOR_DELTA, message + " (blue)");
    }

    /**
     * Asserts that two colours have the same components within {@link #COLOR_DELTA}.
     *
     * @param expected the expected colour
     * @param actual   the actual colour
     * @param message  the failure message, suffixed with the component name
     */
    public static void assertColor(Color expected, Color actual, String message) {
        assertColor(expected.getR(), expected.getG(), expected.getB(), actual, message);
    }

    /**
     * Asserts that U and V place a square facing along a normal: both unit, orthogonal to each other
     * and to the normal, so |(U × V) · normal| = 1.
     *
     * @param u      the square's first side
     * @param v      the square's second side
     * @param normal the unit normal the square must face
     * @param tc     the test-case label, named in the failure messages
     */
    public static void assertSquareAxes(Vector u, Vector v, Vector normal, String tc) {
        assertNotNull(u, tc + ": U must not be null");
        assertNotNull(v, tc + ": V must not be null");
        assertEquals(1, u.length(), 1e-10, tc + ": U must be unit");
        assertEquals(1, v.length(), 1e-10, tc + ": V must be unit");
        assertEquals(0, u.dotProduct(v), 1e-10, tc + ": U·V must be 0");
        assertEquals(0, u.dotProduct(normal), 1e-10, tc + ": U·normal must be 0");
        assertEquals(0, v.dotProduct(normal), 1e-10, tc + ": V·normal must be 0");
        assertEquals(1, Math.abs(u.crossProduct(v).dotProduct(normal)), 1e-10, tc + ": |(U×V)·normal| must be 1");
    }
}
