package app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

import testutil.TestFiles;

/**
 * Tests for {@link Main}: it runs the render command in this process and returns its exit code (the
 * gallery's pictures are tested by {@link GalleryTest}, {@code --gallery} by {@link RenderCommandTest}).
 */
class MainTest {
    /** Where the test's scene file and picture go. */
    private static final Path FOLDER = Path.of("target", "test-cli", "main");

    /** The course's first scene file, in its original form. */
    private static final String TWO_COLORS = """
            <scene background-color="75 127 90">
              <ambient-light color="255 191 191"/>
              <geometries>
                <sphere center="0 0 -100" radius="50"/>
                <triangle p0="-100 0 -100" p1="0 100 -100" p2="-100 100 -100"/>
                <triangle p0="100 0 -100" p1="0 100 -100" p2="100 100 -100"/>
                <triangle p0="-100 0 -100" p1="0 -100 -100" p2="-100 -100 -100"/>
                <triangle p0="100 0 -100" p1="0 -100 -100" p2="100 -100 -100"/>
              </geometries>
            </scene>
            """;

    /** Test method for {@link Main#run(String[], PrintWriter, PrintWriter, boolean)}. */
    @Test
    void testRun() throws IOException {
        Path scene = TestFiles.write(FOLDER, "twoColors.xml", TWO_COLORS);
        Path png = FOLDER.resolve("twoColors.png");
        Files.deleteIfExists(png);
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();

        // ===== Equivalence Partitions Tests =====
        // TC01: a scene file: exit 0, the image written, the report on out
        int code = Main.run(new String[]{scene.toString(), "-o", png.toString(), "--width", "20"},
                new PrintWriter(out), new PrintWriter(err), false);
        assertEquals(0, code, "TC01: wrong exit code: " + err);
        assertEquals(20, ImageIO.read(png.toFile()).getHeight(), "TC01: wrong image height (the file's 500 x 500)");
        assertTrue(out.toString().contains("Primary rays: 400"), "TC01: wrong report: " + out);
        // the course's colours: the background at a corner, the ambient light on the sphere in the middle
        assertEquals(0x4B7F5A, ImageIO.read(png.toFile()).getRGB(0, 0) & 0xFFFFFF, "TC01: wrong background");
        assertEquals(0xFFBFBF, ImageIO.read(png.toFile()).getRGB(10, 10) & 0xFFFFFF, "TC01: wrong sphere colour");

        // TC02: --help: exit 0, the usage on out
        out.getBuffer().setLength(0);
        code = Main.run(new String[]{"--help"}, new PrintWriter(out), new PrintWriter(err), false);
        assertEquals(0, code, "TC02: --help should exit with 0");
        assertTrue(out.toString().startsWith("Usage: java -jar target/raytracer.jar"), "TC02: no usage: " + out);

        // TC03: a bad argument: exit 2 (and no System.exit), the message on err
        err.getBuffer().setLength(0);
        code = Main.run(new String[]{scene.toString(), "--beams", "0"}, new PrintWriter(out), new PrintWriter(err),
                false);
        assertEquals(2, code, "TC03: a bad argument should exit with 2");
        assertTrue(err.toString().startsWith("--beams must be between 1 and 1000"), "TC03: wrong message: " + err);

        // ===== Boundary Values Tests =====
        // TC11: a bad scene file: exit 2, one line
        err.getBuffer().setLength(0);
        Path missing = FOLDER.resolve("missing.xml");
        code = Main.run(new String[]{missing.toString()}, new PrintWriter(out), new PrintWriter(err), false);
        assertEquals(2, code, "TC11: a missing scene file should exit with 2");
        assertEquals(1, err.toString().lines().count(), "TC11: not one line: " + err);
        // TC12: no arguments: exit 2, the usage on err (the gallery is rendered only when asked for)
        out.getBuffer().setLength(0);
        err.getBuffer().setLength(0);
        code = Main.run(new String[0], new PrintWriter(out), new PrintWriter(err), false);
        assertEquals(2, code, "TC12: no arguments should exit with 2");
        assertTrue(err.toString().startsWith("Usage: java -jar target/raytracer.jar"), "TC12: no usage: " + err);
        assertEquals("", out.toString(), "TC12: nothing should go to the output stream");
    }

    /** Test method for {@link Main#isGallery(String[])}. */
    @Test
    void testIsGallery() {
        // ===== Equivalence Partitions Tests =====
        // TC01: --gallery, alone or with a folder, asks for the gallery
        assertTrue(Main.isGallery(new String[]{"--gallery"}), "TC01: --gallery alone");
        assertTrue(Main.isGallery(new String[]{"--threads", "2", "--gallery", "out"}), "TC01: --gallery FOLDER");
        // TC02: a scene file does not
        assertFalse(Main.isGallery(new String[]{"scenes/a.xml", "--width", "30"}), "TC02: a scene file");

        // ===== Boundary Values Tests =====
        // TC11: --gallery=FOLDER does; no arguments, and an option that starts alike, do not
        assertTrue(Main.isGallery(new String[]{"--gallery=out"}), "TC11: --gallery=FOLDER");
        assertFalse(Main.isGallery(new String[0]), "TC11: no arguments");
        assertFalse(Main.isGallery(new String[]{"--gallery-x"}), "TC11: --gallery-x is another option");
    }
}
