package renderer;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.concurrent.atomic.AtomicLong;

import javax.imageio.ImageIO;

import primitives.Color;

import static primitives.Util.requireNonNull;

/**
 * An image of {@code nX × nY} pixels that is written as a PNG file, by default to
 * {@code images/<imageName>.png}. The folder is created when it does not exist. The file is written
 * atomically: the PNG goes to a temporary file in the same folder, renamed over the old picture only
 * once complete, so an interrupted write leaves the old picture or the new one, never half of one.
 */
public class ImageWriter {
    /** The folder images go to unless another is given. */
    public static final Path DEFAULT_FOLDER = Path.of("images");
    /** The extension of the files images are written to. */
    public static final String EXTENSION = ".png";
    /** The most pixels an image can hold: the longest array of ints. */
    public static final long MAX_PIXELS = Integer.MAX_VALUE - 8;

    /** Numbers the temporary files of this process, so that two writes never share one. */
    private static final AtomicLong TEMPORARY_COUNT = new AtomicLong();

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
     * @throws IllegalArgumentException when the name is blank or null, or the size is not positive or has
     *                                  more than {@link #MAX_PIXELS} pixels
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
     * @throws IllegalArgumentException when the name is blank, an argument is null, or the size is not
     *                                  positive or has more than {@link #MAX_PIXELS} pixels
     */
    public ImageWriter(String imageName, int nX, int nY, Path folder) {
        this.imageName = requireNonNull(imageName, "image name");
        if (imageName.isBlank())
            throw new IllegalArgumentException("image name must not be blank");
        this.folder = requireNonNull(folder, "image folder");
        requireSize(nX, nY);
        this.nX = nX;
        this.nY = nY;
        this.image = new BufferedImage(nX, nY, BufferedImage.TYPE_INT_RGB);
    }

    /**
     * Checks the size of an image: both sides positive, and no more than {@link #MAX_PIXELS} pixels.
     *
     * @param nX the number of columns
     * @param nY the number of rows
     * @throws IllegalArgumentException when the size is not positive or too large
     */
    public static void requireSize(int nX, int nY) {
        if (nX <= 0 || nY <= 0)
            throw new IllegalArgumentException("image size must be positive, got " + nX + "x" + nY);
        if ((long) nX * nY > MAX_PIXELS)
            throw new IllegalArgumentException("image size " + nX + "x" + nY + " is too large: an image holds at most "
                    + MAX_PIXELS + " pixels");
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
     * Checks, before any rendering, that the image can be written: creates its folder when missing,
     * and checks that a file can be made there and that the image's path is not a folder.
     *
     * @throws UncheckedIOException when the image cannot be written there
     */
    public void checkOutput() {
        checkOutput(getPath());
    }

    /**
     * Checks, before any rendering, that a PNG file can be written at a path: creates its folder when
     * missing, and checks that a file can be made there and that the path is not a folder.
     *
     * @param file the PNG file
     * @throws UncheckedIOException when no image can be written there
     */
    public static void checkOutput(Path file) {
        try {
            prepareFolder(file);
            Files.delete(Files.createFile(temporaryPath(file)));
        } catch (IOException e) {
            throw cannotWrite(file, e);
        }
    }

    /**
     * Writes the image as a PNG file, creating the folder when it does not exist: to a temporary file
     * in the folder first, then renamed over the old file in one step.
     *
     * @throws UncheckedIOException when the file cannot be written
     */
    public void writeToImage() {
        Path path = getPath();
        try {
            prepareFolder(path);
            Path temporary = temporaryPath(path);
            temporary.toFile().deleteOnExit(); // not left behind by Ctrl-C while writing
            try {
                if (!ImageIO.write(image, "png", temporary.toFile()))
                    throw new IOException("no PNG writer available");
                Files.move(temporary, path, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } finally {
                Files.deleteIfExists(temporary);
            }
        } catch (IOException e) {
            throw cannotWrite(path, e);
        }
    }

    /** Creates the file's folder when missing; the file itself must not be a folder. */
    private static void prepareFolder(Path file) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        if (Files.isDirectory(file))
            throw new IOException("it is a folder");
    }

    /** A new temporary file beside the image, hidden and unique to this write. */
    private static Path temporaryPath(Path file) {
        return file.resolveSibling("." + file.getFileName() + "." + ProcessHandle.current().pid() + "-"
                + TEMPORARY_COUNT.incrementAndGet() + ".tmp");
    }

    /** The failure to write an image, in the user's terms: what is in the way, not the exception's class. */
    private static UncheckedIOException cannotWrite(Path file, IOException e) {
        String reason;
        if (e instanceof AccessDeniedException)
            reason = "permission denied";
        else if (e instanceof FileAlreadyExistsException)
            reason = e.getMessage() + " is a file, not a folder";
        else if (e instanceof NoSuchFileException)
            reason = "no file can be made in " + file.toAbsolutePath().getParent();
        else if (e instanceof FileSystemException f && f.getReason() != null)
            reason = f.getReason();
        else
            reason = e.getMessage();
        return new UncheckedIOException(file + ": cannot write image: " + reason, e);
    }
}
