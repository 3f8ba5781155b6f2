package renderer;

import java.awt.image.BufferedImage;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongConsumer;

import static primitives.Util.requireNonNull;

/**
 * What a preview window shows while a picture renders: the picture as far as it is done, and its
 * progress in a title. It listens to a render's progress ({@link Render#setProgressListener}) and
 * needs no display, so it works, and is tested, anywhere; {@link PreviewWindow} shows it on the screen.
 */
public class Preview implements LongConsumer {
    private final ImageWriter imageWriter;
    private final String name;
    private final long pixelsCount;
    private final AtomicLong pixelsDone = new AtomicLong();
    private final BufferedImage frame;

    /**
     * Creates the preview of a picture.
     *
     * @param imageWriter the image the picture is rendered into
     * @param name        the picture's name, shown in the title
     * @throws IllegalArgumentException when an argument is null
     */
    public Preview(ImageWriter imageWriter, String name) {
        this.imageWriter = requireNonNull(imageWriter, "preview image");
        this.name = requireNonNull(name, "preview name");
        this.pixelsCount = (long) imageWriter.getNx() * imageWriter.getNy();
        this.frame = new BufferedImage(imageWriter.getNx(), imageWriter.getNy(), BufferedImage.TYPE_INT_RGB);
    }

    /**
     * Takes note of the render's progress; any thread may call it.
     *
     * @param done the number of pixels rendered so far
     */
    @Override
    public void accept(long done) {
        pixelsDone.accumulateAndGet(done, Math::max);
    }

    /** {@return the share of the picture rendered so far, in whole percent from 0 to 100} */
    public int getPercent() {
        return (int) (100 * Math.min(pixelsDone.get(), pixelsCount) / pixelsCount);
    }

    /** {@return the window's title: the picture's name and its progress} */
    public String getTitle() {
        return name + " \u2014 " + (pixelsDone.get() >= pixelsCount ? "done" : getPercent() + " %");
    }

    /**
     * Copies the picture as it is now into the preview's frame; the pixels not yet rendered are black.
     * Call it from one thread (the window's).
     *
     * @return the frame, the same image at every call
     */
    public BufferedImage refresh() {
        imageWriter.copyTo(frame);
        return frame;
    }
}
