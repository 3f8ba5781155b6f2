package app;

import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Path;

import renderer.ImageWriter;
import scenefile.Picture;

/**
 * The command-line entry point: with no arguments it renders the example gallery into {@code images/};
 * with arguments it runs the {@link RenderCommand render command} ({@code render SCENE.xml [options]},
 * see {@code --help}).
 */
public final class Main {
    private Main() {
    }

    /**
     * Renders the gallery (exit code 2 with one line when {@code images/} cannot be written), or runs the
     * render command and exits with its exit code.
     *
     * @param args none for the gallery, or the render command's arguments
     */
    public static void main(String[] args) {
        if (args.length == 0) {
            try {
                renderGallery();
            } catch (UncheckedIOException e) { // images/ cannot be written: one line, as for the render command
                System.err.println(e.getMessage());
                System.exit(RenderCommand.BAD_INPUT);
            }
            return;
        }
        System.exit(run(args, new PrintWriter(System.out, true), new PrintWriter(System.err, true),
                System.console() != null));
    }

    /**
     * Runs the render command in this process.
     *
     * @param args     the command's arguments
     * @param out      where the command's results and help go
     * @param err      where its progress bar and error messages go
     * @param terminal true when the error stream is a terminal (the progress bar redraws its line)
     * @return the exit code: 0 on success, 2 on bad arguments, a bad scene file or an image that cannot be
     * written
     */
    static int run(String[] args, PrintWriter out, PrintWriter err, boolean terminal) {
        return RenderCommand.newCommandLine(terminal).setOut(out).setErr(err).execute(args);
    }

    /** Renders every picture of the gallery into {@code images/}. */
    private static void renderGallery() {
        Path folder = ImageWriter.DEFAULT_FOLDER;
        for (Picture picture : Gallery.pictures()) {
            long start = System.nanoTime();
            Gallery.render(picture, folder);
            System.out.printf("%-32s %4dx%-4d %6.2f s%n", picture.name() + ".png", picture.nX(), picture.nY(),
                    (System.nanoTime() - start) / 1e9);
        }
    }
}
