package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static testutil.TestAssertions.assertMessage;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Unit tests for {@link FileReplacement}: a file is replaced whole or not at all, with nothing left
 * beside it.
 */
class FileReplacementTest {
    private static final Path FOLDER = Path.of("target", "test-file-replacement");

    /** {@return the names of the files in a folder, sorted} */
    private static List<String> names(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(f -> f.getFileName().toString()).sorted().toList();
        }
    }

    /** A fresh, empty folder for one test. */
    private static Path folder(String name) throws IOException {
        Path folder = FOLDER.resolve(name);
        if (Files.isDirectory(folder))
            for (String file : names(folder))
                Files.delete(folder.resolve(file));
        return folder;
    }

    /** Test method for {@link FileReplacement#replace(Path, FileReplacement.Contents)}. */
    @Test
    void testReplace() throws IOException {
        Path folder = folder("replace");
        Path file = folder.resolve("a.txt");

        // ===== Equivalence Partitions Tests =====
        // TC01: a new file in a missing folder: the folder made, the file holds "new", nothing else is there
        FileReplacement.replace(file, f -> Files.writeString(f, "new"));
        assertEquals("new", Files.readString(file), "TC01: wrong contents");
        assertEquals(List.of("a.txt"), names(folder), "TC01: a temporary file was left behind");
        // TC02: an old file: replaced by "newer"
        FileReplacement.replace(file, f -> Files.writeString(f, "newer"));
        assertEquals("newer", Files.readString(file), "TC02: the old file must be replaced");
        // TC03: contents that fail half way: the failure passes on, the old file stays "newer", nothing else
        IOException e = assertThrows(IOException.class, () -> FileReplacement.replace(file, f -> {
            Files.writeString(f, "half");
            throw new IOException("disk full");
        }), "TC03: a failed write must fail");
        assertMessage(e, "disk full", "TC03");
        assertEquals("newer", Files.readString(file), "TC03: a failed write must leave the old file");
        assertEquals(List.of("a.txt"), names(folder), "TC03: a failed write left a temporary file");
        // TC04: contents that throw an unchecked exception: the same, the old file stays
        assertThrows(IllegalArgumentException.class, () -> FileReplacement.replace(file, f -> {
            Files.writeString(f, "half");
            throw new IllegalArgumentException("bad frame");
        }), "TC04: an unchecked failure must pass on");
        assertEquals("newer", Files.readString(file), "TC04: a failed write must leave the old file");
        assertEquals(List.of("a.txt"), names(folder), "TC04: a failed write left a temporary file");

        // ===== Boundary Values Tests =====
        // TC11: contents that write nothing: an empty file
        FileReplacement.replace(file, f -> Files.write(f, new byte[0]));
        assertEquals(0, Files.size(file), "TC11: the file must be empty");
        // TC12: a folder at the path: refused, the folder stays
        Path sub = Files.createDirectories(folder.resolve("sub"));
        assertMessage(assertThrows(IOException.class, () -> FileReplacement.replace(sub, f -> Files.writeString(f, "x")),
                "TC12: a folder must not be replaced"), "is a folder", "TC12");
        assertTrue(Files.isDirectory(sub), "TC12: the folder must stay");
        Files.delete(sub);
        // TC13: a null file or contents: refused, naming it
        assertMessage(assertThrows(IllegalArgumentException.class, () -> FileReplacement.replace(null, f -> {
        }), "TC13: null file"), "file", "TC13");
        assertMessage(assertThrows(IllegalArgumentException.class, () -> FileReplacement.replace(file, null),
                "TC13: null contents"), "contents", "TC13");
    }

    /** Test method for {@link FileReplacement#checkWritable(Path)}. */
    @Test
    void testCheckWritable() throws IOException {
        Path folder = folder("check");

        // ===== Equivalence Partitions Tests =====
        // TC01: a file in a missing folder: the folder made and left empty
        FileReplacement.checkWritable(folder.resolve("a.txt"));
        assertEquals(List.of(), names(folder), "TC01: the check must leave the folder empty");
        // TC02: a folder below a file: refused
        Path blocker = Files.writeString(folder.resolve("file"), "not a folder");
        assertThrows(IOException.class, () -> FileReplacement.checkWritable(blocker.resolve("a.txt")),
                "TC02: a folder below a file must be refused");

        // ===== Boundary Values Tests =====
        // TC11: the path is a folder: refused
        Path sub = Files.createDirectories(folder.resolve("sub"));
        assertMessage(assertThrows(IOException.class, () -> FileReplacement.checkWritable(sub),
                "TC11: a folder must be refused"), "is a folder", "TC11");
    }
}
