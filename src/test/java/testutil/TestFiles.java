package testutil;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

/**
 * Files the tests write for themselves, under {@code target/} (or a test's temporary folder): text files
 * and named pipes.
 */
public final class TestFiles {
    /** Not instantiable. */
    private TestFiles() {
    }

    /**
     * Writes a text file, creating its folder; a named pipe of that name (left by an earlier run of a test),
     * which writing would wait on forever, is replaced.
     *
     * @param folder the folder
     * @param name   the file's name
     * @param text   the file's text
     * @return the file's path
     */
    public static Path write(Path folder, String name, String text) {
        Path file = folder.resolve(name);
        try {
            Files.createDirectories(folder);
            if (Files.exists(file) && !Files.isRegularFile(file) && !Files.isDirectory(file))
                Files.delete(file);
            return Files.writeString(file, text);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Writes a scene file of some bodies: {@code <scene>}, a line, {@code <geometries>}, a line, the bodies
     * (from line 3), {@code </geometries>}, {@code </scene>}.
     *
     * @param folder the folder, created when missing
     * @param name   the file's name
     * @param bodies the bodies' elements, and lines
     * @return the file's path
     */
    public static Path writeBodies(Path folder, String name, String bodies) {
        return write(folder, name, "<scene>\n<geometries>\n" + bodies + "</geometries>\n</scene>\n");
    }

    /**
     * Writes a PNG image, creating its folder.
     *
     * @param folder the folder
     * @param name   the file's name
     * @param width  the image's width; its height is the number of texels over it
     * @param rgb    the texels' packed RGB colours, row by row from the top
     * @return the file's path
     */
    public static Path writePng(Path folder, String name, int width, int... rgb) {
        BufferedImage image = new BufferedImage(width, rgb.length / width, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, rgb.length / width, rgb, 0, width);
        try {
            Files.createDirectories(folder);
            Path file = folder.resolve(name);
            ImageIO.write(image, "png", file.toFile());
            return file;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Makes a named pipe (a FIFO) with the system's {@code mkfifo}, in place of any file of that name; a
     * test that needs one is skipped, by an assumption, on a system without {@code mkfifo}.
     *
     * @param folder the folder, created when missing
     * @param name   the pipe's name
     * @return the pipe's path
     */
    public static Path fifo(Path folder, String name) {
        Path fifo = folder.resolve(name);
        Process mkfifo;
        try {
            Files.createDirectories(folder);
            Files.deleteIfExists(fifo);
            mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).redirectErrorStream(true).start();
        } catch (IOException e) {
            assumeTrue(false, "no mkfifo on this system: " + e.getMessage());
            throw new UncheckedIOException(e);
        }
        try {
            if (mkfifo.waitFor() != 0)
                throw new IllegalStateException("mkfifo " + fifo + " failed: "
                        + new String(mkfifo.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while making " + fifo, e);
        }
        return fifo;
    }

    /**
     * Writes a text into a named pipe for its first reader, from a thread of its own (a daemon), then
     * opens it once more and writes nothing: code that opens the pipe a second time (once the first reader
     * has closed it) finds it empty and fails, rather than waiting forever for a writer. Opening the pipe
     * waits for a reader: a test whose code must not read the pipe reads it itself at the end.
     *
     * @param fifo the pipe
     * @param text the text, in UTF-8
     */
    public static void feed(Path fifo, String text) {
        Thread writer = new Thread(() -> {
            try {
                Files.writeString(fifo, text);
                Files.newOutputStream(fifo).close();
            } catch (IOException e) {
                // the reader stopped early: what it read, its test checks
            }
        }, "fifo-writer");
        writer.setDaemon(true);
        writer.start();
    }
}
