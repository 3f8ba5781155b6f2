package testutil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.function.Function;

import org.junit.jupiter.api.function.Executable;

import geometries.Intersectable;
import geometries.Intersectable.GeoPoint;
import primitives.Color;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;

/** Assertion helpers shared by the unit tests. */
public final class TestAssertions {
    /** Default tolerance for comparing colour components. */
    public static final double COLOR_DELTA = 1e-10;
    /** How many seeded random rays {@link #assertNearestFirstThrough} casts. */
    private static final int ORDER_RAYS = 200;

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
     * Asserts that a text shown to a user holds no control character (C0, DEL or C1) that a terminal
     * could run as a command, but for the line ends of its lines, and that it quotes the input printably:
     * with a given escape in it.
     *
     * @param text   the text: a message, or what a command printed
     * @param escape the visible escape it must hold, such as {@code \x1B}
     * @param tc     the test-case label, named in the failure message
     */
    public static void assertPrintable(String text, String escape, String tc) {
        assertNotNull(text, tc + ": no text");
        assertTrue(text.chars().noneMatch(c -> c < 0x20 && c != '\n' && c != '\r' || c >= 0x7F && c <= 0x9F),
                tc + ": a control character must not reach the terminal: " + text.replaceAll("[\\x00-\\x1F\\x7F-\\x9F]", "?"));
        assertTrue(text.contains(escape), tc + ": the input must be quoted as \"" + escape + "\", got: " + text);
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
     * Asserts that a body lists the points where a ray crosses it by distance along the ray, nearest
     * first: the expected points, through {@code findIntersections} and {@code findGeoIntersections}
     * alike, and the same points in the reverse order along the way back (see {@link #assertNearestFirstThrough}).
     *
     * @param body     the body
     * @param ray      a ray from outside the body (convex, or at least so along the line)
     * @param expected the points, nearest first, 2 or more
     * @param tc       the test-case label, named in the failure messages
     */
    public static void assertNearestFirst(Intersectable body, Ray ray, List<Point3D> expected, String tc) {
        assertEquals(expected, assertBothWays(body, ray, expected.size(), tc), tc + ": wrong points, nearest first");
    }

    /**
     * Asserts, for 200 seeded random rays that cross a body twice, that each gets its two points nearest
     * first, through {@code findIntersections} and {@code findGeoIntersections} alike, and that the ray
     * back along the same line, from a unit past the farther point, gets them in the reverse order.
     *
     * @param body the body
     * @param rays draws, from the generator given, a ray from outside the body that crosses it twice
     * @param tc   the test-case label, named in the failure messages
     */
    public static void assertNearestFirstThrough(Intersectable body, Function<Random, Ray> rays, String tc) {
        Random rnd = new Random(25);
        for (int i = 0; i < ORDER_RAYS; ++i)
            assertBothWays(body, rays.apply(rnd), 2, tc + " (ray " + i + ")");
    }

    /** Asserts a body's points along a ray and back nearest first, and returns those along the ray. */
    private static List<Point3D> assertBothWays(Intersectable body, Ray ray, int count, String tc) {
        List<Point3D> points = assertAscending(body, ray, count, tc);
        List<GeoPoint> geoPoints = body.findGeoIntersections(ray);
        assertEquals(points, geoPoints.stream().map(gp -> gp.point).toList(),
                tc + ": findGeoIntersections must list the points of findIntersections, in the same order");
        Ray back = new Ray(points.get(count - 1).add(ray.getDir()), ray.getDir().scale(-1));
        List<Point3D> reversed = new ArrayList<>(points);
        Collections.reverse(reversed);
        assertEquals(reversed, assertAscending(body, back, count, tc + " (the way back)"),
                tc + ": the way back must meet the same points in the reverse order");
        return points;
    }

    /** Asserts that a ray meets a body in a number of points, each farther from its start than the one before. */
    private static List<Point3D> assertAscending(Intersectable body, Ray ray, int count, String tc) {
        List<Point3D> points = body.findIntersections(ray);
        assertNotNull(points, tc + ": the ray " + ray + " must hit");
        assertEquals(count, points.size(), tc + ": wrong number of points along " + ray + ": " + points);
        for (int i = 1; i < count; ++i)
            assertTrue(ray.getP0().distance(points.get(i - 1)) < ray.getP0().distance(points.get(i)),
                    tc + ": the points along " + ray + " must come nearest first: " + points);
        return points;
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
