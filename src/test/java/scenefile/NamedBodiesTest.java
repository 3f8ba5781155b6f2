package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Instance;
import geometries.Intersectable;
import primitives.Point3D;
import primitives.Ray;
import primitives.Vector;
import testutil.TestFiles;

/**
 * Tests for {@link NamedBodies}, through scene files: {@code <instance>}s of named bodies and groups
 * share them, and a name that is unknown, given twice or not yet built is refused at its place.
 */
class NamedBodiesTest {
    private static final Path FOLDER = Path.of("target", "test-scenes", "names");
    /** A library of a group named "pair": two unit spheres, at the origin and at (3, 0, 0). */
    private static final String PAIR = "<library>\n<geometries name=\"pair\">\n"
            + "<sphere center=\"0 0 0\" radius=\"1\" kD=\"0.5\"/>\n<sphere center=\"3 0 0\" radius=\"1\"/>\n"
            + "</geometries>\n</library>\n";

    /** Loads a scene of the library and these bodies; returns its bodies. */
    private static List<Intersectable> load(String name, String library, String bodies) {
        Path file = TestFiles.write(FOLDER, name, "<scene>\n" + library + "<geometries>\n" + bodies
                + "</geometries>\n</scene>\n");
        return SceneLoader.load(file).scene().geometries.getGeometries();
    }

    /** Asserts that a load fails at a line with a message. */
    private static void assertRefused(String tc, int line, String problem, String library, String bodies) {
        SceneFileException e = assertThrows(SceneFileException.class, () -> load("bad.xml", library, bodies),
                tc + ": must be refused");
        assertEquals(line, e.getLine(), tc + ": wrong line in " + e.getMessage());
        assertTrue(e.getColumn() > 0, tc + ": no column");
        assertMessage(e, problem, tc);
    }

    /** Test method for {@link NamedBodies#target(SceneElement)}. */
    @Test
    void testInstances() {
        // ===== Equivalence Partitions Tests =====
        // TC01: two instances of the library's group: the library is not in the picture; both place the same
        // group, one moved up by 10: a ray down x at y = 10 meets its spheres at x = −1 and 2
        List<Intersectable> bodies = load("pair.xml", PAIR,
                "<instance of=\"pair\"><transform translate=\"0 10 0\"/></instance>\n<instance of=\"pair\"/>\n");
        assertEquals(2, bodies.size(), "TC01: two instances, and no library");
        Instance up = assertInstanceOf(Instance.class, bodies.get(0), "TC01: an instance");
        Instance still = assertInstanceOf(Instance.class, bodies.get(1), "TC01: an instance");
        assertInstanceOf(Geometries.class, up.getBody(), "TC01: the instance places the group");
        assertSame(up.getBody(), still.getBody(), "TC01: the instances must share the group");
        List<Point3D> hits = up.findIntersections(new Ray(new Point3D(-10, 10, 0), new Vector(1, 0, 0)));
        assertNotNull(hits, "TC01: the moved group must be hit at y = 10");
        assertEquals(4, hits.size(), "TC01: both spheres, twice each");
        assertTrue(hits.contains(new Point3D(-1, 10, 0)) && hits.contains(new Point3D(2, 10, 0)),
                "TC01: wrong hits " + hits);
        // TC02: a body named in <geometries> is in the picture, and an instance after it places it again; an
        // instance of an instance, turned, places that
        bodies = load("inline.xml", "", "<sphere name=\"ball\" center=\"0 0 0\" radius=\"1\"/>\n"
                + "<instance name=\"twin\" of=\"ball\"><transform translate=\"5 0 0\"/></instance>\n"
                + "<instance of=\"twin\"><transform rotate-z=\"90\"/></instance>\n");
        assertEquals(3, bodies.size(), "TC02: the ball and two instances");
        Instance twin = assertInstanceOf(Instance.class, bodies.get(1), "TC02: an instance");
        assertSame(bodies.get(0), twin.getBody(), "TC02: the instance must place the ball itself");
        Instance turned = assertInstanceOf(Instance.class, bodies.get(2), "TC02: an instance of an instance");
        assertSame(twin, turned.getBody(), "TC02: the instance of the twin must place the twin");
        assertEquals(0, new Point3D(0, 5, 0).distance(turned.findIntersections(new Ray(new Point3D(0, 10, 0),
                new Vector(0, -1, 0))).get(0)) - 1, 1e-9, "TC02: the twin turned about z must be met at (0, 6, 0)");
        // TC03: a name misspelt: refused at the instance, naming the nearest name
        assertRefused("TC03", 9, "<instance>: no body is named 'piar'; did you mean 'pair'?", PAIR,
                "<instance of=\"piar\"/>\n");

        // ===== Boundary Values Tests =====
        // TC11: no names in the file at all
        assertRefused("TC11", 3, "no body is named 'pair'", "", "<instance of=\"pair\"/>\n");
        // TC12: a name given twice: refused at the second, naming the first's line
        assertRefused("TC12", 9, "the name 'pair' is already the name of the <geometries> at line 3", PAIR,
                "<sphere name=\"pair\" center=\"0 0 0\" radius=\"1\"/>\n");
        // TC13: an instance before its body, and one inside the group it names: not built yet
        assertRefused("TC13", 3, "the body named 'ball' is not built yet", "",
                "<instance of=\"ball\"/>\n<sphere name=\"ball\" center=\"0 0 0\" radius=\"1\"/>\n");
        assertRefused("TC13", 4, "the body named 'group' is not built yet", "",
                "<geometries name=\"group\">\n<instance of=\"group\"/>\n</geometries>\n");
        // TC14: a name that is not one: refused by the schema
        assertRefused("TC14", 3, "attribute 'name' of <sphere> must be a name", "",
                "<sphere name=\"2 balls\" center=\"0 0 0\" radius=\"1\"/>\n");
    }

    /** Test method for {@link NamedBodies#moves(SceneElement)}, through {@link AnimatedScene#moves()}. */
    @Test
    void testMoves() {
        // ===== Equivalence Partitions Tests =====
        // TC01: an instance of a spinning body moves; an instance of a still one does not
        String spinning = "<library>\n<sphere name=\"s\" center=\"1 0 0\" radius=\"1\"><transform spin-y=\"90\"/>"
                + "</sphere>\n</library>\n";
        assertTrue(moves("spin.xml", spinning, "<instance of=\"s\"/>"), "TC01: an instance of a spinning body");
        assertFalse(moves("still.xml", PAIR, "<instance of=\"pair\"/>"), "TC01: an instance of a still group");
        // TC02: a body inside a spinning group moves
        assertTrue(moves("group.xml", "", "<geometries><transform spin-x=\"1\"/><sphere center=\"0 0 0\""
                + " radius=\"1\"/></geometries>"), "TC02: a spinning group");

        // ===== Boundary Values Tests =====
        // TC11: a spin of 0 does not move
        assertFalse(moves("zero.xml", "", "<sphere center=\"0 0 0\" radius=\"1\"><transform spin-z=\"0\"/></sphere>"),
                "TC11: a spin of 0");
    }

    private static boolean moves(String name, String library, String bodies) {
        Path file = TestFiles.write(FOLDER, name, "<scene>\n" + library + "<geometries>\n" + bodies
                + "</geometries>\n</scene>\n");
        return SceneLoader.loadAnimation(file).moves();
    }
}
