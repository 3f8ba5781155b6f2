package scenefile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.io.IOException;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link SceneFileException}: the one-line message with the file, line and column, and
 * the getters.
 */
class SceneFileExceptionTest {
    /** A scene file in a folder (the separator is the system's). */
    private static final Path FILE = Path.of("scenes", "a.xml");

    /** Test method for {@link SceneFileException#SceneFileException(Path, int, int, String, Throwable)}. */
    @Test
    void testPositionConstructor() {
        IOException cause = new IOException("disk");

        // ===== Equivalence Partitions Tests =====
        // TC01: line 12 and column 40 known: "scenes/a.xml:12:40: radius must be positive"
        SceneFileException e = new SceneFileException(FILE, 12, 40, "radius must be positive", cause);
        assertEquals(FILE + ":12:40: radius must be positive", e.getMessage(), "TC01: wrong message");
        assertSame(FILE, e.getFile(), "TC01: wrong file");
        assertEquals(12, e.getLine(), "TC01: wrong line");
        assertEquals(40, e.getColumn(), "TC01: wrong column");
        assertEquals("radius must be positive", e.getProblem(), "TC01: wrong problem");
        assertSame(cause, e.getCause(), "TC01: the cause must be kept");
        // TC02: line 3 known, column unknown: "scenes/a.xml:3: bad"
        e = new SceneFileException(FILE, 3, SceneFileException.UNKNOWN, "bad", null);
        assertEquals(FILE + ":3: bad", e.getMessage(), "TC02: wrong message without a column");
        assertEquals(3, e.getLine(), "TC02: wrong line");
        assertEquals(-1, e.getColumn(), "TC02: the column must be -1 (unknown)");
        assertNull(e.getCause(), "TC02: no cause");
        // TC03: line unknown (column 5 given): "scenes/a.xml: bad", the column is not shown
        e = new SceneFileException(FILE, SceneFileException.UNKNOWN, 5, "bad", null);
        assertEquals(FILE + ": bad", e.getMessage(), "TC03: wrong message without a line");
        assertEquals(-1, e.getLine(), "TC03: the line must be -1 (unknown)");
        assertEquals(5, e.getColumn(), "TC03: the column must be kept");
        // TC04: a problem quoting ESC [ 2 J (clear the screen): "got '\x1B[2J'" in the message and the problem
        e = new SceneFileException(FILE, 2, 9, "radius must be a number, got '\u001b[2J'", null);
        assertEquals(FILE + ":2:9: radius must be a number, got '\\x1B[2J'", e.getMessage(), "TC04: wrong message");
        assertEquals("radius must be a number, got '\\x1B[2J'", e.getProblem(), "TC04: wrong problem");

        // ===== Boundary Values Tests =====
        // TC11: line 1, column 1, the first place in a file: "scenes/a.xml:1:1: x"
        assertEquals(FILE + ":1:1: x", new SceneFileException(FILE, 1, 1, "x", null).getMessage(),
                "TC11: wrong message at 1:1");
        // TC12: line 0 counts as unknown: "scenes/a.xml: x"
        assertEquals(FILE + ": x", new SceneFileException(FILE, 0, 7, "x", null).getMessage(),
                "TC12: line 0 must count as unknown");
        // TC13: column 0 counts as unknown: "scenes/a.xml:4: x"
        assertEquals(FILE + ":4: x", new SceneFileException(FILE, 4, 0, "x", null).getMessage(),
                "TC13: column 0 must count as unknown");
        // TC14: UNKNOWN is -1
        assertEquals(-1, SceneFileException.UNKNOWN, "TC14: UNKNOWN must be -1");
    }

    /** Test method for {@link SceneFileException#SceneFileException(Path, String, Throwable)}. */
    @Test
    void testWholeFileConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a problem with the whole file: "scenes/a.xml: no such scene file", line and column -1
        IOException cause = new IOException("missing");
        SceneFileException e = new SceneFileException(FILE, "no such scene file", cause);
        assertEquals(FILE + ": no such scene file", e.getMessage(), "TC01: wrong message");
        assertEquals(SceneFileException.UNKNOWN, e.getLine(), "TC01: the line must be unknown");
        assertEquals(SceneFileException.UNKNOWN, e.getColumn(), "TC01: the column must be unknown");
        assertEquals("no such scene file", e.getProblem(), "TC01: wrong problem");
        assertSame(FILE, e.getFile(), "TC01: wrong file");
        assertSame(cause, e.getCause(), "TC01: the cause must be kept");
        // TC02: it is an IllegalArgumentException
        assertInstanceOf(IllegalArgumentException.class, e, "TC02: must be an IllegalArgumentException");

        // ===== Boundary Values Tests =====
        // TC11: a file without a folder: "b.xml: x"
        assertEquals("b.xml: x", new SceneFileException(Path.of("b.xml"), "x", null).getMessage(),
                "TC11: wrong message for a file without a folder");
        // TC12: a null cause is kept as null
        assertNull(new SceneFileException(FILE, "x", null).getCause(), "TC12: the cause must be null");
        // TC13 (own): a file whose name ends with BEL: named printably, "b.xml\x07: x"; the path is kept as it is
        Path bell = Path.of("b.xml\u0007");
        e = new SceneFileException(bell, "x", null);
        assertEquals("b.xml\\x07: x", e.getMessage(), "TC13: the file's name must be printable");
        assertSame(bell, e.getFile(), "TC13: the file must be kept");
    }
}
