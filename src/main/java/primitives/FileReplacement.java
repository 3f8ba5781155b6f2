package primitives;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.concurrent.atomic.AtomicLong;

import static primitives.Util.requireNonNull;

/**
 * Writes a file so that no reader ever sees half of it: the contents go to a hidden temporary file in
 * the same folder, which is renamed over the old file in one step once complete. A failed or
 * interrupted write leaves the old file (or none) and no temporary file behind.
 */
public final class FileReplacement {
    /** Numbers the temporary files of this process, so that two writes never share one. */
    private static final AtomicLong TEMPORARY_COUNT = new AtomicLong();

    /** What is written into the file: its whole contents, to the path given. */
    @FunctionalInterface
    public interface Contents {
        /**
         * Writes the contents.
         *
         * @param file the file to write them to (the temporary file)
         * @throws IOException when they cannot be written
         */
        void writeTo(Path file) throws IOException;
    }

    /** Not instantiable. */
    private FileReplacement() {
    }

    /**
     * Writes a file's contents, creating its folder when missing, through a temporary file renamed over
     * the old file once the contents are complete.
     *
     * @param file     the file, replaced when it exists
     * @param contents writes the contents to the path it is given
     * @throws IOException              when the folder cannot be made, the file is a folder, or the
     *                                  contents or the rename fail; the old file is then left as it was
     * @throws IllegalArgumentException when an argument is null
     */
    public static void replace(Path file, Contents contents) throws IOException {
        requireNonNull(file, "file");
        requireNonNull(contents, "contents");
        prepareFolder(file);
        Path temporary = temporaryPath(file);
        temporary.toFile().deleteOnExit(); // not left behind by Ctrl-C while writing
        try {
            contents.writeTo(temporary);
            Files.move(temporary, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /**
     * Checks, before the contents are made, that {@link #replace} can write a file: creates its folder
     * when missing, and makes and deletes a temporary file there.
     *
     * @param file the file
     * @throws IOException              when no file can be made there, or the path is a folder
     * @throws IllegalArgumentException when the file is null
     */
    public static void checkWritable(Path file) throws IOException {
        requireNonNull(file, "file");
        prepareFolder(file);
        Files.delete(Files.createFile(temporaryPath(file)));
    }

    /** Creates the file's folder when missing; the file itself must not be a folder. */
    private static void prepareFolder(Path file) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        if (Files.isDirectory(file))
            throw new IOException("it is a folder");
    }

    /** A new temporary file beside the file, hidden and unique to this write. */
    private static Path temporaryPath(Path file) {
        return file.resolveSibling("." + file.getFileName() + "." + ProcessHandle.current().pid() + "-"
                + TEMPORARY_COUNT.incrementAndGet() + ".tmp");
    }
}
