package primitives;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Iterator;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

import static primitives.Util.requireNonNull;
import static primitives.Util.requirePositive;

/**
 * A picture on a surface: an image file (PNG or JPEG, read with ImageIO) stretched over a square of
 * surface coordinates and repeated beyond it, looked up with bilinear filtering. The square from (0, 0)
 * to (size, size) holds the whole image, u from its left edge to its right, v from its bottom edge to its
 * top (as an OBJ file's UVs are); the colour at a point mixes the four texels around it by its distance
 * from their centres, so at a texel's centre it is that texel's colour.
 */
public class ImageTexture implements Texture {
    /** The most pixels an image may have: 32 Mi (8192 × 4096), 128 MiB in memory. */
    public static final long MAX_PIXELS = 1L << 25;

    private final Path file;
    private final double size;
    private final int width;
    private final int height;
    /** The texels, row by row from the top, as packed RGB. */
    private final int[] texels;

    /**
     * Reads an image whose whole covers the unit square of surface coordinates: a mesh's UVs, a sphere's
     * longitude and latitude.
     *
     * @param file the image file
     * @throws IllegalArgumentException as {@link #ImageTexture(Path, double)}
     */
    public ImageTexture(Path file) {
        this(file, 1);
    }

    /**
     * Reads an image whose whole covers a square of surface coordinates of a given edge: a plane's or a
     * polygon's coordinates are in scene units.
     *
     * @param file the image file (PNG or JPEG)
     * @param size the edge of the square the image covers, a finite positive number
     * @throws IllegalArgumentException when the file is null, missing, unreadable, not an image ImageIO
     *                                  can read or larger than {@link #MAX_PIXELS}, or the size is not a
     *                                  finite positive number; the message names the file
     */
    public ImageTexture(Path file, double size) {
        this.file = requireNonNull(file, "texture file");
        this.size = requirePositive(size, "size of texture " + Printable.of(file));
        BufferedImage image = read(file);
        this.width = image.getWidth();
        this.height = image.getHeight();
        this.texels = image.getRGB(0, 0, width, height, null, 0, width);
    }

    /**
     * Reads the image, checking its size before decoding it. It must be a regular file: a pipe or a
     * device, which could keep the reading waiting forever, is refused.
     */
    private static BufferedImage read(Path file) {
        if (Files.isDirectory(file))
            throw Printable.refusal("texture file " + file + " is a folder, not an image", null);
        if (Files.exists(file) && !Files.isRegularFile(file))
            throw Printable.refusal("texture file " + file + " is not a regular file but a pipe or a device, which could"
                    + " keep the reading waiting", null);
        BufferedImage image;
        try (InputStream bytes = Files.newInputStream(file);
             ImageInputStream in = ImageIO.createImageInputStream(bytes)) {
            image = in == null ? null : decode(in, file);
        } catch (NoSuchFileException e) {
            throw Printable.refusal("texture file not found: " + file, e);
        } catch (AccessDeniedException e) {
            throw Printable.refusal("cannot read texture file " + file + ": permission denied", e);
        } catch (IOException e) {
            throw Printable.refusal("cannot read texture file " + file + ": " + e.getMessage(), e);
        }
        if (image == null)
            throw Printable.refusal("texture file " + file + " is not an image ImageIO can read (PNG or JPEG)", null);
        return image;
    }

    /** Decodes the image of a stream with the first reader that knows its format; null when none does. */
    private static BufferedImage decode(ImageInputStream in, Path file) throws IOException {
        Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
        if (!readers.hasNext())
            return null;
        ImageReader reader = readers.next();
        try {
            reader.setInput(in, true, true);
            long pixels = (long) reader.getWidth(0) * reader.getHeight(0);
            if (pixels > MAX_PIXELS)
                throw Printable.refusal("texture file " + file + " has " + pixels + " pixels, more than the " + MAX_PIXELS
                        + " a texture may have", null);
            return reader.read(0);
        } finally {
            reader.dispose();
        }
    }

    /** {@inheritDoc} Bilinear between the four texels around the point, the image repeated in u and v. */
    @Override
    public Color getColor(double u, double v) {
        double x = finite(u) / size * width - 0.5;
        double y = (1 - finite(v) / size) * height - 0.5;
        double left = Math.floor(x);
        double top = Math.floor(y);
        double ax = x - left;
        double ay = y - top;
        int x0 = (int) Math.floorMod((long) left, width);
        int y0 = (int) Math.floorMod((long) top, height);
        int x1 = x0 + 1 == width ? 0 : x0 + 1;
        int y1 = y0 + 1 == height ? 0 : y0 + 1;
        int[] corners = { texels[y0 * width + x0], texels[y0 * width + x1], texels[y1 * width + x0],
                texels[y1 * width + x1] };
        double[] weights = { (1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay };
        double[] rgb = new double[3];
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c)
                rgb[c] += weights[k] * (corners[k] >> (16 - 8 * c) & 0xFF);
        return new Color(rgb[0], rgb[1], rgb[2]);
    }

    /** A surface coordinate, 0 when it is not a finite number. */
    private static double finite(double coordinate) {
        return Double.isFinite(coordinate) ? coordinate : 0;
    }

    /** {@return the image file} */
    public Path getFile() {
        return file;
    }

    /** {@return the edge of the square of surface coordinates the whole image covers} */
    public double getSize() {
        return size;
    }

    /** {@return the image's width in texels} */
    public int getWidth() {
        return width;
    }

    /** {@return the image's height in texels} */
    public int getHeight() {
        return height;
    }

    @Override
    public String toString() {
        return "ImageTexture{" + file + ", " + width + "x" + height + ", size=" + size + "}";
    }
}
