package app;

import java.nio.file.Path;

import picocli.CommandLine;
import picocli.CommandLine.Option;
import renderer.ImageWriter;

/**
 * The command line's animation options: {@code --frames N} renders the scene at N times of its run
 * into numbered frames, {@code --frame-range A-B} only some of them (for a batch scheduler that spreads
 * the frames over machines), {@code --fps F} the GIF's frame rate, and {@code --assemble} builds the GIF
 * {@code -o NAME.gif} from the frames already on disk.
 */
final class AnimationOptions {
    @Option(names = "--frames", paramLabel = "N",
            description = "render an animation of N frames, frame k at time (k - 1) / N of the scene's run, into"
                    + " NAME-0001.png... beside -o NAME.png or -o NAME.gif; a .gif also gets the animated GIF")
    private Integer frames;

    @Option(names = "--frame-range", paramLabel = "A-B",
            description = "with --frames: render only frames A to B (from 1, both included), and no GIF; a later"
                    + " --assemble builds it from the frames of every run")
    private String range;

    @Option(names = "--fps", paramLabel = "F",
            description = "with -o NAME.gif: the GIF's frame rate, 1 to " + GifWriter.MAX_FPS + " (default: "
                    + GifWriter.DEFAULT_FPS + ")")
    private Integer fps;

    @Option(names = "--assemble",
            description = "with --frames N -o NAME.gif: build the GIF from frames NAME-0001.png... already"
                    + " rendered, rendering nothing (no scene file needed)")
    private boolean assemble;

    /** {@return whether an animation option was given} */
    boolean given() {
        return frames != null || range != null || fps != null || assemble;
    }

    /** {@return whether the run only assembles the GIF} */
    boolean assembles() {
        return assemble;
    }

    /** {@return the GIF's frame rate} */
    int fps() {
        return fps == null ? GifWriter.DEFAULT_FPS : fps;
    }

    /**
     * Checks the animation options against each other and the output.
     *
     * @param commandLine the command line, for its bad-argument exceptions
     * @param output      the {@code -o} file, or null
     * @return the frames to render, or null when no animation option was given
     * @throws CommandLine.ParameterException when an option is bad or does not go with the others
     */
    Animation check(CommandLine commandLine, Path output) {
        boolean gif = output != null && Animation.isGif(output);
        if (!given()) {
            if (gif)
                try {
                    ImageWriter.formatOf(output);
                } catch (IllegalArgumentException e) {
                    throw new CommandLine.ParameterException(commandLine, "-o: " + e.getMessage()
                            + "; a .gif is an animation: give --frames N");
                }
            return null;
        }
        if (frames == null)
            throw new CommandLine.ParameterException(commandLine, (range != null ? "--frame-range" : fps != null
                    ? "--fps" : "--assemble") + " goes with --frames N, the animation's number of frames");
        if (fps != null && !gif)
            throw new CommandLine.ParameterException(commandLine, "--fps is the GIF's frame rate: it goes with"
                    + " -o NAME.gif");
        if (assemble && !gif)
            throw new CommandLine.ParameterException(commandLine, "--assemble builds a GIF: give -o NAME.gif");
        if (assemble && range != null)
            throw new CommandLine.ParameterException(commandLine, "--assemble reads every frame: it does not go"
                    + " with --frame-range");
        try {
            GifWriter.delay(fps());
            return Animation.of(frames, range);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(commandLine, e.getMessage());
        }
    }
}
