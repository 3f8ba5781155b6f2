package app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;

import testutil.TestFiles;
import testutil.TestImages;
import testutil.TestImages.GifFrame;

/**
 * Unit tests for {@link GifWriter}: GIFs that ImageIO reads back, with their delays and loop.
 */
class GifWriterTest {
    private static final Path FOLDER = Path.of("target", "test-gif");
    /** Three colours a GIF's palette holds exactly. */
    private static final int[] COLOURS = {0xFF0000, 0x00FF00, 0x0000FF};

    /** Writes frame k, 8 × 6 pixels of colour k. */
    private static Path frame(int k) {
        int[] pixels = new int[8 * 6];
        Arrays.fill(pixels, COLOURS[k]);
        return TestFiles.writePng(FOLDER, "frame" + k + ".png", 8, pixels);
    }

    /** Test method for {@link GifWriter#delay(int)}. */
    @Test
    void testDelay() {
        // ===== Equivalence Partitions Tests =====
        // TC01: 24 fps: 100 / 24 rounded, 4 hundredths of a second; 10 fps: 10
        assertEquals(4, GifWriter.delay(24), "TC01: 24 fps");
        assertEquals(10, GifWriter.delay(10), "TC01: 10 fps");

        // ===== Boundary Values Tests =====
        // TC11: 1 fps: 100; 100 fps: 1
        assertEquals(100, GifWriter.delay(1), "TC11: 1 fps");
        assertEquals(1, GifWriter.delay(GifWriter.MAX_FPS), "TC11: 100 fps");
        // TC12: 0 and 101 fps: refused, naming the option
        assertMessage(assertThrows(IllegalArgumentException.class, () -> GifWriter.delay(0), "TC12: 0 fps"),
                "--fps must be 1 to 100, got 0", "TC12");
        assertThrows(IllegalArgumentException.class, () -> GifWriter.delay(101), "TC12: 101 fps");
    }

    /** Test method for {@link GifWriter#write(List, Path, int)}. */
    @Test
    void testWrite() throws IOException {
        List<Path> frames = List.of(frame(0), frame(1), frame(2));
        Path gif = FOLDER.resolve("three.gif");
        // ===== Equivalence Partitions Tests =====
        // TC01: three frames at 24 fps: ImageIO reads back 3 frames of 8 × 6, each of its colour, delay 4,
        // the loop on the first
        GifWriter.write(frames, gif, 24);
        List<GifFrame> read = TestImages.gifFrames(gif);
        assertEquals(3, read.size(), "TC01: wrong number of frames");
        for (int k = 0; k < 3; ++k) {
            assertEquals(8, read.get(k).image().getWidth(), "TC01: wrong width of frame " + k);
            assertEquals(6, read.get(k).image().getHeight(), "TC01: wrong height of frame " + k);
            assertEquals(COLOURS[k], read.get(k).image().getRGB(3, 2) & 0xFFFFFF, "TC01: wrong colour of frame " + k);
            assertEquals(4, read.get(k).delay(), "TC01: wrong delay of frame " + k);
        }
        assertTrue(read.get(0).loops(), "TC01: the first frame must carry the NETSCAPE2.0 loop");
        // TC02: the same frames again: the same bytes
        byte[] first = Files.readAllBytes(gif);
        GifWriter.write(frames, gif, 24);
        assertArrayEquals(first, Files.readAllBytes(gif), "TC02: the same frames must give the same bytes");
        // TC03: a frame of another size: refused, naming it; the GIF already there is left as it was
        Path wide = TestFiles.writePng(FOLDER, "wide.png", 9, new int[9 * 6]);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> GifWriter.write(List.of(frame(0), wide), gif, 24), "TC03: two sizes");
        assertMessage(e, "wide.png: the frame is 9 x 6 pixels, the first one 8 x 6", "TC03");
        assertArrayEquals(first, Files.readAllBytes(gif), "TC03: a failed write must leave the old GIF");
        try (var files = Files.list(FOLDER)) {
            assertTrue(files.noneMatch(f -> f.toString().endsWith(".tmp")), "TC03: a temporary file was left");
        }

        // ===== Boundary Values Tests =====
        // TC11: one frame at 1 fps: one frame, delay 100
        GifWriter.write(List.of(frame(1)), gif, 1);
        read = TestImages.gifFrames(gif);
        assertEquals(1, read.size(), "TC11: one frame");
        assertEquals(100, read.get(0).delay(), "TC11: 1 fps is a delay of 100");
        // TC12: no frame, a missing frame: refused, naming the file
        assertMessage(assertThrows(IllegalArgumentException.class, () -> GifWriter.write(List.of(), gif, 24),
                "TC12: no frame"), "one frame at least", "TC12");
        assertMessage(assertThrows(UncheckedIOException.class,
                () -> GifWriter.write(List.of(FOLDER.resolve("none.png")), gif, 24), "TC12: missing frame"),
                "none.png: cannot read the frame", "TC12");
    }
}
