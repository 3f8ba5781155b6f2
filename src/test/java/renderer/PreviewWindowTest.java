package renderer;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link PreviewWindow} without a display (the suite runs headless, see the pom); the
 * window itself is checked by hand under a virtual display (docs/testing.md).
 */
class PreviewWindowTest {

    /** Test method for {@link PreviewWindow#open(Preview)} with no display. */
    @Test
    void testOpenHeadless() {
        // ===== Equivalence Partitions Tests =====
        // TC01: the tests run headless
        assertTrue(GraphicsEnvironment.isHeadless(), "TC01: the suite must run headless");
        // TC02: opening a window fails with one message saying there is no display
        Preview preview = new Preview(new ImageWriter("window", 8, 8, Path.of("target", "test-images", "preview")), "window");
        HeadlessException e = assertThrows(HeadlessException.class, () -> PreviewWindow.open(preview),
                "TC02: opening a window with no display must fail");
        assertMessage(e, "no display", "TC02");

        // ===== Boundary Values Tests =====
        // TC11: a null preview is refused with a message naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> PreviewWindow.open(null), "TC11: null preview"),
                "preview", "TC11");
    }
}
