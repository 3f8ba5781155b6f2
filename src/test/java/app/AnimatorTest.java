package app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestCommands.run;
import static testutil.TestImages.samePixels;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import testutil.TestAnimations;
import testutil.TestCommands.Result;
import testutil.TestImages;
import testutil.TestImages.GifFrame;

/**
 * Tests for {@link Animator}, through the command line: the frames of a spinning sphere, the GIF made of
 * them, and the GIF assembled from runs of parts of the frames. The pictures are 24 × 24 pixels and go to
 * {@code target/test-animation/}.
 */
class AnimatorTest {
    private static final Path FOLDER = Path.of("target", "test-animation");
    private static Path scene;

    /** Writes the spinning scene. */
    @BeforeAll
    static void writeScene() {
        scene = TestAnimations.spinning(FOLDER, "spin.xml", "");
    }

    /** An empty folder for a test's pictures. */
    private static Path folder(String name) throws IOException {
        Path folder = FOLDER.resolve(name);
        Files.createDirectories(folder);
        try (var files = Files.list(folder)) {
            for (Path file : files.toList())
                Files.delete(file);
        }
        return folder;
    }

    /** Runs the command, checking that it succeeds. */
    private static Result succeed(String tc, String... args) {
        Result result = run(args);
        assertEquals(0, result.code(), tc + ": the run failed: " + result.err());
        return result;
    }

    private static BufferedImage image(Path file) throws IOException {
        return ImageIO.read(file.toFile());
    }

    /** Test method for {@link Animator#render(boolean, boolean, int)}. */
    @Test
    void testRender() throws IOException {
        Path folder = folder("render");
        Path gif = folder.resolve("spin.gif");
        // ===== Equivalence Partitions Tests =====
        // TC01: 4 frames into spin.gif: spin-0001.png … spin-0004.png are kept, the sphere right of centre at
        // time 0, left of it at 0.5 (frame 3), and the report names the frames and the GIF
        Result result = succeed("TC01", scene.toString(), "--frames", "4", "-o", gif.toString(), "--fps", "10");
        int x = TestAnimations.SPHERE_AT_START[0];
        int y = TestAnimations.SPHERE_AT_START[1];
        BufferedImage first = image(folder.resolve("spin-0001.png"));
        BufferedImage third = image(folder.resolve("spin-0003.png"));
        assertTrue(TestAnimations.isSphere(first.getRGB(x, y)), "TC01: frame 1 must show the sphere right of centre");
        assertFalse(TestAnimations.isSphere(first.getRGB(23 - x, y)), "TC01: frame 1 must not show it left of centre");
        assertTrue(TestAnimations.isSphere(third.getRGB(23 - x, y)), "TC01: frame 3 must show it left of centre");
        assertFalse(TestAnimations.isSphere(third.getRGB(x, y)), "TC01: frame 3 must not show it right of centre");
        assertTrue(result.out().contains("Frames:       1-4 of 4: spin-0001.png ... spin-0004.png"),
                "TC01: wrong report: " + result.out());
        assertTrue(result.out().contains("4 frames, 10 fps (10/100 s a frame)"), "TC01: wrong report: " + result.out());
        // TC02: the GIF: 4 frames of 24 × 24 that ImageIO reads back, a delay of 10 (--fps 10), looping; the
        // sphere where the frames have it
        List<GifFrame> frames = TestImages.gifFrames(gif);
        assertEquals(4, frames.size(), "TC02: wrong number of GIF frames");
        for (GifFrame frame : frames) {
            assertEquals(24, frame.image().getWidth(), "TC02: wrong width");
            assertEquals(24, frame.image().getHeight(), "TC02: wrong height");
            assertEquals(10, frame.delay(), "TC02: wrong delay");
        }
        assertTrue(frames.get(0).loops(), "TC02: the GIF must loop");
        assertTrue(TestAnimations.isSphere(frames.get(0).image().getRGB(x, y)), "TC02: GIF frame 1 lost the sphere");
        assertTrue(TestAnimations.isSphere(frames.get(2).image().getRGB(23 - x, y)), "TC02: GIF frame 3 lost the sphere");
        // TC03: the same run again: every frame the same bytes
        byte[] frame2 = Files.readAllBytes(folder.resolve("spin-0002.png"));
        succeed("TC03", scene.toString(), "--frames", "4", "-o", gif.toString(), "--fps", "10", "-q");
        assertArrayEquals(frame2, Files.readAllBytes(folder.resolve("spin-0002.png")), "TC03: frames must not change");
        // TC04: -o NAME.png: the frames only, in PNG
        Path pngFolder = folder("png");
        succeed("TC04", scene.toString(), "--frames", "2", "-o", pngFolder.resolve("still.png").toString(), "-q");
        try (var files = Files.list(pngFolder)) {
            assertEquals(List.of("still-0001.png", "still-0002.png"),
                    files.map(f -> f.getFileName().toString()).sorted().toList(), "TC04: wrong files");
        }

        // ===== Boundary Values Tests =====
        // TC11: one frame: its picture, at time 0, and a GIF of one frame
        Path one = folder("one").resolve("one.gif");
        succeed("TC11", scene.toString(), "--frames", "1", "-o", one.toString(), "-q");
        assertTrue(samePixels(first, image(one.resolveSibling("one-0001.png"))), "TC11: frame 1 is the picture at 0");
        assertEquals(1, TestImages.gifFrames(one).size(), "TC11: a GIF of one frame");
        // TC12: a range of the frames: only those, and no GIF
        Path range = folder("range").resolve("part.gif");
        succeed("TC12", scene.toString(), "--frames", "4", "--frame-range", "2-3", "-o", range.toString(), "-q");
        try (var files = Files.list(range.getParent())) {
            assertEquals(List.of("part-0002.png", "part-0003.png"),
                    files.map(f -> f.getFileName().toString()).sorted().toList(), "TC12: wrong files");
        }
    }

    /** Test method for {@link Animator#assemble(boolean)}. */
    @Test
    void testAssemble() throws IOException {
        Path whole = folder("whole").resolve("spin.gif");
        Path parts = folder("parts").resolve("spin.gif");
        succeed("TC01", scene.toString(), "--frames", "4", "-o", whole.toString(), "-q");
        // ===== Equivalence Partitions Tests =====
        // TC01: frames 1-2 and 3-4 in two runs, then --assemble (no scene file): the same frames and the same
        // GIF, byte for byte, as one run of the 4 frames
        succeed("TC01", scene.toString(), "--frames", "4", "--frame-range", "1-2", "-o", parts.toString(), "-q");
        succeed("TC01", scene.toString(), "--frames", "4", "--frame-range", "3-4", "-o", parts.toString(), "-q");
        assertFalse(Files.exists(parts), "TC01: a range must not write the GIF");
        Result result = succeed("TC01", "--assemble", "--frames", "4", "-o", parts.toString());
        for (int k = 1; k <= 4; ++k) {
            String name = "spin-000" + k + ".png";
            assertArrayEquals(Files.readAllBytes(whole.resolveSibling(name)), Files.readAllBytes(parts.resolveSibling(name)),
                    "TC01: frame " + k + " differs between the runs");
        }
        assertArrayEquals(Files.readAllBytes(whole), Files.readAllBytes(parts), "TC01: the assembled GIF differs");
        assertTrue(result.out().contains("4 frames, 24 fps (4/100 s a frame)"), "TC01: wrong report: " + result.out());

        // ===== Boundary Values Tests =====
        // TC11: a frame missing: exit code 2, one line naming it and the run that makes it
        Files.delete(parts.resolveSibling("spin-0003.png"));
        result = run("--assemble", "--frames", "4", "-o", parts.toString());
        assertEquals(2, result.code(), "TC11: a missing frame must fail");
        assertEquals(List.of(parts.resolveSibling("spin-0003.png") + ": frame 3 of 4 is missing: render it"
                + " (--frame-range 3-3) before --assemble"), result.errLines(), "TC11: wrong message");
    }
}
