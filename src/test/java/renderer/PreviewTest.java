package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static testutil.TestAssertions.assertMessage;

import java.awt.image.BufferedImage;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import geometries.Sphere;
import primitives.Color;
import primitives.Point3D;
import primitives.Vector;
import scene.Scene;

/**
 * Unit tests for {@link Preview}, the image model of the preview window: it runs without a display.
 */
class PreviewTest {
    private static final Path FOLDER = Path.of("target", "test-images", "preview");
    private static final Color RED = new Color(255, 0, 0);

    /**
     * Asserts that every pixel of a frame is the image writer's.
     *
     * @param expected the image writer
     * @param frame    the preview's frame
     * @param tc       the test-case label
     */
    private static void assertSamePixels(ImageWriter expected, BufferedImage frame, String tc) {
        for (int y = 0; y < expected.getNy(); ++y)
            for (int x = 0; x < expected.getNx(); ++x)
                assertEquals(expected.getPixel(x, y).getRGB(), frame.getRGB(x, y),
                        tc + ": the preview differs at pixel (" + x + ", " + y + ")");
    }

    /** Test method for {@link Preview#refresh()}, {@link Preview#accept(long)} and {@link Preview#getTitle()}. */
    @Test
    void testProgress() {
        ImageWriter image = new ImageWriter("progress", 32, 32, FOLDER);
        Preview preview = new Preview(image, "progress");

        // ===== Equivalence Partitions Tests =====
        // TC01: before any tile: a black frame of the picture's size, "progress — 0 %"
        BufferedImage frame = preview.refresh();
        assertEquals(32, frame.getWidth(), "TC01: wrong frame width");
        assertEquals(32, frame.getHeight(), "TC01: wrong frame height");
        assertSamePixels(image, frame, "TC01");
        assertEquals(0, frame.getRGB(5, 5) & 0xFFFFFF, "TC01: an unrendered pixel must be black");
        assertEquals("progress \u2014 0 %", preview.getTitle(), "TC01: wrong title");
        // TC02: one 16 × 16 tile rendered red and reported (256 of 1024 pixels): the frame shows it, 25 %
        for (int y = 0; y < 16; ++y)
            for (int x = 16; x < 32; ++x)
                image.writePixel(x, y, RED);
        preview.accept(256);
        assertSame(frame, preview.refresh(), "TC02: the frame must be reused");
        assertSamePixels(image, frame, "TC02");
        assertEquals(0xFF0000, frame.getRGB(20, 3) & 0xFFFFFF, "TC02: the rendered tile must show");
        assertEquals(25, preview.getPercent(), "TC02: wrong percent");
        assertEquals("progress \u2014 25 %", preview.getTitle(), "TC02: wrong title");
        // TC03: reports from several threads arrive out of order: 768 then 512 keeps 75 %
        preview.accept(768);
        preview.accept(512);
        assertEquals(75, preview.getPercent(), "TC03: a late, smaller report must not move the progress back");

        // ===== Boundary Values Tests =====
        // TC11: all 1024 pixels reported: 100 %, "progress — done"
        preview.accept(1024);
        assertEquals(100, preview.getPercent(), "TC11: wrong percent at the end");
        assertEquals("progress \u2014 done", preview.getTitle(), "TC11: wrong title at the end");
        // TC12: 1023 of 1024 pixels: still 99 %, not done
        Preview almost = new Preview(image, "almost");
        almost.accept(1023);
        assertEquals("almost \u2014 99 %", almost.getTitle(), "TC12: one pixel short is not done");
    }

    /** Test method for {@link Preview} as a render's progress listener. */
    @Test
    void testWithRender() {
        Scene scene = new Scene("preview").setBackground(new Color(0, 0, 80));
        scene.geometries.add(new Sphere(Point3D.ZERO, 40).setEmission(new Color(200, 150, 0)));
        ImageWriter image = new ImageWriter("preview", 50, 40, FOLDER);
        Preview preview = new Preview(image, "preview");
        Render render = new Render().setImageWriter(image).setProgressListener(preview)
                .setCamera(new Camera(new Point3D(0, 0, 500), new Vector(0, 0, -1), new Vector(0, 1, 0))
                        .setVpSize(125, 100).setVpDistance(500))
                .setRayTracer(new RayTracerBasic(scene)).setMultithreading(2);

        // ===== Equivalence Partitions Tests =====
        // TC01: after the render the preview is done and shows the whole picture, sphere and background
        render.renderImage();
        assertEquals("preview \u2014 done", preview.getTitle(), "TC01: the render's progress must reach the preview");
        BufferedImage frame = preview.refresh();
        assertSamePixels(image, frame, "TC01");
        assertEquals(0xC89600, frame.getRGB(25, 20) & 0xFFFFFF, "TC01: the sphere must show in the middle");
        assertEquals(0x000050, frame.getRGB(0, 0) & 0xFFFFFF, "TC01: the background must show in the corner");
    }

    /** Test method for {@link Preview#Preview(ImageWriter, String)}: bad arguments. */
    @Test
    void testConstructor() {
        ImageWriter image = new ImageWriter("bad", 4, 4, FOLDER);
        // ===== Equivalence Partitions Tests =====
        // TC01: a null image writer or name is refused with a message naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new Preview(null, "x"), "TC01: null image"),
                "image", "TC01");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new Preview(image, null), "TC01: null name"),
                "name", "TC01");

        // ===== Boundary Values Tests =====
        // TC11: a 1 × 1 picture: 0 % before its pixel, done after it
        Preview single = new Preview(new ImageWriter("single", 1, 1, FOLDER), "single");
        assertEquals(0, single.getPercent(), "TC11: wrong percent before the pixel");
        single.accept(1);
        assertEquals("single \u2014 done", single.getTitle(), "TC11: wrong title after the pixel");
    }
}
