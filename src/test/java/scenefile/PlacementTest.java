package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import geometries.Instance;
import geometries.Sphere;
import primitives.Point3D;
import primitives.Transform;
import renderer.Camera;
import testutil.TestFiles;

/**
 * Tests for {@link Placement}, through scene files: the transform a {@code <transform>} gives (compared
 * by the points it moves), at times of an animation, and the camera's orbit; bad values named at their
 * file, line and column.
 */
class PlacementTest {
    private static final Path FOLDER = Path.of("target", "test-scenes", "placement");

    /** A unit sphere at the origin with a {@code <transform>} of these attributes, on line 4. */
    private static Path sphereFile(String name, String attributes) {
        return TestFiles.writeBodies(FOLDER, name, "<sphere center=\"0 0 0\" radius=\"1\">\n<transform " + attributes
                + "/>\n</sphere>\n");
    }

    /** The transform of the sphere of {@link #sphereFile} at a time. */
    private static Transform transform(String attributes, double time) {
        Picture picture = SceneLoader.loadAnimation(sphereFile("t.xml", attributes)).at(time);
        Instance instance = assertInstanceOf(Instance.class, picture.scene().geometries.getGeometries().get(0),
                "a body with a <transform> must be an Instance");
        assertInstanceOf(Sphere.class, instance.getBody(), "the instance must place the sphere");
        return instance.getTransform();
    }

    /** Asserts that a transform moves a point where expected, within 1e-12. */
    private static void assertMoves(Transform transform, Point3D from, Point3D to, String message) {
        Point3D moved = transform.apply(from);
        assertEquals(0, moved.distance(to), 1e-12, message + ": " + from + " went to " + moved + ", not " + to);
    }

    /** Test method for {@link Placement#transform(SceneElement, double)}. */
    @Test
    void testTransform() {
        // ===== Equivalence Partitions Tests =====
        // TC01: translate="0 -50 0": (1, 2, 3) → (1, −48, 3)
        assertMoves(transform("translate=\"0 -50 0\"", 0), new Point3D(1, 2, 3), new Point3D(1, -48, 3), "TC01");
        // TC02: scale, then rotate, then translate, whatever the attributes' order: scale 2, rotate-y 90,
        // translate (10, 0, 0) take (1, 0, 0) to (2, 0, 0), (0, 0, −2), then (10, 0, −2)
        Transform t = transform("translate=\"10 0 0\" rotate-y=\"90\" scale=\"2\"", 0);
        assertMoves(t, new Point3D(1, 0, 0), new Point3D(10, 0, -2), "TC02");
        // TC03: a non-uniform scale "1 2 3": (1, 1, 1) → (1, 2, 3)
        assertMoves(transform("scale=\"1 2 3\"", 0), new Point3D(1, 1, 1), new Point3D(1, 2, 3), "TC03");
        // TC04: rotate-x before rotate-z: (0, 0, 1) → (0, −1, 0) → (1, 0, 0) (the other order gives (0, −1, 0))
        assertMoves(transform("rotate-z=\"90\" rotate-x=\"90\"", 0), new Point3D(0, 0, 1), new Point3D(1, 0, 0),
                "TC04");
        // TC05: spin-y 360 at time 0.25 is a quarter turn, after the rotation and before the translation:
        // rotate-y 90, spin-y 360, translate (0, 5, 0) take (1, 0, 0) to (0, 0, −1), (−1, 0, 0), (−1, 5, 0)
        assertMoves(transform("rotate-y=\"90\" spin-y=\"360\" translate=\"0 5 0\"", 0.25), new Point3D(1, 0, 0),
                new Point3D(-1, 5, 0), "TC05");

        // ===== Boundary Values Tests =====
        // TC11: an empty <transform>, a translation by 0 0 0, a spin at time 0: the identity
        assertSame(Transform.IDENTITY, transform("", 0), "TC11: an empty transform is the identity");
        assertSame(Transform.IDENTITY, transform("translate=\"0 0 0\"", 0), "TC11: translate 0 0 0");
        assertSame(Transform.IDENTITY, transform("spin-y=\"360\"", 0), "TC11: a spin at time 0");
        // TC12: a full spin at time 1 comes back: (1, 0, 0) stays
        assertMoves(transform("spin-z=\"360\"", 1), new Point3D(1, 0, 0), new Point3D(1, 0, 0), "TC12");
    }

    /** Test method for {@link Placement#transform(SceneElement, double)}: bad values, named where they are. */
    @Test
    void testBadTransforms() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a scale of 0, whole or along an axis: refused at the <transform>'s line and column
        for (String scale : new String[] {"0", "1 0 1"}) {
            Path file = sphereFile("zero.xml", "scale=\"" + scale + "\"");
            SceneFileException e = assertThrows(SceneFileException.class, () -> SceneLoader.load(file), "TC01: 0");
            assertEquals(4, e.getLine(), "TC01: wrong line");
            assertTrue(e.getColumn() > 0, "TC01: no column");
            assertTrue(e.getMessage().startsWith(file + ":4:" + e.getColumn() + ": <transform>: scale factor along"),
                    "TC01: wrong message: " + e.getMessage());
            assertMessage(e, "must not be 0", "TC01");
        }
        // TC02: NaN, a word, two numbers for a scale: refused by the schema, at their place
        String[][] bad = {{"rotate-y=\"NaN\"", "attribute 'rotate-y' of <transform> must be a number, got 'NaN'"},
                {"translate=\"1 x 3\"", "attribute 'translate' of <transform> must be three numbers"},
                {"scale=\"1 2\"", "attribute 'scale' of <transform> must be one number, or three (x y z), got '1 2'"},
                {"rotate=\"30\"", "unknown attribute 'rotate' on <transform>"}};
        for (String[] value : bad) {
            Path file = sphereFile("bad.xml", value[0]);
            SceneFileException e = assertThrows(SceneFileException.class, () -> SceneLoader.load(file), "TC02");
            assertEquals(4, e.getLine(), "TC02: wrong line for " + value[0]);
            assertMessage(e, value[1], "TC02");
        }

        // ===== Boundary Values Tests =====
        // TC11: two transforms on a body: refused, the second named
        Path two = TestFiles.writeBodies(FOLDER, "two.xml", "<sphere center=\"0 0 0\" radius=\"1\">\n<transform/>\n"
                + "<transform/>\n</sphere>\n");
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneLoader.load(two), "TC11");
        assertEquals(5, e.getLine(), "TC11: wrong line");
        assertMessage(e, "<sphere> may have only one <transform>", "TC11");
        // TC12: two transforms in a group: refused at the second
        Path group = TestFiles.writeBodies(FOLDER, "group.xml", "<geometries>\n<transform/>\n<sphere center=\"0 0 0\""
                + " radius=\"1\"/>\n<transform/>\n</geometries>\n");
        e = assertThrows(SceneFileException.class, () -> SceneLoader.load(group), "TC12");
        assertEquals(6, e.getLine(), "TC12: wrong line");
        assertMessage(e, "a group has one <transform> at most; the first is at line 4", "TC12");
    }

    /** Test method for {@link Placement#orbit(SceneElement, double)} and {@link Placement#orbited}. */
    @Test
    void testOrbit() {
        String camera = "<camera p0=\"0 0 0\" vTo=\"0 0 -1\" vUp=\"0 1 0\" vp-distance=\"50\"/>\n";
        Path file = TestFiles.write(FOLDER, "orbit.xml", "<scene>\n" + camera
                + "<animation orbit-center=\"0 0 -100\" orbit-axis=\"0 2 0\" orbit-degrees=\"360\"/>\n</scene>\n");
        AnimatedScene scene = SceneLoader.loadAnimation(file);
        // ===== Equivalence Partitions Tests =====
        // TC01: a quarter of the run, a quarter turn about y through (0, 0, −100): the camera's offset (0, 0, 100)
        // from the centre turns to (100, 0, 0), so it is at (100, 0, −100), looking along (−1, 0, 0) at the
        // centre, up still (0, 1, 0)
        Camera quarter = scene.at(0.25).camera();
        assertEquals(0, quarter.getP0().distance(new Point3D(100, 0, -100)), 1e-10, "TC01: wrong position");
        assertEquals(-1, quarter.getVTo().getX(), 1e-12, "TC01: wrong direction");
        assertEquals(1, quarter.getVUp().getY(), 1e-12, "TC01: wrong up");
        assertEquals(50, quarter.getDistance(), 0, "TC01: the view plane must stay");
        // TC02: half the run: behind the centre, (0, 0, −200), looking along +z
        Camera half = scene.at(0.5).camera();
        assertEquals(0, half.getP0().distance(new Point3D(0, 0, -200)), 1e-10, "TC02: wrong position");
        assertEquals(1, half.getVTo().getZ(), 1e-12, "TC02: wrong direction");

        // ===== Boundary Values Tests =====
        // TC11: time 0, and no <animation>: the camera of the file
        assertEquals(Point3D.ZERO, scene.at(0).camera().getP0(), "TC11: time 0 must not move the camera");
        assertNull(Placement.orbit(null, 0.5), "TC11: no <animation>, no orbit");
        // TC12: an orbit axis of 0 0 0: refused at the <animation>'s line
        Path zero = TestFiles.write(FOLDER, "zero-axis.xml", "<scene>\n" + camera
                + "<animation orbit-axis=\"0 0 0\" orbit-degrees=\"90\"/>\n</scene>\n");
        SceneFileException e = assertThrows(SceneFileException.class, () -> SceneLoader.loadAnimation(zero).at(0.5),
                "TC12: a zero axis");
        assertEquals(3, e.getLine(), "TC12: wrong line");
        assertMessage(e, "<animation>: orbit-axis must not be 0 0 0", "TC12");
        // TC13: an orbit of 0 degrees does not move, and the scene does not either
        Path still = TestFiles.write(FOLDER, "still.xml", "<scene>\n" + camera + "<animation/>\n</scene>\n");
        assertFalse(SceneLoader.loadAnimation(still).moves(), "TC13: an orbit of 0 degrees is still");
    }
}
