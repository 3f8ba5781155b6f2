package app;

import java.nio.file.Path;

import renderer.ImageWriter;

/**
 * The command-line entry point: with no arguments it renders the example gallery into {@code images/}.
 */
public final class Main {
    private Main() {
    }

    /**
     * Renders the gallery.
     *
     * @param args none
     */
    public static void main(String[] args) {
        Path folder = ImageWriter.DEFAULT_FOLDER;
        for (Picture picture : Gallery.pictures()) {
            long start = System.nanoTime();
            Gallery.render(picture, folder);
            System.out.printf("%-32s %4dx%-4d %6.2f s%n", picture.name() + ".png", picture.nX(), picture.nY(),
                    (System.nanoTime() - start) / 1e9);
        }
    }
}
