package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static testutil.TestAssertions.assertColor;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertPrintable;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import geometries.Polygon;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.Render;
import scene.Scene;
import testutil.TestFiles;

/**
 * Unit tests for {@link ImageTexture}: reading (and refusing) image files, the texels at their centres,
 * bilinear filtering between them, repetition, and a 2 × 2 image on a textured square in a picture.
 */
class ImageTextureTest {
    private static final Path FOLDER = Path.of("target", "test-images", "texture");
    private static final int RED = 0xFF0000;
    private static final int GREEN = 0x00FF00;
    private static final int BLUE = 0x0000FF;
    private static final int WHITE = 0xFFFFFF;
    /** A 2 × 2 image: red, green on the top row; blue, white on the bottom one. */
    private static final Path FOUR = TestFiles.writePng(FOLDER, "four.png", 2, RED, GREEN, BLUE, WHITE);

    /** Test method for {@link ImageTexture#ImageTexture(Path, double)}: reading the file. */
    @Test
    void testConstructor() {
        ImageTexture texture = new ImageTexture(FOUR, 100);
        // ===== Equivalence Partitions Tests =====
        // TC01: a 2 × 2 PNG, its file and size kept; the default size is 1
        assertEquals(2, texture.getWidth(), "TC01: wrong width");
        assertEquals(2, texture.getHeight(), "TC01: wrong height");
        assertEquals(FOUR, texture.getFile(), "TC01: wrong file");
        assertEquals(100, texture.getSize(), 0, "TC01: wrong size");
        assertEquals(1, new ImageTexture(FOUR).getSize(), 0, "TC01: the default size is 1");
        // TC02: a missing file, a file that is no image, a folder: each message names the path
        Path missing = FOLDER.resolve("missing.png");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new ImageTexture(missing),
                "TC02: a missing file"), "not found: " + missing, "TC02");
        Path text = TestFiles.write(FOLDER, "text.png", "not an image");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new ImageTexture(text),
                "TC02: not an image"), text + " is not an image", "TC02");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new ImageTexture(FOLDER),
                "TC02: a folder"), "folder", "TC02");
        // TC03: a null file, a size that is not positive
        assertThrows(IllegalArgumentException.class, () -> new ImageTexture(null), "TC03: null file");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new ImageTexture(FOUR, -2),
                "TC03: negative size"), "size", "TC03");
        // TC04: a named pipe is refused without reading it (which could wait forever), naming the pipe
        Path pipe = TestFiles.fifo(FOLDER.resolve("pipes"), "texture.png");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new ImageTexture(pipe),
                "TC04: a pipe"), "pipe", "TC04");
        // TC05: a file name with an escape character: the message quotes it printably, as \x1B
        Path escaped = FOLDER.resolve("\u001B[2Jmissing.png");
        assertPrintable(assertThrows(IllegalArgumentException.class, () -> new ImageTexture(escaped),
                "TC05: a missing file with an escape in its name").getMessage(), "\\x1B[2J", "TC05");
        // ===== Boundary Values Tests =====
        // TC11: size 0 is refused; a 1 × 1 image is read
        assertThrows(IllegalArgumentException.class, () -> new ImageTexture(FOUR, 0), "TC11: size 0");
        assertEquals(1, new ImageTexture(TestFiles.writePng(FOLDER, "one.png", 1, RED)).getWidth(), "TC11: 1 × 1");
    }

    /** Test method for {@link ImageTexture#getColor(double, double)}. */
    @Test
    void testGetColor() {
        ImageTexture texture = new ImageTexture(FOUR);
        // ===== Equivalence Partitions Tests =====
        // TC01: at each texel's centre, that texel: v up, so the top row is at v = 0.75
        assertColor(255, 0, 0, texture.getColor(0.25, 0.75), "TC01: the top left texel");
        assertColor(0, 255, 0, texture.getColor(0.75, 0.75), "TC01: the top right texel");
        assertColor(0, 0, 255, texture.getColor(0.25, 0.25), "TC01: the bottom left texel");
        assertColor(255, 255, 255, texture.getColor(0.75, 0.25), "TC01: the bottom right texel");
        // TC02: halfway between red and green, bilinear: (127.5, 127.5, 0)
        assertColor(127.5, 127.5, 0, texture.getColor(0.5, 0.75), "TC02: between two texels");
        // TC03: the centre, the mean of the four: (127.5, 127.5, 127.5)
        assertColor(127.5, 127.5, 127.5, texture.getColor(0.5, 0.5), "TC03: between four texels");
        // ===== Boundary Values Tests =====
        // TC11: the image repeats: one square further, and one back, the same texels
        assertColor(255, 0, 0, texture.getColor(1.25, 0.75), "TC11: repeated along u");
        assertColor(0, 0, 255, texture.getColor(-0.75, -0.75), "TC11: repeated back along u and v");
        // TC12: on the image's edge the filter wraps around: at u = 0 red mixes with green
        assertColor(127.5, 127.5, 0, texture.getColor(0, 0.75), "TC12: the left edge wraps to the right");
        // TC13: the size scales the coordinates: with size 100, (25, 75) is the top left texel
        assertColor(255, 0, 0, new ImageTexture(FOUR, 100).getColor(25, 75), "TC13: size 100");
    }

    /** Asserts a pixel is a packed RGB colour within one level in each channel (the render's rounding). */
    private static void assertPixel(int rgb, java.awt.Color pixel, String message) {
        assertEquals(rgb >> 16 & 0xFF, pixel.getRed(), 1, message + " (red)");
        assertEquals(rgb >> 8 & 0xFF, pixel.getGreen(), 1, message + " (green)");
        assertEquals(rgb & 0xFF, pixel.getBlue(), 1, message + " (blue)");
    }

    /**
     * Test method for {@link ImageTexture} in a picture: a textured square of edge 100 (emission white, no
     * lights) with the 2 × 2 image over it, seen as 6 × 6 pixels, shows the four texels, one in each
     * quarter: pixels 1 and 4 of a row or column look at the texels' centres, 25 and 75.
     */
    @Test
    void testTexturedSquare() {
        Scene scene = new Scene("textured square");
        scene.geometries.add(new Polygon(new Point3D(0, 0, 0), new Point3D(100, 0, 0), new Point3D(100, 100, 0),
                new Point3D(0, 100, 0)).setEmission(new Color(255, 255, 255)).setTexture(new ImageTexture(FOUR, 100)));
        ImageWriter image = new ImageWriter("square", 6, 6, FOLDER);
        Render render = new Render().setImageWriter(image)
                .setCamera(new Camera(new Point3D(50, 50, 1000), new Vector(0, 0, -1), new Vector(0, 1, 0))
                        .setVpSize(100, 100).setVpDistance(1000))
                .setRayTracer(new RayTracerBasic(scene));
        render.renderImage();
        render.writeToImage();
        // ===== Equivalence Partitions Tests =====
        // TC01: the centre of each quarter shows its texel
        assertPixel(RED, image.getPixel(1, 1), "TC01: the top left quarter");
        assertPixel(GREEN, image.getPixel(4, 1), "TC01: the top right quarter");
        assertPixel(BLUE, image.getPixel(1, 4), "TC01: the bottom left quarter");
        assertPixel(WHITE, image.getPixel(4, 4), "TC01: the bottom right quarter");
        // ===== Boundary Values Tests =====
        // TC11: nearer the middle the filter blends: a third of the way from red to green, neither pure
        java.awt.Color middle = image.getPixel(2, 1);
        assertEquals(true, middle.getRed() > 0 && middle.getGreen() > 0, "TC11: blended across the middle, " + middle);
    }
}
