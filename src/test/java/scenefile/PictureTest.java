package scenefile;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

import primitives.Color;
import primitives.Point3D;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerBase;
import renderer.RayTracerBasic;
import renderer.Render;
import scene.Scene;

/**
 * Unit tests for {@link Picture}: the checks of its parts, the copies, {@link Picture#newRender(Path)} and
 * {@link Picture#render(Render)} (PNG files written under {@code target/test-images/picture/}).
 */
class PictureTest {
    private static final Path FOLDER = Path.of("target", "test-images", "picture");
    /** The background of the test scene, RGB (20, 40, 60). */
    private static final java.awt.Color BACKGROUND = new java.awt.Color(20, 40, 60);
    private static final java.awt.Color YELLOW = new java.awt.Color(255, 255, 0);

    private final Scene scene = new Scene("picture").setBackground(new Color(BACKGROUND));
    private final Camera camera = new Camera(new Point3D(0, 0, 1000), new Vector(0, 0, -1), new Vector(0, 1, 0))
            .setVpSize(200, 150).setVpDistance(1000);

    /** Renders a 40 × 30 picture of the empty scene with a grid interval, and checks the PNG file. */
    private Render renderGrid(String name, int grid) {
        Picture picture = new Picture(name, 40, 30, scene, camera, grid, RenderSettings.DEFAULT);
        Path png = FOLDER.resolve(name + ".png");
        try {
            Files.deleteIfExists(png);
            Render render = picture.newRender(png).setMultithreading(2);
            assertSame(render, picture.render(render), name + ": render must return the render");
            BufferedImage image = ImageIO.read(png.toFile());
            assertNotNull(image, name + ": the PNG file must be readable");
            assertEquals(40, image.getWidth(), name + ": the PNG must be 40 wide");
            assertEquals(30, image.getHeight(), name + ": the PNG must be 30 high");
            for (int y = 0; y < 30; ++y)
                for (int x = 0; x < 40; ++x)
                    assertEquals(render.getImageWriter().getPixel(x, y).getRGB() & 0xFFFFFF,
                            image.getRGB(x, y) & 0xFFFFFF,
                            name + ": the file's pixel (" + x + ", " + y + ") must be the image's");
            return render;
        } catch (IOException e) {
            throw new AssertionError(name + ": cannot read " + png, e);
        }
    }

    /** Asserts that exactly the pixels on rows and columns multiple of the interval are yellow. */
    private static void assertGrid(Render render, int interval, String tc) {
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) {
                boolean onGrid = interval > 0 && (x % interval == 0 || y % interval == 0);
                assertEquals(onGrid ? YELLOW : BACKGROUND, render.getImageWriter().getPixel(x, y),
                        tc + ": pixel (" + x + ", " + y + ") must be " + (onGrid ? "the grid" : "the background"));
            }
    }

    /** Test method for the checks of {@link Picture#Picture(String, int, int, Scene, Camera, int, RenderSettings)}. */
    @Test
    void testConstructor() {
        RenderSettings settings = RenderSettings.DEFAULT.withAntiAliasing(2);

        // ===== Equivalence Partitions Tests =====
        // TC01: good parts are kept: "p", 40 × 30, grid 10, the settings
        Picture p = new Picture("p", 40, 30, scene, camera, 10, settings);
        assertEquals("p", p.name(), "TC01: wrong name");
        assertEquals(40, p.nX(), "TC01: wrong nX");
        assertEquals(30, p.nY(), "TC01: wrong nY");
        assertSame(scene, p.scene(), "TC01: wrong scene");
        assertSame(camera, p.camera(), "TC01: wrong camera");
        assertEquals(10, p.gridInterval(), "TC01: wrong grid interval");
        assertSame(settings, p.settings(), "TC01: wrong settings");
        // TC02: a null name, scene, camera or settings → IllegalArgumentException naming it
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture(null, 40, 30, scene, camera, 0, settings), "TC02: null name"),
                "picture name must not be null", "TC02");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", 40, 30, null, camera, 0, settings), "TC02: null scene"),
                "picture scene must not be null", "TC02");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", 40, 30, scene, null, 0, settings), "TC02: null camera"),
                "picture camera must not be null", "TC02");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", 40, 30, scene, camera, 0, null), "TC02: null settings"),
                "picture render settings must not be null", "TC02");
        // TC03: a negative size (-40 × 30, 40 × -30) → "size"
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", -40, 30, scene, camera, 0, settings), "TC03: negative width"), "size", "TC03");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", 40, -30, scene, camera, 0, settings), "TC03: negative height"), "size", "TC03");
        // TC04: a negative grid interval (-5) → "grid"
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", 40, 30, scene, camera, -5, settings), "TC04: negative grid"), "grid", "TC04");

        // ===== Boundary Values Tests =====
        // TC11: width 0 or height 0 → "size"
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", 0, 30, scene, camera, 0, settings), "TC11: width 0"), "size", "TC11");
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", 40, 0, scene, camera, 0, settings), "TC11: height 0"), "size", "TC11");
        // TC12: 1 × 1 is accepted
        Picture tiny = assertDoesNotThrow(() -> new Picture("p", 1, 1, scene, camera, 0, settings),
                "TC12: 1 × 1 must be accepted");
        assertEquals(1, tiny.nX() * tiny.nY(), "TC12: the picture must be 1 × 1");
        // TC13: grid -1 → "grid"; grid 0 (no grid) is accepted
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> new Picture("p", 40, 30, scene, camera, -1, settings), "TC13: grid -1"), "grid", "TC13");
        assertEquals(0, new Picture("p", 40, 30, scene, camera, 0, settings).gridInterval(),
                "TC13: grid 0 must be accepted");
    }

    /** Test method for {@link Picture#Picture(String, int, int, Scene, Camera)}. */
    @Test
    void testDefaultsConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: no grid (0) and the default settings
        Picture p = new Picture("p", 40, 30, scene, camera);
        assertEquals(0, p.gridInterval(), "TC01: the grid interval must be 0");
        assertEquals(RenderSettings.DEFAULT, p.settings(), "TC01: the settings must be the default");
        assertEquals(new Picture("p", 40, 30, scene, camera, 0, RenderSettings.DEFAULT), p,
                "TC01: must equal the full constructor with grid 0 and the default settings");

        // ===== Boundary Values Tests =====
        // TC11: the checks apply: a null name and a 0 width are rejected
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new Picture(null, 40, 30, scene, camera),
                "TC11: null name"), "name", "TC11");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new Picture("p", 0, 30, scene, camera),
                "TC11: width 0"), "size", "TC11");
    }

    /**
     * Test method for {@link Picture#withSoftShadows(String)}, {@link Picture#withSettings(RenderSettings)} and
     * {@link Picture#withSize(int, int)}.
     */
    @Test
    void testWithMethods() {
        RenderSettings settings = new RenderSettings(false, true, 4, 3, 7L);
        Picture p = new Picture("p", 40, 30, scene, camera, 10, settings);

        // ===== Equivalence Partitions Tests =====
        // TC01: withSoftShadows("soft"): the new name and soft shadows on, everything else kept
        Picture soft = p.withSoftShadows("soft");
        assertEquals(new Picture("soft", 40, 30, scene, camera, 10, new RenderSettings(true, true, 4, 3, 7L)), soft,
                "TC01: withSoftShadows must change only the name and softShadows");
        // TC02: withSettings: only the settings change
        RenderSettings other = RenderSettings.DEFAULT.withSeed(99);
        Picture resettled = p.withSettings(other);
        assertEquals(new Picture("p", 40, 30, scene, camera, 10, other), resettled,
                "TC02: withSettings must change only the settings");
        assertSame(other, resettled.settings(), "TC02: the settings must be the given ones");
        // TC03: withSize(80, 60): only the size changes (same camera)
        Picture big = p.withSize(80, 60);
        assertEquals(new Picture("p", 80, 60, scene, camera, 10, settings), big,
                "TC03: withSize must change only the size");
        assertSame(camera, big.camera(), "TC03: the camera must be the same");
        // TC04: the original picture is not changed
        assertEquals(new Picture("p", 40, 30, scene, camera, 10, settings), p, "TC04: the picture must not change");

        // ===== Boundary Values Tests =====
        // TC11: withSoftShadows of an already soft picture keeps soft shadows on
        assertTrue(soft.withSoftShadows("soft2").settings().softShadows(), "TC11: soft shadows must stay on");
        // TC12: withSize(1, 1) is accepted; withSize(0, 60) is rejected
        assertEquals(1, p.withSize(1, 1).nX(), "TC12: 1 × 1 must be accepted");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> p.withSize(0, 60), "TC12: width 0"),
                "size", "TC12");
        // TC13: withSettings(null) and withSoftShadows(null) are rejected
        assertMessage(assertThrows(IllegalArgumentException.class, () -> p.withSettings(null), "TC13: null settings"),
                "settings", "TC13");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> p.withSoftShadows(null), "TC13: null name"),
                "name", "TC13");
    }

    /** Test method for {@link Picture#newRender(Path)}. */
    @Test
    void testNewRender() throws IOException {
        RenderSettings settings = new RenderSettings(true, true, 4, 3, 7L);
        Picture p = new Picture("p", 40, 30, scene, camera, 10, settings);
        Path png = FOLDER.resolve("newRender.png");
        Files.deleteIfExists(png);

        // ===== Equivalence Partitions Tests =====
        // TC01: the image writer is 40 × 30 and writes to the given file
        Render render = p.newRender(png);
        assertEquals(40, render.getImageWriter().getNx(), "TC01: wrong image width");
        assertEquals(30, render.getImageWriter().getNy(), "TC01: wrong image height");
        assertEquals(png, render.getImageWriter().getPath(), "TC01: wrong image file");
        // TC02: a basic ray tracer with the settings (true, true, 4, 3, 7)
        RayTracerBase tracer = assertInstanceOf(RayTracerBasic.class, render.getRayTracer(),
                "TC02: the ray tracer must be a RayTracerBasic");
        assertTrue(tracer.isSoftShadows(), "TC02: soft shadows must be on");
        assertTrue(tracer.isAdaptiveSoftShadows(), "TC02: adaptive soft shadows must be on");
        assertEquals(4, tracer.getSqrtBeamNum(), "TC02: sqrtBeamNum must be 4");
        assertEquals(7L, tracer.getSeed(), "TC02: the seed must be 7");
        assertEquals(3, render.getAntiAliasing(), "TC02: anti-aliasing must be 3");
        // TC03: nothing is rendered or written yet
        assertFalse(Files.exists(png), "TC03: newRender must not write the file");
        // TC04: the default settings give hard shadows and one ray per pixel
        Render plain = new Picture("q", 20, 10, scene, camera).newRender(FOLDER.resolve("q.png"));
        assertFalse(plain.getRayTracer().isSoftShadows(), "TC04: soft shadows must be off");
        assertEquals(9, plain.getRayTracer().getSqrtBeamNum(), "TC04: sqrtBeamNum must be 9");
        assertEquals(1, plain.getAntiAliasing(), "TC04: anti-aliasing must be 1");
        // TC05: a file of a format not written here (.gif) → IllegalArgumentException listing the formats
        assertMessage(assertThrows(IllegalArgumentException.class, () -> p.newRender(FOLDER.resolve("p.gif")),
                "TC05: a .gif file must be rejected"), ".bmp, .jpeg, .jpg, .png", "TC05");
        // TC06: a null file → "image file"
        assertMessage(assertThrows(IllegalArgumentException.class, () -> p.newRender(null),
                "TC06: a null file must be rejected"), "image file", "TC06");

        // ===== Boundary Values Tests =====
        // TC11: ".png" in the middle of the name is not enough
        assertMessage(assertThrows(IllegalArgumentException.class, () -> p.newRender(FOLDER.resolve("p.png.txt")),
                "TC11: p.png.txt must be rejected"), ".png", "TC11");
        // TC12: a file name without a folder stays as given: the current folder
        assertEquals(Path.of("bare.png"), p.newRender(Path.of("bare.png")).getImageWriter().getPath(),
                "TC12: a bare file name must be in the current folder");
        // TC13: the name ".png" alone is no image file → IllegalArgumentException
        assertMessage(assertThrows(IllegalArgumentException.class, () -> p.newRender(FOLDER.resolve(".png")),
                "TC13: .png alone must be rejected"), "must end with one of", "TC13");
        // TC14: a .JPG file (upper case) is accepted
        assertEquals(FOLDER.resolve("p.JPG"), p.newRender(FOLDER.resolve("p.JPG")).getImageWriter().getPath(),
                "TC14: a .JPG file must be accepted");
    }

    /** Test method for {@link Picture#render(Render)}. */
    @Test
    void testRender() {
        // ===== Equivalence Partitions Tests =====
        // TC01: no grid: every pixel of the 40 × 30 PNG is the background (20, 40, 60)
        assertGrid(renderGrid("noGrid", 0), 0, "TC01");
        // TC02: grid 10: yellow on rows 0, 10, 20 and columns 0, 10, 20, 30, background elsewhere
        Render grid = renderGrid("grid10", 10);
        assertGrid(grid, 10, "TC02");
        assertEquals(YELLOW, grid.getImageWriter().getPixel(30, 29), "TC02: column 30 must be yellow");
        assertEquals(BACKGROUND, grid.getImageWriter().getPixel(39, 29), "TC02: pixel (39, 29) must be background");
        assertColor(new Color(YELLOW), Picture.GRID_COLOR, "TC02: the grid must be yellow");

        // ===== Boundary Values Tests =====
        // TC11: grid 1: every pixel is on a line
        assertGrid(renderGrid("grid1", 1), 1, "TC11");
        // TC12: grid 40, as wide as the picture: only row 0 and column 0
        assertGrid(renderGrid("grid40", 40), 40, "TC12");
        // TC13: grid 100, larger than the picture: still row 0 and column 0
        assertGrid(renderGrid("grid100", 100), 100, "TC13");
    }
}
