package scenefile;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import primitives.Point3D;
import primitives.Vector;

/**
 * Unit tests for {@link SceneElement}: the typed attribute getters, the children, and the errors naming
 * the element's place in the file.
 */
class SceneElementTest {
    private static final Path FILE = Path.of("scenes", "e.xml");

    /** An element of {@link #FILE} at line 3, column 17, with the given attributes (name, value, ...). */
    private static SceneElement element(String name, String... nameValues) {
        Map<String, String> attributes = new LinkedHashMap<>();
        for (int k = 0; k < nameValues.length; k += 2)
            attributes.put(nameValues[k], nameValues[k + 1]);
        return new SceneElement(FILE, name, attributes, 3, 17);
    }

    /**
     * Test method for {@link SceneElement#number(String)}, {@link SceneElement#integer(String)},
     * {@link SceneElement#longInteger(String)} and {@link SceneElement#numbers(String)}.
     */
    @Test
    void testNumbers() {
        SceneElement e = element("x", "radius", "2.5", "neg", "-1e-3", "zero", "0.0E1", "spaced", " 4.5 ",
                "width", "640", "seed", "9000000000", "small", "-7", "list", "0 0 0 1 0 0 0 1 0",
                "messy", "  1   -2.5\t3e1\n4 ");

        // ===== Equivalence Partitions Tests =====
        // TC01: number "2.5" → 2.5, "-1e-3" → -0.001
        assertEquals(2.5, e.number("radius"), 1e-15, "TC01: wrong number");
        assertEquals(-0.001, e.number("neg"), 1e-15, "TC01: wrong negative number");
        // TC02: integer "640" → 640, "-7" → -7
        assertEquals(640, e.integer("width"), "TC02: wrong integer");
        assertEquals(-7, e.integer("small"), "TC02: wrong negative integer");
        // TC03: longInteger "9000000000" (beyond int) → 9000000000, "640" → 640
        assertEquals(9_000_000_000L, e.longInteger("seed"), "TC03: wrong long integer");
        assertEquals(640L, e.longInteger("width"), "TC03: wrong long integer from a small value");
        // TC04: numbers "0 0 0 1 0 0 0 1 0" → 9 values in order
        assertArrayEquals(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, e.numbers("list"), 1e-15,
                "TC04: wrong list of numbers");

        // ===== Boundary Values Tests =====
        // TC11: the schema's normalised zero "0.0E1" → 0
        assertEquals(0, e.number("zero"), 1e-15, "TC11: 0.0E1 must be 0");
        // TC12: a number with spaces around it " 4.5 " → 4.5
        assertEquals(4.5, e.number("spaced"), 1e-15, "TC12: spaces around a number must be ignored");
        // TC13: a list with extra spaces, a tab and a newline → 1, -2.5, 30, 4
        assertArrayEquals(new double[] { 1, -2.5, 30, 4 }, e.numbers("messy"), 1e-15,
                "TC13: extra whitespace in a list must be ignored");
        // TC14: a single number as a list → one value
        assertArrayEquals(new double[] { 2.5 }, e.numbers("radius"), 1e-15, "TC14: one number is a list of one");
    }

    /** Test method for {@link SceneElement#flag(String)}. */
    @Test
    void testFlag() {
        SceneElement e = element("render", "t", "true", "one", "1", "f", "false", "zero", "0");

        // ===== Equivalence Partitions Tests =====
        // TC01: "true" → true
        assertTrue(e.flag("t"), "TC01: \"true\" must be true");
        // TC02: "false" → false
        assertFalse(e.flag("f"), "TC02: \"false\" must be false");

        // ===== Boundary Values Tests =====
        // TC11: the schema's numeric booleans: "1" → true, "0" → false
        assertTrue(e.flag("one"), "TC11: \"1\" must be true");
        assertFalse(e.flag("zero"), "TC11: \"0\" must be false");
    }

    /**
     * Test method for {@link SceneElement#point(String)}, {@link SceneElement#vector(String)} and
     * {@link SceneElement#color(String)}.
     */
    @Test
    void testTriples() {
        SceneElement e = element("x", "center", "0 0 -100", "dir", "1 2 2", "color", "255 191 191",
                "spaced", "  1   2\t3 ", "zero", "0 0 0", "tiny", "0 0 1e-20");

        // ===== Equivalence Partitions Tests =====
        // TC01: point "0 0 -100" → (0, 0, -100)
        assertEquals(new Point3D(0, 0, -100), e.point("center"), "TC01: wrong point");
        // TC02: vector "1 2 2" → (1, 2, 2), length 3
        Vector v = e.vector("dir");
        assertEquals(new Vector(1, 2, 2), v, "TC02: wrong vector");
        assertEquals(3, v.length(), 1e-12, "TC02: the vector must not be normalised");
        // TC03: colour "255 191 191" → (255, 191, 191)
        assertColor(255, 191, 191, e.color("color"), "TC03: wrong colour");
        // TC04: a zero vector "0 0 0" → IllegalArgumentException "zero vector"
        IllegalArgumentException ex = assertThrows(IllegalArgumentException.class, () -> e.vector("zero"),
                "TC04: a zero vector must be rejected");
        assertMessage(ex, "zero vector", "TC04");

        // ===== Boundary Values Tests =====
        // TC11: extra whitespace between and around the numbers → (1, 2, 3)
        assertEquals(new Point3D(1, 2, 3), e.point("spaced"), "TC11: extra whitespace must be ignored");
        assertColor(1, 2, 3, e.color("spaced"), "TC11: extra whitespace must be ignored in a colour");
        // TC12: "0 0 0" is a good point (the origin) and a good colour (black)
        assertEquals(Point3D.ZERO, e.point("zero"), "TC12: 0 0 0 must be the origin");
        assertColor(0, 0, 0, e.color("zero"), "TC12: 0 0 0 must be black");
    }

    /**
     * Test method for {@link SceneElement#name()}, {@link SceneElement#children()},
     * {@link SceneElement#addChild(SceneElement)} and {@link SceneElement#child(String)}.
     */
    @Test
    void testChildren() {
        SceneElement geometries = element("geometries");
        SceneElement sphere1 = element("sphere", "radius", "1");
        SceneElement triangle = element("triangle");
        SceneElement sphere2 = element("sphere", "radius", "2");

        // ===== Equivalence Partitions Tests =====
        // TC01: the name
        assertEquals("geometries", geometries.name(), "TC01: wrong name");
        // TC02: children in the order they were added: sphere, triangle, sphere
        geometries.addChild(sphere1);
        geometries.addChild(triangle);
        geometries.addChild(sphere2);
        assertEquals(List.of(sphere1, triangle, sphere2), geometries.children(), "TC02: wrong children or order");
        // TC03: child(name) gives the first child of that name
        assertSame(sphere1, geometries.child("sphere"), "TC03: child must give the first sphere");
        assertSame(triangle, geometries.child("triangle"), "TC03: child must give the triangle");
        // TC04: no child of that name → null
        assertNull(geometries.child("plane"), "TC04: a missing child must be null");
        // TC05: the children list cannot be changed from outside
        assertThrows(UnsupportedOperationException.class, () -> geometries.children().add(sphere1),
                "TC05: children() must be unmodifiable");

        // ===== Boundary Values Tests =====
        // TC11: an element without children: empty list, child → null
        assertTrue(sphere1.children().isEmpty(), "TC11: a leaf must have no children");
        assertNull(sphere1.child("sphere"), "TC11: a leaf's child must be null");
        // TC12: names are case-sensitive
        assertNull(geometries.child("Sphere"), "TC12: child names must be case-sensitive");
    }

    /** Test method for {@link SceneElement#has(String)} and {@link SceneElement#text(String)}. */
    @Test
    void testHasAndText() {
        SceneElement e = element("scene", "name", "tiny", "empty", "");

        // ===== Equivalence Partitions Tests =====
        // TC01: a given attribute: has → true, text → its text
        assertTrue(e.has("name"), "TC01: has must be true for a given attribute");
        assertEquals("tiny", e.text("name"), "TC01: wrong text");
        // TC02: a missing attribute: has → false, text → null
        assertFalse(e.has("background-color"), "TC02: has must be false for a missing attribute");
        assertNull(e.text("background-color"), "TC02: text must be null for a missing attribute");

        // ===== Boundary Values Tests =====
        // TC11: an empty attribute is present, with text ""
        assertTrue(e.has("empty"), "TC11: an empty attribute must be present");
        assertEquals("", e.text("empty"), "TC11: an empty attribute's text must be empty");
    }

    /** Test method for the typed getters with a missing attribute. */
    @Test
    void testMissingAttribute() {
        SceneElement e = element("sphere", "center", "0 0 0");

        // ===== Equivalence Partitions Tests =====
        // TC01: number of a missing attribute → SceneFileException at 3:17 naming the element and the attribute
        SceneFileException ex = assertThrows(SceneFileException.class, () -> e.number("radius"),
                "TC01: a missing attribute must be reported");
        assertEquals(FILE + ":3:17: <sphere>: attribute 'radius' is missing", ex.getMessage(),
                "TC01: wrong message");
        assertEquals("<sphere>: attribute 'radius' is missing", ex.getProblem(), "TC01: wrong problem");
        assertEquals(FILE, ex.getFile(), "TC01: wrong file");
        assertEquals(3, ex.getLine(), "TC01: wrong line");
        assertEquals(17, ex.getColumn(), "TC01: wrong column");
        assertNull(ex.getCause(), "TC01: no cause");
        // TC02: every other typed getter reports the missing attribute too
        assertMessage(assertThrows(SceneFileException.class, () -> e.integer("width"), "TC02: integer"),
                "'width' is missing", "TC02");
        assertMessage(assertThrows(SceneFileException.class, () -> e.longInteger("seed"), "TC02: longInteger"),
                "'seed' is missing", "TC02");
        assertMessage(assertThrows(SceneFileException.class, () -> e.flag("adaptive"), "TC02: flag"),
                "'adaptive' is missing", "TC02");
        assertMessage(assertThrows(SceneFileException.class, () -> e.numbers("vertices"), "TC02: numbers"),
                "'vertices' is missing", "TC02");
        assertMessage(assertThrows(SceneFileException.class, () -> e.point("p0"), "TC02: point"),
                "'p0' is missing", "TC02");
        assertMessage(assertThrows(SceneFileException.class, () -> e.vector("dir"), "TC02: vector"),
                "'dir' is missing", "TC02");
        assertMessage(assertThrows(SceneFileException.class, () -> e.color("emission"), "TC02: color"),
                "'emission' is missing", "TC02");

        // ===== Boundary Values Tests =====
        // TC11: attribute names are case-sensitive: "Center" is missing though "center" is given
        assertMessage(assertThrows(SceneFileException.class, () -> e.point("Center"), "TC11: Center is missing"),
                "'Center' is missing", "TC11");
    }

    /** Test method for {@link SceneElement#error(String, Throwable)}. */
    @Test
    void testError() {
        SceneElement e = element("sphere");
        IllegalArgumentException cause = new IllegalArgumentException("radius must be positive");

        // ===== Equivalence Partitions Tests =====
        // TC01: "scenes/e.xml:3:17: <sphere>: radius must be positive", the cause kept
        SceneFileException ex = e.error("radius must be positive", cause);
        assertEquals(FILE + ":3:17: <sphere>: radius must be positive", ex.getMessage(), "TC01: wrong message");
        assertEquals("<sphere>: radius must be positive", ex.getProblem(), "TC01: wrong problem");
        assertEquals(3, ex.getLine(), "TC01: wrong line");
        assertEquals(17, ex.getColumn(), "TC01: wrong column");
        assertSame(cause, ex.getCause(), "TC01: the cause must be kept");

        // ===== Boundary Values Tests =====
        // TC11: an element at line 1, column 8 (just after "<scene>"), no cause
        SceneFileException first = new SceneElement(FILE, "scene", Map.of(), 1, 8).error("empty", null);
        assertEquals(FILE + ":1:8: <scene>: empty", first.getMessage(), "TC11: wrong message at 1:8");
        assertNull(first.getCause(), "TC11: the cause must be null");
    }
}
