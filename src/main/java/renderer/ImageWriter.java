package renderer;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;

import javax.imageio.ImageIO;

import primitives.Color;
import primitives.FileNames;
import primitives.FileReplacement;
import primitives.Printable;

import static primitives.Util.requireNonNull;

/**
 * An image of {@code nX × nY} pixels that is written as a PNG file, by default to
 * {@code images/<imageName>.png}, or to any file whose extension names a format ImageIO writes:
 * {@code .png}, {@code .jpg}/{@code .jpeg} or {@code .bmp} (see {@link #forFile(Path, int, int)}). The
 * folder is created when it does not exist. The file is written atomically: the image goes to a
 * temporary file in the same folder, renamed over the old picture only once complete, so an interrupted
 * write leaves the old picture or the new one, never half of one.
 */
public class ImageWriter {
    /** The folder images go to unless another is given. */
    public static final Path DEFAULT_FOLDER = Path.of("images");
    /** The extension of the files images are written to unless a file is given. */
    public static final String EXTENSION = ".png";
    /** The extensions of the files images can be written to, with ImageIO's name of each format. */
    private static final Map<String, String> FORMATS = Map.of(".png", "png", ".jpg", "jpeg", ".jpeg", "jpeg",
            ".bmp", "bmp");
    /** The most pixels an image can hold: the longest array of ints. */
    public static final long MAX_PIXELS = Integer.MAX_VALUE - 8;

    private final Path file;
    private final String format;
    private final int nX;
    private final int nY;
    private final BufferedImage image;
    /** The image's pixels, row after row, each 0xRRGGBB: written directly, without a colour model's conversion. */
    private final int[] pixels;

    /**
     * Creates an image that will be written to {@code images/<imageName>.png}.
     *
     * @param imageName the file name, without extension
     * @param nX        the number of columns, positive
     * @param nY        the number of rows, positive
     * @throws IllegalArgumentException when the name is blank or null, cannot be a path or leads out of
     *                                  {@code images/} (an absolute name, or {@code ..} above it), or the
     *                                  size is not positive or has more than {@link #MAX_PIXELS} pixels
     */
    public ImageWriter(String imageName, int nX, int nY) {
        this(imageName, nX, nY, DEFAULT_FOLDER);
    }

    /**
     * Creates an image that will be written to {@code <folder>/<imageName>.png}.
     *
     * @param imageName the file name, without extension; it may lead into a folder inside the folder
     *                  ({@code sub/picture}), never out of it
     * @param nX        the number of columns, positive
     * @param nY        the number of rows, positive
     * @param folder    the folder to write to (created when missing)
     * @throws IllegalArgumentException when the name is blank, cannot be a path or leads out of the folder
     *                                  (an absolute name, or {@code ..} above it), an argument is null, or
     *                                  the size is not positive or has more than {@link #MAX_PIXELS} pixels
     */
    public ImageWriter(String imageName, int nX, int nY, Path folder) {
        this(fileIn(requireNonNull(folder, "image folder"), requireName(imageName)), nX, nY);
    }

    /**
     * Creates an image that will be written to a file, in the format its extension names.
     *
     * @param file the file: {@code .png}, {@code .jpg}, {@code .jpeg} or {@code .bmp} (any case)
     * @param nX   the number of columns, positive
     * @param nY   the number of rows, positive
     * @return the image
     * @throws IllegalArgumentException when the file is null or has another extension, or the size is not
     *                                  positive or has more than {@link #MAX_PIXELS} pixels
     */
    public static ImageWriter forFile(Path file, int nX, int nY) {
        return new ImageWriter(file, nX, nY);
    }

    private ImageWriter(Path file, int nX, int nY) {
        this.format = formatOf(file);
        this.file = file;
        requireSize(nX, nY);
        this.nX = nX;
        this.nY = nY;
        this.image = new BufferedImage(nX, nY, BufferedImage.TYPE_INT_RGB);
        this.pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
    }

    /**
     * The file of an image's name in its folder: {@code <folder>/<imageName>.png}. A name may lead into a
     * folder inside (sub/picture), never out of it: an absolute name, or one whose ".." climbs above the
     * folder, is refused.
     */
    private static Path fileIn(Path folder, String imageName) {
        Path file = folder.resolve(FileNames.toPath(imageName + EXTENSION));
        if (!file.toAbsolutePath().normalize().startsWith(folder.toAbsolutePath().normalize()))
            throw new IllegalArgumentException("image name '" + Printable.of(imageName) + "' leads out of its folder "
                    + Printable.of(folder) + ": give a name inside it, without an absolute path or '..' above it");
        return file;
    }

    private static String requireName(String imageName) {
        if (requireNonNull(imageName, "image name").isBlank())
            throw new IllegalArgumentException("image name must not be blank");
        return imageName;
    }

    /**
     * The image format of a file, from its extension.
     *
     * @param file the file
     * @return ImageIO's name of the format: png, jpeg or bmp
     * @throws IllegalArgumentException when the file is null or its extension names no format written here
     */
    public static String formatOf(Path file) {
        Path name = requireNonNull(file, "image file").getFileName();
        String fileName = name == null ? "" : name.toString();
        int dot = fileName.lastIndexOf('.');
        String format = dot > 0 ? FORMATS.get(fileName.substring(dot).toLowerCase(Locale.ROOT)) : null;
        if (format == null)
            throw new IllegalArgumentException("the image file " + Printable.of(file) + " must end with one of "
                    + String.join(", ", new TreeSet<>(FORMATS.keySet())));
        return format;
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
        return file;
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
        pixels[yIndex * nX + xIndex] = requireNonNull(color, "pixel colour").getRGB();
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
     * Checks, before any rendering, that an image file can be written at a path: creates its folder when
     * missing, and checks that a file can be made there and that the path is not a folder.
     *
     * @param file the image file
     * @throws UncheckedIOException     when no image can be written there
     * @throws IllegalArgumentException when the file is null
     */
    public static void checkOutput(Path file) {
        requireNonNull(file, "image file");
        try {
            FileReplacement.checkWritable(file);
        } catch (IOException e) {
            throw cannotWrite(file, e);
        }
    }

    /**
     * Writes the image to its file in its format, creating the folder when it does not exist: to a
     * temporary file in the folder first, then renamed over the old file in one step.
     *
     * @throws UncheckedIOException when the file cannot be written
     */
    public void writeToImage() {
        try {
            FileReplacement.replace(file, temporary -> {
                if (!ImageIO.write(image, format, temporary.toFile()))
                    throw new IOException("no " + format + " writer available");
            });
        } catch (IOException e) {
            throw cannotWrite(file, e);
        }
    }

    /**
     * The failure to write an image, in the user's terms: what is in the way, not the exception's class;
     * the file's name made {@link Printable printable}.
     */
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
        return new UncheckedIOException(Printable.of(file + ": cannot write image: " + reason), e);
    }
}
