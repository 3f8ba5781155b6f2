package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static testutil.TestAssertions.assertMessage;
import static testutil.TestAssertions.assertPrintable;

import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link FileNames}: file names become paths, and one that cannot be a path gets a message
 * saying why and, when the locale is the cause, what to set. (The C locale itself is run in a JVM of its
 * own by {@code RenderCommandTest}.)
 */
class FileNamesTest {

    /** Test method for {@link FileNames#toPath(String)}. */
    @Test
    void testToPath() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a relative name is the path of its parts: scenes/a.xml
        assertEquals(Path.of("scenes", "a.xml"), FileNames.toPath("scenes/a.xml"), "TC01: wrong relative path");
        // TC02: an absolute name stays absolute: /tmp/a.png
        assertEquals(Path.of("/tmp", "a.png"), FileNames.toPath("/tmp/a.png"), "TC02: wrong absolute path");
        // TC03: a name with a NUL character, which no path holds: refused, naming it printably and the reason
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FileNames.toPath("a\0b.xml"),
                "TC03: NUL must be refused");
        assertPrintable(e.getMessage(), "the file name 'a\\x00b.xml' cannot be a path: Nul character not allowed",
                "TC03");

        // ===== Boundary Values Tests =====
        // TC11: null is refused, naming the file name
        assertMessage(assertThrows(IllegalArgumentException.class, () -> FileNames.toPath(null),
                "TC11: null must be refused"), "file name must not be null", "TC11");
        // TC12: the empty name is the empty path, the current folder
        assertEquals(Path.of(""), FileNames.toPath(""), "TC12: the empty name must be the empty path");
    }

    /** Test method for {@link FileNames#problem(String, java.nio.charset.Charset, InvalidPathException)}. */
    @Test
    void testProblem() {
        InvalidPathException unmappable = new InvalidPathException("sc\u00e8ne.xml", "Malformed input or input contains"
                + " unmappable characters");
        // ===== Equivalence Partitions Tests =====
        // TC01: in the C locale (file names in ASCII) "scène.xml": the letters, the encoding and what to set
        assertEquals("the file name 'sc\u00e8ne.xml' has letters that file names cannot hold in this locale (its file"
                + " names are US-ASCII); run with a UTF-8 locale, e.g. LC_ALL=C.UTF-8",
                FileNames.problem("sc\u00e8ne.xml", StandardCharsets.US_ASCII, unmappable), "TC01: wrong message");
        // TC02: a name the locale can encode was refused for another reason: that reason, no locale advice
        assertEquals("the file name 'a\\x00b' cannot be a path: Nul character not allowed", FileNames.problem("a\0b",
                StandardCharsets.UTF_8, new InvalidPathException("a\0b", "Nul character not allowed")),
                "TC02: wrong message");
        // TC03 (own): a Hebrew name in ISO-8859-1 (Latin letters only): the locale's advice, its encoding named
        assertMessage(new IllegalArgumentException(FileNames.problem("\u05e1\u05e6\u05e0\u05d4.xml",
                StandardCharsets.ISO_8859_1, unmappable)), "(its file names are ISO-8859-1); run with a UTF-8 locale",
                "TC03");

        // ===== Boundary Values Tests =====
        // TC11: the encoding unknown (null): the reason alone
        assertEquals("the file name 'sc\u00e8ne.xml' cannot be a path: Malformed input or input contains unmappable"
                + " characters", FileNames.problem("sc\u00e8ne.xml", null, unmappable), "TC11: wrong message");
        // TC12: U+FFFD, what the launcher makes of bytes the C locale cannot decode, is a letter ASCII lacks
        assertMessage(new IllegalArgumentException(FileNames.problem("sc\ufffd\ufffdne.xml", StandardCharsets.US_ASCII,
                unmappable)), "LC_ALL=C.UTF-8", "TC12");
    }
}
