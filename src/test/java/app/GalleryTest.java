package app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestImages.differentPixels;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

import renderer.ImageWriter;
import renderer.Render;
import scenefile.Picture;
import scenefile.SceneLoader;

/**
 * Tests for {@link Gallery}: every picture renders (into {@code target/}, never {@code images/}), and the
 * report's scene A matches the report's own picture.
 */
class GalleryTest {
    private static final Path FOLDER = Path.of("target", "test-images", "gallery");

    private static BufferedImage reportImage(String name) throws IOException {
        try (InputStream in = GalleryTest.class.getResourceAsStream("/report/" + name)) {
            assertNotNull(in, "missing test resource " + name);
            return ImageIO.read(in);
        }
    }

    /** The largest difference of one channel between two colours. */
    private static int channelDifference(int rgb1, int rgb2) {
        int max = 0;
        for (int shift = 0; shift < 24; shift += 8)
            max = Math.max(max, Math.abs(((rgb1 >> shift) & 0xFF) - ((rgb2 >> shift) & 0xFF)));
        return max;
    }

    /** The picture of the gallery with this name. */
    private static Picture picture(String name) {
        return Gallery.pictures().stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow();
    }

    /** The mean of each channel over the (2r + 1)² pixels around (x, y), packed as three doubles. */
    private static double[] boxMean(BufferedImage image, int x, int y, int r) {
        double[] mean = new double[3];
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
                int rgb = image.getRGB(x + dx, y + dy);
                for (int c = 0; c < 3; ++c)
                    mean[c] += ((rgb >> (8 * c)) & 0xFF) / (double) ((2 * r + 1) * (2 * r + 1));
            }
        return mean;
    }

    /** Test method for {@link Gallery#pictures()} and {@link Gallery#render(Picture, Path)}. */
    @Test
    void testEveryPictureRenders() {
        List<Picture> pictures = Gallery.pictures();
        // ===== Equivalence Partitions Tests =====
        // TC01: 24 pictures, each written as a PNG that shows more than one colour
        assertEquals(24, pictures.size(), "TC01: wrong number of gallery pictures");
        for (Picture picture : pictures) {
            ImageWriter image = Gallery.render(picture, FOLDER).getImageWriter();
            assertTrue(Files.exists(FOLDER.resolve(picture.name() + ".png")), "TC01: " + picture.name() + " not written");
            Set<java.awt.Color> colours = new HashSet<>();
            for (int y = 0; y < picture.nY(); y += 7)
                for (int x = 0; x < picture.nX(); x += 7)
                    colours.add(image.getPixel(x, y));
            assertTrue(colours.size() > 1, "TC01: " + picture.name() + " is a single flat colour");
        }
    }

    /**
     * Test method for {@link Gallery#render(Picture, Path, int)}: a picture rendered on any number of
     * threads has the same pixels, written into the folder given.
     */
    @Test
    void testRenderOnThreads() {
        Picture picture = picture("softSphereOnTriangles").withSize(60, 60);
        ImageWriter allCores = Gallery.render(picture, FOLDER.resolve("cores")).getImageWriter();
        // ===== Equivalence Partitions Tests =====
        // TC01: 3 threads: the pixels of one per core, in the folder given
        ImageWriter three = Gallery.render(picture, FOLDER.resolve("three"), 3).getImageWriter();
        assertEquals(FOLDER.resolve("three").resolve("softSphereOnTriangles.png"), three.getPath(),
                "TC01: wrong file");
        assertEquals(0, differentPixels(allCores, three), "TC01: 3 threads changed the picture");
        // ===== Boundary Values Tests =====
        // TC11: 1 thread, and 0 (one per core): the same pixels
        assertEquals(0, differentPixels(allCores, Gallery.render(picture, FOLDER.resolve("one"), 1).getImageWriter()),
                "TC11: 1 thread changed the picture");
        assertEquals(0, differentPixels(allCores, Gallery.render(picture, FOLDER.resolve("zero"), 0).getImageWriter()),
                "TC11: 0 threads (one per core) changed the picture");
    }

    /**
     * Test method for {@link Gallery#render(Picture, Path)}: the report's scene A with hard shadows is
     * the report's picture, level for level, except along the seam the report's open triangles leave.
     */
    @Test
    void testSceneAMatchesReport() throws IOException {
        Render render = Gallery.render(picture("sphereOnTriangles"), FOLDER);
        BufferedImage report = reportImage("A-sphere-on-triangles-hard.png");

        // ===== Equivalence Partitions Tests =====
        // TC01: off the seam (the diagonal x + y = 599), every pixel is within 2 levels of the report's,
        // except the odd ray through the floor's outer edge, which the report's open triangles miss
        int seamPixels = 0;
        int outerEdgePixels = 0;
        for (int y = 0; y < 600; ++y)
            for (int x = 0; x < 600; ++x) {
                int rgb = render.getImageWriter().getPixel(x, y).getRGB();
                int difference = channelDifference(rgb, report.getRGB(x, y));
                if (difference <= 2)
                    continue;
                if (Math.abs(x + y - 599) <= 1)
                    ++seamPixels;
                else {
                    assertEquals(0, report.getRGB(x, y) & 0xFFFFFF,
                            "TC01: pixel (" + x + ", " + y + ") differs by " + difference + " off the floor's edges");
                    ++outerEdgePixels;
                }
            }
        assertTrue(outerEdgePixels <= 5, "TC01: too many edge pixels differ: " + outerEdgePixels);
        // ===== Boundary Values Tests =====
        // TC11: on the seam the report shows its dark line and we do not (the floor is closed there)
        assertTrue(seamPixels > 300, "TC11: the report's seam line should differ from our seamless floor");
    }

    /**
     * Test method for {@link Gallery#render(Picture, Path)}: the report's scene A with soft shadows is
     * the report's soft picture up to noise: averaged over 5 × 5 pixels, within 4 levels everywhere
     * off the report's seam.
     */
    @Test
    void testSoftSceneAMatchesReport() throws IOException {
        BufferedImage ours = ImageIO.read(Gallery.render(picture("softSphereOnTriangles"), FOLDER)
                .getImageWriter().getPath().toFile());
        BufferedImage report = reportImage("A-sphere-on-triangles-soft.png");
        int radius = 2;
        double worst = 0;
        int penumbraPixels = 0;
        for (int y = radius; y < 600 - radius; ++y)
            for (int x = radius; x < 600 - radius; ++x) {
                if (Math.abs(x + y - 599) <= radius + 4)
                    continue;
                double[] a = boxMean(ours, x, y, radius);
                double[] b = boxMean(report, x, y, radius);
                for (int c = 0; c < 3; ++c)
                    worst = Math.max(worst, Math.abs(a[c] - b[c]));
                if ((ours.getRGB(x, y) & 0xFFFFFF) != (report.getRGB(x, y) & 0xFFFFFF))
                    ++penumbraPixels;
            }
        // ===== Equivalence Partitions Tests =====
        // TC01: off the seam, the 5 × 5 means agree within 4 levels (the pictures differ only by noise)
        assertTrue(worst <= 4, "TC01: the soft picture departs from the report's by " + worst + " levels");
        // ===== Boundary Values Tests =====
        // TC11: the two renders are not the same noise: many single pixels differ
        assertTrue(penumbraPixels > 1000, "TC11: expected the report's and our noise to differ, " + penumbraPixels);
    }

    /**
     * Test method for {@link Gallery#pictures()} and {@link SceneLoader#load(Path)}: every picture of the
     * gallery has its scene file {@code scenes/<name>.xml}, which loads into the same picture (name, size,
     * grid, settings) and renders, at a quarter of the size, exactly the pixels of the Java picture.
     */
    @Test
    void testSceneFilesMatchPictures() throws IOException {
        Path quarterFolder = Path.of("target", "test-images", "gallery-files");
        // ===== Equivalence Partitions Tests =====
        // TC01: for each of the 24 pictures, the scene file exists and loads into the same picture
        for (Picture picture : Gallery.pictures()) {
            Path file = Path.of("scenes", picture.name() + ".xml");
            assertTrue(Files.isRegularFile(file), "TC01: missing scene file " + file);
            Picture loaded = SceneLoader.load(file);
            assertEquals(picture.name(), loaded.name(), "TC01: wrong name in " + file);
            assertEquals(picture.nX(), loaded.nX(), "TC01: wrong width in " + file);
            assertEquals(picture.nY(), loaded.nY(), "TC01: wrong height in " + file);
            assertEquals(picture.gridInterval(), loaded.gridInterval(), "TC01: wrong grid in " + file);
            assertEquals(picture.settings(), loaded.settings(), "TC01: wrong render settings in " + file);
            // TC02: at a quarter of the size, the loaded picture renders exactly the Java picture's pixels
            int width = picture.nX() / 4;
            int height = picture.nY() / 4;
            ImageWriter java = quarter(picture, width, height, quarterFolder.resolve("java"));
            ImageWriter fromFile = quarter(loaded, width, height, quarterFolder.resolve("file"));
            int different = differentPixels(java, fromFile);
            assertEquals(0, different, "TC02: " + file + " renders " + different + " pixels unlike its Java picture");
        }

        // ===== Boundary Values Tests =====
        // TC11: the course's first picture uses the schema's default camera, so its file has no <camera>,
        // and it still loads the course's camera: at (0, 0, 0) looking to -z, 500 × 500 at distance 100
        Path twoColors = Path.of("scenes", "baseRenderTwoColors.xml");
        assertFalse(Files.readString(twoColors).contains("<camera"), "TC11: the default camera should not be written");
        renderer.Camera camera = SceneLoader.load(twoColors).camera();
        assertEquals(new primitives.Point3D(0, 0, 0), camera.getP0(), "TC11: wrong camera position");
        assertEquals(new primitives.Vector(0, 0, -1), camera.getVTo(), "TC11: wrong camera vTo");
        assertEquals(500, camera.getWidth(), 0, "TC11: wrong view plane width");
        assertEquals(100, camera.getDistance(), 0, "TC11: wrong view plane distance");
    }

    /** Renders a picture at another size into a folder. */
    private static ImageWriter quarter(Picture picture, int width, int height, Path folder) {
        return Gallery.render(picture.withSize(width, height), folder).getImageWriter();
    }
}
