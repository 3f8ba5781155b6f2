package app;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.List;

import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;

import primitives.FileReplacement;
import primitives.Printable;

/**
 * Writes an animated GIF with the JDK's GIF writer: the frames in order, each shown for
 * {@link #delay(int) 100 / fps} hundredths of a second (a GIF's unit; 24 fps shows each frame 4
 * hundredths, so 25 a second), looping for ever (the NETSCAPE2.0 application extension). The writer
 * gives each frame a palette of its own of up to 256 colours. The same frames give the same bytes.
 */
final class GifWriter {
    /** The frame rate when none is given. */
    static final int DEFAULT_FPS = 24;
    /** The highest frame rate: one frame a hundredth of a second, a GIF's shortest delay. */
    static final int MAX_FPS = 100;
    /** The format name of the JDK's GIF image metadata. */
    static final String METADATA_FORMAT = "javax_imageio_gif_image_1.0";

    private GifWriter() {
    }

    /**
     * The delay between the frames for a frame rate.
     *
     * @param fps frames a second, 1 to {@link #MAX_FPS}
     * @return the delay in hundredths of a second, 100 / fps rounded, at least 1
     * @throws IllegalArgumentException when the rate is out of bounds
     */
    static int delay(int fps) {
        if (fps < 1 || fps > MAX_FPS)
            throw new IllegalArgumentException("--fps must be 1 to " + MAX_FPS + ", got " + fps);
        return Math.max(1, Math.round(100f / fps));
    }

    /**
     * Writes the animation of image files (PNG, say) into a GIF, reading one at a time.
     *
     * @param frames the frames' files, in order, all of one size
     * @param gif    the GIF file, replaced whole when it exists (a failed write leaves it as it was)
     * @param fps    frames a second, 1 to {@link #MAX_FPS}
     * @throws UncheckedIOException     when a frame cannot be read or the GIF cannot be written; the message
     *                                  names the file
     * @throws IllegalArgumentException when there is no frame, the frames differ in size, or the rate is
     *                                  out of bounds
     */
    static void write(List<Path> frames, Path gif, int fps) {
        int delay = delay(fps);
        if (frames.isEmpty())
            throw new IllegalArgumentException(Printable.of(gif) + ": an animation needs one frame at least");
        try {
            FileReplacement.replace(gif, temporary -> writeFrames(frames, temporary, delay));
        } catch (IOException e) {
            throw new UncheckedIOException(Printable.of(gif + ": cannot write the GIF: " + e.getMessage()), e);
        }
    }

    /** Writes the frames into a GIF file, each shown for a delay in hundredths of a second. */
    private static void writeFrames(List<Path> frames, Path gif, int delay) throws IOException {
        ImageWriter writer = gifWriter();
        try (ImageOutputStream out = ImageIO.createImageOutputStream(Files.newOutputStream(gif))) {
            writer.setOutput(out);
            writer.prepareWriteSequence(null);
            BufferedImage first = null;
            for (Path frame : frames) {
                BufferedImage image = read(frame);
                if (first == null)
                    first = image;
                else if (image.getWidth() != first.getWidth() || image.getHeight() != first.getHeight())
                    throw new IllegalArgumentException(Printable.of(frame) + ": the frame is " + image.getWidth()
                            + " x " + image.getHeight() + " pixels, the first one " + first.getWidth() + " x "
                            + first.getHeight() + ": render all the frames at one size");
                ImageWriteParam param = writer.getDefaultWriteParam();
                IIOMetadata metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(image),
                        param);
                frameMetadata(metadata, delay, image == first);
                writer.writeToSequence(new IIOImage(image, null, metadata), param);
            }
            writer.endWriteSequence();
        } finally {
            writer.dispose();
        }
    }

    /** {@return the JDK's GIF writer} */
    private static ImageWriter gifWriter() {
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("gif");
        if (!writers.hasNext())
            throw new IllegalStateException("this Java has no GIF writer");
        return writers.next();
    }

    /** Reads a frame; a missing or unreadable one is a failure naming it. */
    private static BufferedImage read(Path frame) {
        try {
            BufferedImage image = ImageIO.read(frame.toFile());
            if (image == null)
                throw new IOException("not an image ImageIO reads");
            return image;
        } catch (IOException e) {
            throw new UncheckedIOException(Printable.of(frame + ": cannot read the frame: " + e.getMessage()), e);
        }
    }

    /**
     * Sets a frame's delay and disposal and, on the first frame, the loop for ever.
     *
     * @param metadata the frame's metadata, in {@link #METADATA_FORMAT}
     * @param delay    the delay in hundredths of a second
     * @param first    whether it is the first frame
     */
    private static void frameMetadata(IIOMetadata metadata, int delay, boolean first) throws IOException {
        IIOMetadataNode root = (IIOMetadataNode) metadata.getAsTree(METADATA_FORMAT);
        IIOMetadataNode control = child(root, "GraphicControlExtension");
        control.setAttribute("disposalMethod", "none");
        control.setAttribute("userInputFlag", "FALSE");
        control.setAttribute("transparentColorFlag", "FALSE");
        control.setAttribute("delayTime", Integer.toString(delay));
        control.setAttribute("transparentColorIndex", "0");
        if (first) {
            IIOMetadataNode loop = new IIOMetadataNode("ApplicationExtension");
            loop.setAttribute("applicationID", "NETSCAPE");
            loop.setAttribute("authenticationCode", "2.0");
            loop.setUserObject(new byte[] {1, 0, 0}); // sub-block 1: loop count 0, for ever
            child(root, "ApplicationExtensions").appendChild(loop);
        }
        metadata.setFromTree(METADATA_FORMAT, root);
    }

    /** {@return the child of a node of this name, added when it has none} */
    private static IIOMetadataNode child(IIOMetadataNode node, String name) {
        for (int k = 0; k < node.getLength(); ++k)
            if (node.item(k).getNodeName().equals(name))
                return (IIOMetadataNode) node.item(k);
        IIOMetadataNode child = new IIOMetadataNode(name);
        node.appendChild(child);
        return child;
    }
}
