package app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link PixelProgress}, off a terminal (a log file): nothing before the first tile, the
 * bar's lines after it, nothing once muted.
 */
class PixelProgressTest {
    /** Test method for {@link PixelProgress#listener()}, {@link PixelProgress#mute()} and {@link PixelProgress#close()}. */
    @Test
    void testOffTerminal() {
        // ===== Equivalence Partitions Tests =====
        // TC01: no tile done: the bar writes nothing, even when closed
        StringWriter none = new StringWriter();
        new PixelProgress(new PrintWriter(none), false, 100).close();
        assertEquals("", none.toString(), "TC01: no line before the first tile");
        // TC02: 50 of 100 pixels done, then closed: a line of the bar at 50 %
        StringWriter half = new StringWriter();
        try (PixelProgress progress = new PixelProgress(new PrintWriter(half), false, 100)) {
            progress.listener().accept(50);
        }
        assertTrue(half.toString().contains("Rendering") && half.toString().contains("50%"),
                "TC02: the bar at 50 %, got: " + half);
        // TC03: muted after a tile: nothing at all once muted (the failure's line stands alone)
        StringWriter muted = new StringWriter();
        try (PixelProgress progress = new PixelProgress(new PrintWriter(muted), false, 100)) {
            progress.mute();
            progress.listener().accept(70);
        }
        assertEquals("", muted.toString(), "TC03: nothing once muted");

        // ===== Boundary Values Tests =====
        // TC11: the threads report out of order (80, then 30): the bar stays at 80 %, never back
        StringWriter order = new StringWriter();
        try (PixelProgress progress = new PixelProgress(new PrintWriter(order), false, 100)) {
            progress.listener().accept(80);
            progress.listener().accept(30);
        }
        assertTrue(order.toString().contains("80%"), "TC11: the bar at 80 %, got: " + order);
        assertFalse(order.toString().contains("30%"), "TC11: never back to 30 %, got: " + order);
    }
}
