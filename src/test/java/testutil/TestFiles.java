package testutil;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

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
}
