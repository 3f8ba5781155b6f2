package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotSame;
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
import renderer.ImageWriter;
import testutil.TestAnimations;
import testutil.TestFiles;
import testutil.TestImages;

/**
 * Tests for {@link AnimatedScene}: the pictures of a scene file at times of its run — what spins and
 * orbits, what is shared between them — rendered small under {@code target/}, their pixels checked.
 */
class AnimatedSceneTest {
    private static final Path FOLDER = Path.of("target", "test-scenes", "animated");

    /** Renders a picture to FOLDER/NAME.png and returns its image. */
    private static ImageWriter render(Picture picture, String name) {
        return picture.render(picture.newRender(FOLDER.resolve(name + ".png"))).getImageWriter();
    }

    private static boolean sphereAt(ImageWriter image, int x, int y) {
        return TestAnimations.isSphere(image.getPixel(x, y).getRGB());
    }

    /** Test method for {@link AnimatedScene#at(double)}. */
    @Test
    void testAt() {
        AnimatedScene scene = SceneLoader.loadAnimation(TestAnimations.spinning(FOLDER, "spin.xml", ""));
        int x = TestAnimations.SPHERE_AT_START[0];
        int y = TestAnimations.SPHERE_AT_START[1];
        // ===== Equivalence Partitions Tests =====
        // TC01: the spinning group: at time 0 the sphere is right of centre, at 0.5 left of it (a half turn
        // takes (30, 0, 0) to (−30, 0, 0))
        ImageWriter start = render(scene.at(0), "spin0");
        ImageWriter half = render(scene.at(0.5), "spin50");
        assertTrue(sphereAt(start, x, y) && !sphereAt(start, 23 - x, y), "TC01: time 0 must show the sphere right");
        assertTrue(sphereAt(half, 23 - x, y) && !sphereAt(half, x, y), "TC01: time 0.5 must show the sphere left");
        Instance group = assertInstanceOf(Instance.class, bodies(scene.at(0.5)).get(0), "TC01: the group is placed");
        assertEquals(0, group.getTransform().apply(new Point3D(30, 0, 0)).distance(new Point3D(-30, 0, 0)), 1e-9,
                "TC01: a half turn at time 0.5");
        // TC02: the moving group is built anew at each time, the still sphere in it once and shared
        Instance again = assertInstanceOf(Instance.class, bodies(scene.at(0.25)).get(0), "TC02: placed");
        assertNotSame(group, again, "TC02: the moving group is placed anew");
        assertSame(((Geometries) group.getBody()).getGeometries().get(0),
                ((Geometries) again.getBody()).getGeometries().get(0), "TC02: the still sphere inside is shared");
        // TC03: the picture of a time is the same whichever came before: time 0 again gives the same pixels
        assertEquals(0, TestImages.differentPixels(start, render(scene.at(0), "spin0again")),
                "TC03: time 0 must render the same");
        // TC04: a camera orbit of 180° and the spin of 360° at time 0.5: the camera behind, looking along +z,
        // sees the sphere, at (−30, 0, 0), right of centre (its vRight is −x)
        AnimatedScene orbit = SceneLoader.loadAnimation(TestAnimations.spinning(FOLDER, "orbit.xml",
                "<animation orbit-degrees=\"360\"/>"));
        ImageWriter behind = render(orbit.at(0.5), "orbit50");
        assertEquals(1, orbit.at(0.5).camera().getVTo().getZ(), 1e-12, "TC04: the camera must look along +z");
        assertTrue(sphereAt(behind, x, y) && !sphereAt(behind, 23 - x, y), "TC04: seen from behind, right of centre");
        // TC05: a spinning mesh is read once: each time places the same mesh anew
        TestFiles.write(FOLDER, "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        AnimatedScene mesh = SceneLoader.loadAnimation(TestFiles.writeBodies(FOLDER, "mesh.xml",
                "<mesh file=\"tri.obj\"><transform spin-y=\"360\"/></mesh>\n"));
        Instance mesh0 = assertInstanceOf(Instance.class, bodies(mesh.at(0)).get(0), "TC05: a placed mesh");
        Instance mesh1 = assertInstanceOf(Instance.class, bodies(mesh.at(0.5)).get(0), "TC05: a placed mesh");
        assertNotSame(mesh0, mesh1, "TC05: the spin places the mesh anew");
        assertSame(mesh0.getBody(), mesh1.getBody(), "TC05: the mesh must be read once");
        // TC06: an instance of a still body inside a still group, at a later time: the body, placed
        AnimatedScene inGroup = SceneLoader.loadAnimation(TestFiles.writeBodies(FOLDER, "in-group.xml",
                "<geometries><sphere name=\"b\" center=\"0 0 0\" radius=\"1\"/></geometries>\n"
                        + "<instance of=\"b\"><transform spin-y=\"90\" translate=\"5 0 0\"/></instance>\n"));
        Geometries group0 = (Geometries) bodies(inGroup.at(0)).get(0);
        Instance later = assertInstanceOf(Instance.class, bodies(inGroup.at(0.5)).get(1), "TC06: the instance");
        assertSame(group0.getGeometries().get(0), later.getBody(), "TC06: the instance must place the sphere");

        // ===== Boundary Values Tests =====
        // TC11: a NaN or infinite time: refused
        assertMessage(assertThrows(IllegalArgumentException.class, () -> scene.at(Double.NaN), "TC11: NaN"),
                "animation time", "TC11");
        assertThrows(IllegalArgumentException.class, () -> scene.at(Double.POSITIVE_INFINITY), "TC11: infinity");
        // TC12: time 1 is the end of a full turn: the picture of time 0
        assertEquals(0, TestImages.differentPixels(start, render(scene.at(1), "spin100")),
                "TC12: a full turn must come back");
    }

    /** Test method for {@link AnimatedScene#moves()}. */
    @Test
    void testMoves() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a spin moves; a camera orbit moves
        assertTrue(SceneLoader.loadAnimation(TestAnimations.spinning(FOLDER, "spin.xml", "")).moves(), "TC01: spin");
        Path orbit = TestFiles.write(FOLDER, "orbit-only.xml", "<scene><animation orbit-degrees=\"10\"/></scene>");
        assertTrue(SceneLoader.loadAnimation(orbit).moves(), "TC01: orbit");
        // TC02: a still scene does not move, and its bodies are shared by all times
        Path still = TestFiles.writeBodies(FOLDER, "still.xml", "<sphere center=\"0 0 0\" radius=\"1\"/>\n");
        AnimatedScene scene = SceneLoader.loadAnimation(still);
        assertFalse(scene.moves(), "TC02: nothing moves");
        assertSame(bodies(scene.at(0)).get(0), bodies(scene.at(0.7)).get(0), "TC02: a still body is built once");

        // ===== Boundary Values Tests =====
        // TC11: a scene of nothing does not move
        Path empty = TestFiles.write(FOLDER, "empty.xml", "<scene/>");
        assertFalse(SceneLoader.loadAnimation(empty).moves(), "TC11: an empty scene");
    }

    private static List<Intersectable> bodies(Picture picture) {
        return picture.scene().geometries.getGeometries();
    }
}
