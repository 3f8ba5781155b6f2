package app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestCommands.run;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import testutil.TestAnimations;
import testutil.TestCommands.Result;

/**
 * Tests for {@link AnimationOptions}, through the command line: options that do not go together, and
 * bad frame ranges, are bad arguments (exit code 2, one line, nothing rendered).
 */
class AnimationOptionsTest {
    private static final Path FOLDER = Path.of("target", "test-animation", "options");

    /** Asserts that a run fails as a bad argument, with a message, and writes nothing. */
    private static void assertBadArgument(String tc, String message, String... args) {
        Result result = run(args);
        assertEquals(2, result.code(), tc + ": bad arguments must exit with 2");
        assertEquals(1, result.errLines().size(), tc + ": one line: " + result.err());
        assertTrue(result.err().contains(message), tc + ": wrong message: " + result.err());
        assertFalse(Files.exists(FOLDER.resolve("a-0001.png")), tc + ": a frame was written");
    }

    /** Test method for {@link AnimationOptions#check(picocli.CommandLine, Path)}. */
    @Test
    void testCheck() {
        String scene = TestAnimations.spinning(FOLDER, "spin.xml", "").toString();
        String gif = FOLDER.resolve("a.gif").toString();
        String png = FOLDER.resolve("a.png").toString();
        // ===== Equivalence Partitions Tests =====
        // TC01: an animation option without --frames
        assertBadArgument("TC01", "--frame-range goes with --frames N", scene, "--frame-range", "1-2", "-o", gif);
        assertBadArgument("TC01", "--assemble goes with --frames N", "--assemble", "-o", gif);
        // TC02: a GIF without --frames; --fps or --assemble without a GIF
        assertBadArgument("TC02", "must end with one of .bmp, .jpeg, .jpg, .png; a .gif is an animation: give"
                + " --frames N", scene, "-o", gif);
        assertBadArgument("TC02", "--fps is the GIF's frame rate: it goes with -o NAME.gif", scene, "--frames", "2",
                "--fps", "10", "-o", png);
        assertBadArgument("TC02", "--assemble builds a GIF: give -o NAME.gif", "--assemble", "--frames", "2", "-o", png);
        // TC03: --assemble with a range, --preview with frames
        assertBadArgument("TC03", "--assemble reads every frame", "--assemble", "--frames", "4", "--frame-range", "1-2",
                "-o", gif);
        assertBadArgument("TC03", "--preview does not go with --frames", scene, "--frames", "2", "--preview", "-o", gif);
        // TC04: a range that is not one
        assertBadArgument("TC04", "--frame-range must be two frame numbers A-B", scene, "--frames", "4",
                "--frame-range", "2", "-o", gif);

        // ===== Boundary Values Tests =====
        // TC11: --frames 0, --fps 0 and 101
        assertBadArgument("TC11", "--frames must be 1 to 100000, got 0", scene, "--frames", "0", "-o", gif);
        assertBadArgument("TC11", "--fps must be 1 to 100, got 0", scene, "--frames", "2", "--fps", "0", "-o", gif);
        assertBadArgument("TC11", "--fps must be 1 to 100, got 101", scene, "--frames", "2", "--fps", "101", "-o", gif);
        // TC12: ranges past either end, and backwards
        assertBadArgument("TC12", "frame 0 does not exist", scene, "--frames", "4", "--frame-range", "0-1", "-o", gif);
        assertBadArgument("TC12", "frame 5 is beyond the last frame, 4", scene, "--frames", "4", "--frame-range", "4-5",
                "-o", gif);
        assertBadArgument("TC12", "--frame-range 3-2 is empty", scene, "--frames", "4", "--frame-range", "3-2",
                "-o", gif);
    }
}
