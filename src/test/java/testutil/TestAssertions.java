package testutil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import primitives.Color;

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
}
