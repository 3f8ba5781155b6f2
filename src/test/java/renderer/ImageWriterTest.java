package renderer;

import static org.junit.jupiter.api.Assertions.*;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertPrintable;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

import primitives.Color;

/**
 * Unit tests for {@link renderer.ImageWriter}. Files are written only under {@code target/test-images}.
 */
class ImageWriterTest {
    /** The folder test pictures go to (never the checked-in images/). */
    private static final Path TEST_FOLDER = Path.of("target", "test-images");

    /** Asserts an AWT colour's exact components. */
    private static void assertRgb(int r, int g, int b, java.awt.Color c, String message) {
        assertEquals(r, c.getRed(), message + " (red)");
        assertEquals(g, c.getGreen(), message + " (green)");
        assertEquals(b, c.getBlue(), message + " (blue)");
    }

    /** @return a folder name under target/test-images that no other run uses */
    private static Path uniqueFolder(String prefix) {
        return TEST_FOLDER.resolve(prefix + "-" + ProcessHandle.current().pid() + "-" + System.nanoTime());
    }

    /** Deletes the given paths when they exist, in order (files first, then their folders). */
    private static void deleteAll(Path... paths) throws IOException {
        for (Path p : paths)
            Files.deleteIfExists(p);
    }

    /** Test method for {@link renderer.ImageWriter#ImageWriter(String, int, int)} and the size getters. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: an 800×500 image reports nX 800, nY 500
        ImageWriter writer = new ImageWriter("size", 800, 500);
        assertEquals(800, writer.getNx(), "TC01: wrong nX");
        assertEquals(500, writer.getNy(), "TC01: wrong nY");
        // TC02: a new image is black: pixel (0, 0) and (799, 499) are (0, 0, 0)
        assertRgb(0, 0, 0, writer.getPixel(0, 0), "TC02: new image must be black");
        assertRgb(0, 0, 0, writer.getPixel(799, 499), "TC02: new image must be black");
        // TC03: negative sizes are rejected, the message names the "image size"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new ImageWriter("bad", -5, 10), "TC03: negative nX must be rejected");
        assertMessage(e, "image size", "TC03");
        e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter("bad", 10, -5),
                "TC03: negative nY must be rejected");
        assertMessage(e, "image size", "TC03");
        // TC04: a null or blank name is rejected, the message names the "image name"
        e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter(null, 10, 10),
                "TC04: null name must be rejected");
        assertMessage(e, "image name", "TC04");
        e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter("  ", 10, 10),
                "TC04: blank name must be rejected");
        assertMessage(e, "image name", "TC04");
        // TC05: a null folder is rejected, the message names the "folder"
        e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter("bad", 10, 10, null),
                "TC05: null folder must be rejected");
        assertMessage(e, "folder", "TC05");
        // TC06: a name no path can hold (NUL): refused, naming it printably and why
        e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter("a\0b", 2, 2, TEST_FOLDER),
                "TC06: a NUL in the name must be rejected");
        assertPrintable(e.getMessage(), "the file name 'a\\x00b.png' cannot be a path", "TC06");

        // ===== Boundary Values Tests =====
        // TC10: size 0 is rejected, the message names the "image size"
        e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter("bad", 0, 10),
                "TC10: nX 0 must be rejected");
        assertMessage(e, "image size", "TC10");
        e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter("bad", 10, 0),
                "TC10: nY 0 must be rejected");
        assertMessage(e, "image size", "TC10");
        // TC11: a 1×1 image is accepted: nX 1, nY 1
        ImageWriter tiny = new ImageWriter("tiny", 1, 1);
        assertEquals(1, tiny.getNx(), "TC11: wrong nX");
        assertEquals(1, tiny.getNy(), "TC11: wrong nY");
        // TC12: sizes whose pixel count an image cannot hold are rejected before any memory is taken:
        // 100000×100000 and Integer.MAX_VALUE×2, the message names the largest pixel count
        for (int[] size : new int[][] { { 100_000, 100_000 }, { Integer.MAX_VALUE, 2 } }) {
            e = assertThrows(IllegalArgumentException.class, () -> new ImageWriter("huge", size[0], size[1]),
                    "TC12: " + size[0] + "x" + size[1] + " must be rejected");
            assertMessage(e, "at most " + ImageWriter.MAX_PIXELS + " pixels", "TC12");
        }
    }

    /** Test method for {@link renderer.ImageWriter#getPath()}. */
    @Test
    void testGetPath() {
        // ===== Equivalence Partitions Tests =====
        // TC01: by default the file is images/<name>.png
        assertEquals(Path.of("images", "sphere.png"), new ImageWriter("sphere", 10, 10).getPath(),
                "TC01: wrong default path");
        // TC02: with a folder the file is <folder>/<name>.png
        Path folder = TEST_FOLDER.resolve("nested").resolve("deeper");
        assertEquals(folder.resolve("scene A.png"), new ImageWriter("scene A", 10, 10, folder).getPath(),
                "TC02: wrong path in a given folder");
        // TC03: a name with ".." above the folder is refused, naming it and the folder: nothing is written outside
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new ImageWriter("../escaped", 10, 10, folder), "TC03: ../escaped must be refused");
        assertMessage(e, "image name '../escaped' leads out of its folder " + folder, "TC03");
        // TC04: an absolute name is refused, in the default folder too
        assertMessage(assertThrows(IllegalArgumentException.class, () -> new ImageWriter("/tmp/escaped", 10, 10),
                "TC04: /tmp/escaped must be refused"), "leads out of its folder images", "TC04");
        // TC05 (own): a name leading into a folder inside is kept: <folder>/sub/picture.png
        assertEquals(folder.resolve("sub").resolve("picture.png"), new ImageWriter("sub/picture", 10, 10, folder)
                .getPath(), "TC05: a folder inside must be allowed");

        // ===== Boundary Values Tests =====
        // TC11: ".." that climbs back into the folder stays inside: <folder>/sub/../picture.png
        assertEquals(folder.resolve("sub/../picture.png"), new ImageWriter("sub/../picture", 10, 10, folder).getPath(),
                "TC11: a name that stays inside must be kept");
        // TC12: one level too far, sub/../../picture, is refused
        assertThrows(IllegalArgumentException.class, () -> new ImageWriter("sub/../../picture", 10, 10, folder),
                "TC12: sub/../../picture must be refused");
        // TC13: the name ".." alone is the file "...png" in the folder, not its parent
        assertEquals(folder.resolve("...png"), new ImageWriter("..", 10, 10, folder).getPath(),
                "TC13: '..' must be the file ...png");
        // TC14 (own): the current folder, given as "", holds a plain name but not "../x"
        assertEquals(Path.of("x.png"), new ImageWriter("x", 1, 1, Path.of("")).getPath(), "TC14: wrong path in ''");
        assertThrows(IllegalArgumentException.class, () -> new ImageWriter("../x", 1, 1, Path.of("")),
                "TC14: ../x must be refused in ''");
    }

    /** Test method for {@link renderer.ImageWriter#writePixel(int, int, primitives.Color)} and {@link renderer.ImageWriter#getPixel(int, int)}. */
    @Test
    void testWritePixel() {
        ImageWriter writer = new ImageWriter("pixels", 4, 3);
        // ===== Equivalence Partitions Tests =====
        // TC01: an in-range colour reads back as written, components truncated: (10.9, 20.2, 254.99) -> (10, 20, 254)
        writer.writePixel(1, 2, new Color(10.9, 20.2, 254.99));
        assertRgb(10, 20, 254, writer.getPixel(1, 2), "TC01: wrong pixel read back");
        // TC02: components above 255 are clamped: (300, 1000, 40) -> (255, 255, 40)
        writer.writePixel(2, 1, new Color(300, 1000, 40));
        assertRgb(255, 255, 40, writer.getPixel(2, 1), "TC02: colour must be clamped at 255");
        // TC03: writing one pixel leaves its neighbours black (0, 0, 0)
        assertRgb(0, 0, 0, writer.getPixel(2, 2), "TC03: neighbour pixel changed");
        assertRgb(0, 0, 0, writer.getPixel(1, 1), "TC03: neighbour pixel changed");
        // TC04: writing again overwrites: (1, 2, 3)
        writer.writePixel(1, 2, new Color(1, 2, 3));
        assertRgb(1, 2, 3, writer.getPixel(1, 2), "TC04: pixel must be overwritten");
        // TC05: pixels out of the 4×3 image are rejected, the message says "outside"
        for (int[] xy : new int[][] { { -1, 0 }, { 0, -1 }, { 4, 0 }, { 0, 3 }, { 100, 100 } }) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> writer.writePixel(xy[0], xy[1], new Color(1, 1, 1)),
                    "TC05: pixel (" + xy[0] + ", " + xy[1] + ") must be rejected");
            assertMessage(e, "outside", "TC05");
            e = assertThrows(IllegalArgumentException.class, () -> writer.getPixel(xy[0], xy[1]),
                    "TC05: reading pixel (" + xy[0] + ", " + xy[1] + ") must be rejected");
            assertMessage(e, "outside", "TC05");
        }
        // TC06: a null colour is rejected, the message names the "colour"
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> writer.writePixel(0, 0, null), "TC06: null colour must be rejected");
        assertMessage(e, "colour", "TC06");

        // ===== Boundary Values Tests =====
        // TC10: the corners (0, 0) and (3, 2) are writable: (7, 8, 9) and (255, 0, 128)
        writer.writePixel(0, 0, new Color(7, 8, 9));
        writer.writePixel(3, 2, new Color(255, 0, 128));
        assertRgb(7, 8, 9, writer.getPixel(0, 0), "TC10: wrong corner pixel");
        assertRgb(255, 0, 128, writer.getPixel(3, 2), "TC10: wrong corner pixel");
        // TC11: exactly 255 and just above (255.999) give 255; just below 1 (0.999) gives 0
        writer.writePixel(3, 0, new Color(255, 255.999, 0.999));
        assertRgb(255, 255, 0, writer.getPixel(3, 0), "TC11: wrong truncation at the limits");
        // TC12: black (0, 0, 0) is written as black
        writer.writePixel(0, 2, Color.BLACK);
        assertRgb(0, 0, 0, writer.getPixel(0, 2), "TC12: black must stay black");
    }

    /** Test method for {@link renderer.ImageWriter#writeToImage()}. */
    @Test
    void testWriteToImage() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: a 16×9 image is written into a missing nested folder, which is created; the file is a PNG
        // that ImageIO reads back with size 16×9 and exactly the same pixels
        Path nested = uniqueFolder("nested");
        Path folder = nested.resolve("deeper");
        assertFalse(Files.exists(nested), "TC01: the folder must not exist before the test");
        ImageWriter writer = new ImageWriter("random", 16, 9, folder);
        Random random = new Random(42);
        for (int y = 0; y < 9; ++y)
            for (int x = 0; x < 16; ++x)
                writer.writePixel(x, y,
                        new Color(random.nextDouble() * 300, random.nextDouble() * 300, random.nextDouble() * 300));
        Path file = folder.resolve("random.png");
        try {
            writer.writeToImage();
            assertTrue(Files.isDirectory(folder), "TC01: the missing nested folder must be created");
            assertTrue(Files.isRegularFile(file), "TC01: the file must be written");
            assertEquals(file, writer.getPath(), "TC01: getPath must name the written file");
            byte[] bytes = Files.readAllBytes(file);
            byte[] signature = { (byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n' };
            assertTrue(bytes.length > signature.length, "TC01: the file is too short to be a PNG");
            for (int i = 0; i < signature.length; ++i)
                assertEquals(signature[i], bytes[i], "TC01: the file is not a PNG (byte " + i + ")");
            BufferedImage read = ImageIO.read(file.toFile());
            assertNotNull(read, "TC01: ImageIO cannot read the file");
            assertEquals(16, read.getWidth(), "TC01: wrong width read back");
            assertEquals(9, read.getHeight(), "TC01: wrong height read back");
            for (int y = 0; y < 9; ++y)
                for (int x = 0; x < 16; ++x)
                    assertEquals(writer.getPixel(x, y).getRGB() & 0xFFFFFF, read.getRGB(x, y) & 0xFFFFFF,
                            "TC01: wrong pixel (" + x + ", " + y + ") read back");

            // ===== Boundary Values Tests =====
            // TC10: the folder now exists and the file is overwritten: pixel (0, 0) reads back (1, 2, 3)
            writer.writePixel(0, 0, new Color(1, 2, 3));
            writer.writeToImage();
            BufferedImage again = ImageIO.read(file.toFile());
            assertRgb(1, 2, 3, new java.awt.Color(again.getRGB(0, 0)), "TC10: the file must be overwritten");
        } finally {
            deleteAll(file, folder, nested);
        }
    }

    /**
     * Test method for {@link ImageWriter#forFile(Path, int, int)} and {@link ImageWriter#formatOf(Path)}:
     * the file's extension chooses the format.
     */
    @Test
    void testForFile() throws IOException {
        Path folder = TEST_FOLDER.resolve("formats");
        // ===== Equivalence Partitions Tests =====
        // TC01: the extensions and their formats: .png png, .jpg and .jpeg jpeg, .bmp bmp
        assertEquals("png", ImageWriter.formatOf(Path.of("a.png")), "TC01: wrong format of .png");
        assertEquals("jpeg", ImageWriter.formatOf(Path.of("a.jpg")), "TC01: wrong format of .jpg");
        assertEquals("jpeg", ImageWriter.formatOf(Path.of("a.jpeg")), "TC01: wrong format of .jpeg");
        assertEquals("bmp", ImageWriter.formatOf(Path.of("a.bmp")), "TC01: wrong format of .bmp");
        // TC02: a 6 × 4 BMP with a red pixel is written to exactly that file and read back so
        Path bmp = folder.resolve("red.bmp");
        Files.deleteIfExists(bmp);
        ImageWriter writer = ImageWriter.forFile(bmp, 6, 4);
        assertEquals(bmp, writer.getPath(), "TC02: wrong file");
        writer.writePixel(2, 1, new Color(255, 0, 0));
        writer.writeToImage();
        BufferedImage image = ImageIO.read(bmp.toFile());
        assertEquals(6, image.getWidth(), "TC02: wrong width");
        assertEquals(0xFF0000, image.getRGB(2, 1) & 0xFFFFFF, "TC02: wrong pixel in the BMP");
        // TC03: another extension (.gif, .txt) is refused, listing the ones written here
        for (String name : new String[] { "a.gif", "a.txt" })
            assertMessage(assertThrows(IllegalArgumentException.class, () -> ImageWriter.forFile(Path.of(name), 2, 2),
                    "TC03: " + name + " must be refused"), "must end with one of .bmp, .jpeg, .jpg, .png", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: upper case extensions count (.JPG is jpeg)
        assertEquals("jpeg", ImageWriter.formatOf(Path.of("A.JPG")), "TC11: .JPG must be jpeg");
        // TC12: no extension, the extension alone, or a null file are refused
        for (String name : new String[] { "png", ".png", "a." })
            assertThrows(IllegalArgumentException.class, () -> ImageWriter.formatOf(Path.of(name)),
                    "TC12: " + name + " must be refused");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> ImageWriter.formatOf(null),
                "TC12: a null file must be refused"), "image file", "TC12");
        // TC13: a file name holding ESC [ 2 J, of an unknown format: named printably, "a\x1B[2J.gif"
        assertPrintable(assertThrows(IllegalArgumentException.class,
                () -> ImageWriter.formatOf(Path.of("a\u001b[2J.gif")), "TC13: .gif must be refused").getMessage(),
                "a\\x1B[2J.gif must end with", "TC13");
    }

    /** Test method for {@link ImageWriter#copyTo(BufferedImage)}. */
    @Test
    void testCopyTo() {
        ImageWriter writer = new ImageWriter("copy", 3, 2, TEST_FOLDER);
        writer.writePixel(1, 1, new Color(0, 0, 255));
        // ===== Equivalence Partitions Tests =====
        // TC01: a 3 × 2 copy holds every pixel, the blue one included
        BufferedImage copy = new BufferedImage(3, 2, BufferedImage.TYPE_INT_RGB);
        writer.copyTo(copy);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x)
                assertEquals(writer.getPixel(x, y).getRGB(), copy.getRGB(x, y), "TC01: pixel (" + x + ", " + y + ")");
        assertEquals(0x0000FF, copy.getRGB(1, 1) & 0xFFFFFF, "TC01: the blue pixel is not copied");

        // ===== Boundary Values Tests =====
        // TC11: a target of another size (3 × 3) or null is refused
        assertMessage(assertThrows(IllegalArgumentException.class,
                () -> writer.copyTo(new BufferedImage(3, 3, BufferedImage.TYPE_INT_RGB)), "TC11: wrong size accepted"),
                "3x3", "TC11");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> writer.copyTo(null),
                "TC11: null accepted"), "target image", "TC11");
    }

    /** Test method for {@link renderer.ImageWriter#writeToImage()} when the folder cannot be created. */
    @Test
    void testWriteToImageFailure() throws IOException {
        // ===== Equivalence Partitions Tests =====
        // TC01: the folder's parent is a regular file: an UncheckedIOException naming the image path
        Files.createDirectories(TEST_FOLDER);
        Path blocker = uniqueFolder("blocker");
        Files.writeString(blocker, "not a folder");
        try {
            ImageWriter writer = new ImageWriter("blocked", 2, 2, blocker.resolve("sub"));
            UncheckedIOException e = assertThrows(UncheckedIOException.class, writer::writeToImage,
                    "TC01: an unwritable folder must fail");
            assertMessage(e, "cannot write image", "TC01");
            assertMessage(e, "blocked.png", "TC01");
            // TC02: a name holding BEL, below the same file: the message names it printably, "bell\x07.png"
            e = assertThrows(UncheckedIOException.class,
                    () -> new ImageWriter("bell\u0007", 2, 2, blocker.resolve("sub")).writeToImage(),
                    "TC02: an unwritable folder must fail");
            assertPrintable(e.getMessage(), "bell\\x07.png: cannot write image", "TC02");
        } finally {
            deleteAll(blocker);
        }
    }

    /** Test method for {@link renderer.ImageWriter#writeToImage()}: the file is replaced in one step. */
    @Test
    void testWriteToImageAtomic() throws IOException {
        Path folder = uniqueFolder("atomic");
        ImageWriter writer = new ImageWriter("picture", 3, 2, folder);
        Path file = writer.getPath();
        try {
            // ===== Equivalence Partitions Tests =====
            // TC01: an old file is replaced by the complete new PNG, and no temporary file is left behind
            Files.createDirectories(folder);
            Files.writeString(file, "the old picture");
            writer.writeToImage();
            assertEquals(3, ImageIO.read(file.toFile()).getWidth(), "TC01: the new picture must replace the old one");
            try (var files = Files.list(folder)) {
                assertEquals(1, files.count(), "TC01: a temporary file was left in the folder");
            }

            // ===== Boundary Values Tests =====
            // TC11: an empty folder with the image's name is not replaced: the write fails, the folder stays
            Files.delete(file);
            Files.createDirectory(file);
            UncheckedIOException e = assertThrows(UncheckedIOException.class, writer::writeToImage,
                    "TC11: writing onto a folder must fail");
            assertMessage(e, "is a folder", "TC11");
            assertTrue(Files.isDirectory(file), "TC11: the folder must stay");
        } finally {
            deleteAll(file, folder);
        }
    }

    /** Test method for {@link renderer.ImageWriter#checkOutput()}: the path is checked before rendering. */
    @Test
    void testCheckOutput() throws IOException {
        Path folder = uniqueFolder("check");
        Path blocker = folder.resolve("file");
        ImageWriter writer = new ImageWriter("picture", 2, 2, folder.resolve("sub"));
        try {
            // ===== Equivalence Partitions Tests =====
            // TC01: a missing folder is created, and nothing is left in it
            writer.checkOutput();
            try (var files = Files.list(folder.resolve("sub"))) {
                assertEquals(0, files.count(), "TC01: the check must leave the folder empty");
            }
            // TC02: an existing folder named like the image: rejected, naming the folder
            Files.createDirectory(writer.getPath());
            UncheckedIOException e = assertThrows(UncheckedIOException.class, writer::checkOutput,
                    "TC02: an image path that is a folder must be rejected");
            assertMessage(e, "is a folder", "TC02");
            Files.delete(writer.getPath());
            // TC03: the check of a path alone, before any image: its missing folder is created, left empty
            ImageWriter.checkOutput(folder.resolve("other").resolve("x.png"));
            try (var files = Files.list(folder.resolve("other"))) {
                assertEquals(0, files.count(), "TC03: the check must leave the folder empty");
            }
            Files.delete(folder.resolve("other"));
            // TC04: a folder whose parent is a file: rejected, naming the image
            Files.writeString(blocker, "not a folder");
            e = assertThrows(UncheckedIOException.class,
                    () -> new ImageWriter("picture", 2, 2, blocker.resolve("sub")).checkOutput(),
                    "TC04: a folder below a file must be rejected");
            assertMessage(e, blocker.resolve("sub").resolve("picture.png") + ": cannot write image", "TC04");
            // TC05: a null path is refused as such, not with a NullPointerException
            assertMessage(assertThrows(IllegalArgumentException.class, () -> ImageWriter.checkOutput(null),
                    "TC05: a null path must be refused"), "image file must not be null", "TC05");
        } finally {
            deleteAll(blocker, folder.resolve("sub"), folder);
        }
    }
}
