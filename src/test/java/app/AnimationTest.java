package app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link Animation}: the frames of a run, their times and their files.
 */
class AnimationTest {
    private static final Path GIF = Path.of("out", "spin.gif");

    /** Test method for {@link Animation#of(int, String)}. */
    @Test
    void testOf() {
        // ===== Equivalence Partitions Tests =====
        // TC01: no range: frames 1 to N, all of them (4)
        Animation all = Animation.of(4, null);
        assertEquals(new Animation(4, 1, 4), all, "TC01: wrong frames");
        assertEquals(4, all.count(), "TC01: wrong count");
        assertTrue(all.whole(), "TC01: every frame");
        // TC02: a range inside: 2-3, 2 frames, not all
        Animation part = Animation.of(4, "2-3");
        assertEquals(new Animation(4, 2, 3), part, "TC02: wrong frames");
        assertEquals(2, part.count(), "TC02: wrong count");
        assertFalse(part.whole(), "TC02: not every frame");
        // TC03: not two frame numbers: refused, saying what a range is
        for (String bad : new String[] {"x", "1-", "-1-2", "1..3", "1-2-3", "1 2", ""})
            assertMessage(assertThrows(IllegalArgumentException.class, () -> Animation.of(4, bad), "TC03: " + bad),
                    "--frame-range must be two frame numbers A-B", "TC03");

        // ===== Boundary Values Tests =====
        // TC11: the first frame alone, 1-1, and the last alone, N-N: one frame each
        assertEquals(1, Animation.of(4, "1-1").count(), "TC11: 1-1 is one frame");
        assertEquals(new Animation(4, 4, 4), Animation.of(4, "4-4"), "TC11: 4-4 is the last frame");
        // TC12: the whole run as a range, 1-N: every frame
        assertTrue(Animation.of(4, "1-4").whole(), "TC12: 1-4 of 4 is every frame");
        // TC13: A > B: empty, refused
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Animation.of(4, "3-2"), "TC13: 3-2"),
                "--frame-range 3-2 is empty", "TC13");
        // TC14: frame 0: refused, frames count from 1
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Animation.of(4, "0-2"), "TC14: 0-2"),
                "frame 0 does not exist: frames are numbered from 1", "TC14");
        // TC15: beyond N: refused, naming the last frame
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Animation.of(4, "3-5"), "TC15: 3-5"),
                "frame 5 is beyond the last frame, 4", "TC15");
        // TC16: frames 0 and MAX + 1 refused; 1 and MAX accepted
        assertMessage(assertThrows(IllegalArgumentException.class, () -> Animation.of(0, null), "TC16: 0 frames"),
                "--frames must be 1 to " + Animation.MAX_FRAMES + ", got 0", "TC16");
        assertThrows(IllegalArgumentException.class, () -> Animation.of(Animation.MAX_FRAMES + 1, null),
                "TC16: too many frames");
        assertEquals(1, Animation.of(1, null).count(), "TC16: one frame");
        assertEquals(Animation.MAX_FRAMES, Animation.of(Animation.MAX_FRAMES, null).count(), "TC16: the most frames");
    }

    /** Test method for {@link Animation#time(int)}. */
    @Test
    void testTime() {
        Animation animation = Animation.of(4, null);
        // ===== Equivalence Partitions Tests =====
        // TC01: frame k of 4 at (k − 1) / 4: 0, 0.25, 0.5, 0.75 (a full turn never shows its start twice)
        for (int k = 1; k <= 4; ++k)
            assertEquals((k - 1) / 4.0, animation.time(k), 1e-15, "TC01: wrong time of frame " + k);

        // ===== Boundary Values Tests =====
        // TC11: one frame: time 0
        assertEquals(0, Animation.of(1, null).time(1), 0, "TC11: a single frame is at time 0");
        // TC12: frames 0 and N + 1: refused
        assertMessage(assertThrows(IllegalArgumentException.class, () -> animation.time(0), "TC12: frame 0"),
                "frame 0 is not one of the animation's frames 1 to 4", "TC12");
        assertThrows(IllegalArgumentException.class, () -> animation.time(5), "TC12: frame 5");
    }

    /** Test method for {@link Animation#frameFile(Path, int)} and {@link Animation#frameFiles(Path)}. */
    @Test
    void testFrameFiles() {
        // ===== Equivalence Partitions Tests =====
        // TC01: beside NAME.gif: NAME-000k.png, 4 digits, in order
        assertEquals(List.of(Path.of("out", "spin-0001.png"), Path.of("out", "spin-0002.png"),
                Path.of("out", "spin-0003.png")), Animation.of(3, null).frameFiles(GIF), "TC01: wrong files");
        // TC02: beside NAME.png, NAME.jpg: frames of their format
        assertEquals(Path.of("a-0002.png"), Animation.of(3, null).frameFile(Path.of("a.png"), 2), "TC02: png");
        assertEquals(Path.of("a-0002.jpg"), Animation.of(3, null).frameFile(Path.of("a.jpg"), 2), "TC02: jpg");
        // TC03: a GIF is known in any case of its extension; a PNG is not one
        assertTrue(Animation.isGif(Path.of("A.GIF")), "TC03: A.GIF is a GIF");
        assertFalse(Animation.isGif(Path.of("a.png")), "TC03: a.png is not a GIF");

        // ===== Boundary Values Tests =====
        // TC11: 9999 frames keep 4 digits; 10000 need 5
        assertEquals(Path.of("a-9999.png"), Animation.of(9999, null).frameFile(Path.of("a.png"), 9999), "TC11: 9999");
        assertEquals(Path.of("a-00001.png"), Animation.of(10000, null).frameFile(Path.of("a.png"), 1), "TC11: 10000");
        // TC12: a frame outside the animation: refused
        assertThrows(IllegalArgumentException.class, () -> Animation.of(3, null).frameFile(GIF, 4), "TC12: frame 4");
    }
}
