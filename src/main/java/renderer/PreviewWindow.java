package renderer;

import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.lang.reflect.InvocationTargetException;
import java.util.concurrent.CountDownLatch;

import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;

import static primitives.Util.requireNonNull;

/**
 * A window on the screen that shows a {@link Preview}: the picture tile by tile as it renders, scaled
 * to fit, with the progress in its title. It stays open after the render until the user closes it.
 * <pre>{@code
 * Preview preview = new Preview(imageWriter, "my scene");
 * PreviewWindow window = PreviewWindow.open(preview);   // HeadlessException when there is no display
 * render.setProgressListener(preview);
 * render.renderImage();
 * window.awaitClosed();
 * }</pre>
 */
public final class PreviewWindow {
    /** How often, in milliseconds, the window shows the picture anew. */
    private static final int REFRESH_MILLIS = 100;
    /** The largest share of the screen's width or height the window takes at first. */
    private static final double MAX_SCREEN_SHARE = 0.8;

    private final Preview preview;
    private final CountDownLatch closed = new CountDownLatch(1);
    private JFrame frame;
    private Timer timer;

    private PreviewWindow(Preview preview) {
        this.preview = preview;
    }

    /**
     * Opens a window showing a preview.
     *
     * @param preview the preview
     * @return the open window
     * @throws HeadlessException        when there is no display to open it on
     * @throws IllegalArgumentException when the preview is null
     */
    public static PreviewWindow open(Preview preview) {
        requireNonNull(preview, "preview");
        if (GraphicsEnvironment.isHeadless())
            throw new HeadlessException("there is no display to show the preview window on");
        PreviewWindow window = new PreviewWindow(preview);
        onEventThread(window::show);
        return window;
    }

    /** Builds and shows the frame; runs on the event thread. */
    private void show() {
        BufferedImage image = preview.refresh();
        JComponent canvas = new JComponent() {
            private static final long serialVersionUID = 1L;

            @Override
            protected void paintComponent(Graphics g) {
                paintScaled((Graphics2D) g, preview.refresh(), getWidth(), getHeight());
            }
        };
        canvas.setPreferredSize(initialSize(image.getWidth(), image.getHeight()));
        frame = new JFrame(preview.getTitle());
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                timer.stop();
                closed.countDown();
            }
        });
        frame.add(canvas);
        frame.pack();
        frame.setLocationRelativeTo(null);
        timer = new Timer(REFRESH_MILLIS, e -> {
            frame.setTitle(preview.getTitle());
            canvas.repaint();
        });
        timer.start();
        frame.setVisible(true);
    }

    /**
     * The window's first size: the picture's own size, made smaller to fit most of the screen.
     *
     * @param width  the picture's width
     * @param height the picture's height
     * @return the size of the canvas
     */
    private static Dimension initialSize(int width, int height) {
        Rectangle screen = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        double scale = Math.min(1, MAX_SCREEN_SHARE * Math.min((double) screen.width / width,
                (double) screen.height / height));
        return new Dimension(Math.max(1, (int) (width * scale)), Math.max(1, (int) (height * scale)));
    }

    /**
     * Draws an image as large as fits a canvas, keeping its proportions, centred.
     *
     * @param g      the canvas's graphics
     * @param image  the image
     * @param width  the canvas's width
     * @param height the canvas's height
     */
    private static void paintScaled(Graphics2D g, BufferedImage image, int width, int height) {
        double scale = Math.min((double) width / image.getWidth(), (double) height / image.getHeight());
        int w = (int) Math.round(image.getWidth() * scale);
        int h = (int) Math.round(image.getHeight() * scale);
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, scale < 1
                ? RenderingHints.VALUE_INTERPOLATION_BILINEAR : RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        g.drawImage(image, (width - w) / 2, (height - h) / 2, w, h, null);
    }

    /**
     * Waits until the user closes the window.
     *
     * @throws InterruptedException when the waiting thread is interrupted
     */
    public void awaitClosed() throws InterruptedException {
        closed.await();
    }

    /** Closes the window. */
    public void close() {
        onEventThread(() -> frame.dispose());
    }

    /**
     * Runs a task on Swing's event thread and waits for it.
     *
     * @param task the task
     */
    private static void onEventThread(Runnable task) {
        if (SwingUtilities.isEventDispatchThread()) {
            task.run();
            return;
        }
        try {
            SwingUtilities.invokeAndWait(task);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the preview window", e);
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("the preview window failed: " + e.getCause().getMessage(), e.getCause());
        }
    }
}
