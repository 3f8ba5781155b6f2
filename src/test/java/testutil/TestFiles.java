package testutil;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Files the tests write for themselves, under {@code target/}.
 */
public final class TestFiles {
    /** Not instantiable. */
    private TestFiles() {
    }

    /**
     * Writes a text file, creating its folder.
     *
     * @param folder the folder
     * @param name   the file's name
     * @param text   the file's text
     * @return the file's path
     */
    public static Path write(Path folder, String name, String text) {
        try {
            Files.createDirectories(folder);
            return Files.writeString(folder.resolve(name), text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
