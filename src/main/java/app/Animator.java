package app;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.LongConsumer;

import primitives.Printable;
import renderer.ImageWriter;
import renderer.Render;
import scenefile.AnimatedScene;
import scenefile.Picture;

/**
 * Runs an animation for the command line: renders its frames one after the other (each with all the
 * threads) under one progress bar, and writes the animated GIF when the output is one and the run
 * rendered every frame; or, with {@code --assemble}, builds the GIF from the frames on disk. Either
 * way the GIF is written from the frames' files, so one run of all the frames and several runs of
 * parts of them, assembled, give the same bytes. The frames' files are kept.
 */
final class Animator {
    private final RenderCommand command;
    private final Animation animation;
    private final Path output;
    private final int fps;

    /**
     * An animation run.
     *
     * @param command   the command, whose options and scene file it renders
     * @param animation the frames
     * @param output    the {@code -o} file: {@code NAME.gif}, or the image file the frames are named after
     * @param fps       the GIF's frame rate
     */
    Animator(RenderCommand command, Animation animation, Path output, int fps) {
        this.command = command;
        this.animation = animation;
        this.output = output;
        this.fps = fps;
    }

    /**
     * Builds the GIF from the frames' files.
     *
     * @param quiet whether to print nothing but a failure
     * @return the exit code: {@link RenderCommand#OK}
     * @throws Failure when a frame's file is missing
     */
    int assemble(boolean quiet) {
        List<Path> files = animation.frameFiles(output);
        for (int k = 1; k <= files.size(); ++k)
            if (!Files.isRegularFile(files.get(k - 1)))
                throw new Failure(Printable.of(files.get(k - 1)) + ": frame " + k + " of "
                        + animation.frames() + " is missing: render it (--frame-range " + k + "-" + k
                        + ") before --assemble", null);
        ImageWriter.checkOutput(output);
        long start = System.nanoTime();
        GifWriter.write(files, output, fps);
        if (!quiet)
            report(null, (System.nanoTime() - start) / 1e9);
        return RenderCommand.OK;
    }

    /**
     * Renders this run's frames, and the GIF when the output is one and every frame is rendered.
     *
     * @param quiet    whether to print nothing but a failure
     * @param terminal whether the error stream is a terminal, for the progress bar
     * @param threads  the rendering threads, 0 for one per core
     * @return the exit code: {@link RenderCommand#OK}
     */
    int render(boolean quiet, boolean terminal, int threads) {
        List<Path> files = animation.frameFiles(output);
        boolean gif = Animation.isGif(output) && animation.whole();
        ImageWriter.checkOutput(gif ? output : files.get(animation.first() - 1));
        AnimatedScene scene = command.loadAnimation();
        Picture picture = command.picture(scene, animation.time(animation.first()));
        command.noteIgnoredEdges(picture);
        PrintWriter err = command.commandLine().getErr();
        if (!quiet && !scene.moves() && animation.frames() > 1) {
            err.println(Printable.of(command.sceneFile()) + ": nothing moves in the scene (no <animation> orbit,"
                    + " no spin-x/y/z in a <transform>): every frame is the same picture");
            err.flush();
        }
        long pixels = (long) picture.nX() * picture.nY();
        long start = System.nanoTime();
        PixelProgress progress = quiet ? null : new PixelProgress(err, terminal, pixels * animation.count());
        try {
            for (int k = animation.first(); k <= animation.last(); ++k) {
                if (k > animation.first())
                    picture = command.picture(scene, animation.time(k));
                Render render = command.newRender(picture, files.get(k - 1)).setMultithreading(threads);
                if (progress != null) {
                    LongConsumer bar = progress.listener();
                    long before = (k - animation.first()) * pixels;
                    render.setProgressListener(done -> bar.accept(before + done));
                }
                command.render(picture, render, progress == null ? () -> { } : progress::mute);
            }
        } finally {
            if (progress != null)
                progress.close();
        }
        if (gif)
            GifWriter.write(files, output, fps);
        if (!quiet)
            report(picture, (System.nanoTime() - start) / 1e9);
        return RenderCommand.OK;
    }

    /** Prints the frames written, the GIF, the size and the time. */
    private void report(Picture picture, double seconds) {
        PrintWriter out = command.commandLine().getOut();
        if (picture != null)
            out.printf(Locale.ROOT, "Frames:       %d-%d of %d: %s ... %s%n", animation.first(), animation.last(),
                    animation.frames(), Printable.of(animation.frameFile(output, animation.first()).getFileName()),
                    Printable.of(animation.frameFile(output, animation.last()).getFileName()));
        if (Animation.isGif(output) && (picture == null || animation.whole()))
            out.printf(Locale.ROOT, "GIF:          %s, %d frames, %d fps (%d/100 s a frame)%n",
                    Printable.of(output.toAbsolutePath().normalize()), animation.frames(), fps, GifWriter.delay(fps));
        if (picture != null)
            out.printf(Locale.ROOT, "Size:         %d x %d pixels%n", picture.nX(), picture.nY());
        out.printf(Locale.ROOT, "Time:         %.3f s%n", seconds);
        out.flush();
    }
}
