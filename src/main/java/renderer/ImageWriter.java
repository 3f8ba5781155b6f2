package renderer;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import primitives.Color;

import static primitives.Util.requireNonNull;

/**
 * An image of {@code nX × nY} pixels that is written as a PNG file, by default to
 * {@code images/<imageName>.png}. The folder is created when it does not exist.
 */
public class ImageWriter {
    /** The folder images go to unless another is given. */
    public static final Path DEFAULT_FOLDER = Path.of("images");
    /** The extension of the files images are written to. */
    public static final String EXTENSION = ".png";

    private final String imageName;
    private final Path folder;
    private final int nX;
    private final int nY;
    private final BufferedImage image;

    /**
     * Creates an image that will be written to {@code images/<imageName>.png}.
     *
     * @param imageName the file name, without extension
     * @param nX        the number of columns, positive
     * @param nY        the number of rows, positive
     */
    public ImageWriter(String imageName, int nX, int nY) {
        this(imageName, nX, nY, DEFAULT_FOLDER);
    }

    /**
     * Creates an image that will be written to {@code <folder>/<imageName>.png}.
     *
     * @param imageName the file name, without extension
     * @param nX        the number of columns, positive
     * @param nY        the number of rows, positive
     * @param folder    the folder to write to (created when missing)
     */
    public ImageWriter(String imageName, int nX, int nY, Path folder) {
        this.imageName = requireNonNull(imageName, "image name");
        if (imageName.isBlank())
            throw new IllegalArgumentException("image name must not be blank");
        this.folder = requireNonNull(folder, "image folder");
        if (nX <= 0 || nY <= 0)
            throw new IllegalArgumentException("image size must be positive, got " + nX + "x" + nY);
        this.nX = nX;
        this.nY = nY;
        this.image = new BufferedImage(nX, nY, BufferedImage.TYPE_INT_RGB);
    }

    /** {@return the number of columns} */
    public int getNx() {
        return nX;
    }

    /** {@return the number of rows} */
    public int getNy() {
        return nY;
    }

    /** {@return the file the image is written to} */
    public Path getPath() {
        return folder.resolve(imageName + EXTENSION);
    }

    /**
     * Colours one pixel.
     *
     * @param xIndex the column, 0 at the left
     * @param yIndex the row, 0 at the top
     * @param color  the colour
     * @throws IllegalArgumentException when the pixel is outside the image or the colour is null
     */
    public void writePixel(int xIndex, int yIndex, Color color) {
        checkPixel(xIndex, yIndex);
        image.setRGB(xIndex, yIndex, requireNonNull(color, "pixel colour").getColor().getRGB());
    }

    /**
     * Reads back one pixel.
     *
     * @param xIndex the column, 0 at the left
     * @param yIndex the row, 0 at the top
     * @return the pixel's colour as written to the file
     * @throws IllegalArgumentException when the pixel is outside the image
     */
    public java.awt.Color getPixel(int xIndex, int yIndex) {
        checkPixel(xIndex, yIndex);
        return new java.awt.Color(image.getRGB(xIndex, yIndex));
    }

    /**
     * Copies the picture as it is now into another image of the same size (a preview's frame).
     *
     * @param target the image to copy into
     * @throws IllegalArgumentException when the target is null or of another size
     */
    public void copyTo(BufferedImage target) {
        requireNonNull(target, "target image");
        if (target.getWidth() != nX || target.getHeight() != nY)
            throw new IllegalArgumentException("target image is " + target.getWidth() + "x" + target.getHeight()
                    + ", not " + nX + "x" + nY);
        target.getRaster().setRect(image.getRaster());
    }

    private void checkPixel(int xIndex, int yIndex) {
        if (xIndex < 0 || xIndex >= nX || yIndex < 0 || yIndex >= nY)
            throw new IllegalArgumentException("pixel (" + xIndex + ", " + yIndex + ") is outside the " + nX + "x" + nY + " image");
    }

    /**
     * Writes the image as a PNG file, creating the folder when it does not exist.
     *
     * @throws UncheckedIOException when the file cannot be written
     */
    public void writeToImage() {
        Path path = getPath();
        try {
            Files.createDirectories(folder);
            if (!ImageIO.write(image, "png", path.toFile()))
                throw new IOException("no PNG writer available");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write image " + path + ": " + e.getMessage(), e);
        }
    }
}
