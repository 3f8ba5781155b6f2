package testutil;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;

import renderer.ImageWriter;

/**
 * Comparisons of rendered images that several test classes make.
 */
public final class TestImages {
    /** Not instantiable. */
    private TestImages() {
    }

    /**
     * The number of pixels that differ between two rendered images of the same size.
     *
     * @param a one image
     * @param b the other, as large
     * @return how many of their pixels differ
     */
    public static int differentPixels(ImageWriter a, ImageWriter b) {
        int count = 0;
        for (int y = 0; y < a.getNy(); ++y)
            for (int x = 0; x < a.getNx(); ++x)
                if (!a.getPixel(x, y).equals(b.getPixel(x, y)))
                    ++count;
        return count;
    }

    /**
     * Whether two images of the same size have the same pixels.
     *
     * @param a one image
     * @param b the other, as large
     * @return true when every pixel's RGB is the same
     */
    public static boolean samePixels(BufferedImage a, BufferedImage b) {
        for (int y = 0; y < a.getHeight(); ++y)
            for (int x = 0; x < a.getWidth(); ++x)
                if (a.getRGB(x, y) != b.getRGB(x, y))
                    return false;
        return true;
    }

    /**
     * A frame of an animated GIF as ImageIO reads it back.
     *
     * @param image the frame's pixels
     * @param delay its delay in hundredths of a second (GraphicControlExtension's delayTime)
     * @param loops whether it carries the NETSCAPE2.0 loop extension
     */
    public record GifFrame(BufferedImage image, int delay, boolean loops) {
    }

    /**
     * Reads back every frame of a GIF with ImageIO's GIF reader.
     *
     * @param gif the GIF file
     * @return its frames, in order
     * @throws IOException when it cannot be read
     */
    public static List<GifFrame> gifFrames(Path gif) throws IOException {
        ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            reader.setInput(in);
            List<GifFrame> frames = new ArrayList<>();
            for (int k = 0; k < reader.getNumImages(true); ++k) {
                IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(k).getAsTree("javax_imageio_gif_image_1.0");
                IIOMetadataNode control = (IIOMetadataNode) root.getElementsByTagName("GraphicControlExtension").item(0);
                boolean loops = false;
                var extensions = root.getElementsByTagName("ApplicationExtension");
                for (int e = 0; e < extensions.getLength(); ++e)
                    loops |= "NETSCAPE".equals(((IIOMetadataNode) extensions.item(e)).getAttribute("applicationID"));
                frames.add(new GifFrame(reader.read(k), Integer.parseInt(control.getAttribute("delayTime")), loops));
            }
            return frames;
        } finally {
            reader.dispose();
        }
    }
}
