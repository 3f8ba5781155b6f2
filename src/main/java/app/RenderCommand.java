package app;

import java.awt.HeadlessException;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.Callable;
import java.util.function.LongConsumer;
import java.util.function.Supplier;

import lighting.AreaLightSource;
import lighting.LightSource;
import lighting.SpotLight;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import primitives.FileNames;
import primitives.Printable;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.JitteredGrid;
import renderer.Preview;
import renderer.PreviewWindow;
import renderer.RayTracerBase;
import renderer.Render;
import scenefile.AnimatedScene;
import scenefile.Picture;
import scenefile.RenderSettings;
import scenefile.SceneFileException;
import scenefile.SceneLoader;

/**
 * The command line, {@value #NAME}: renders a scene file to an image (PNG, JPEG or BMP, by the output
 * file's extension), with a progress bar on the error stream as wide as the terminal, and prints the
 * elapsed time and the ray counts; {@code --quiet} keeps it silent but for a failure, {@code --preview}
 * shows the picture forming in a window. Options that are not given keep the scene file's settings.
 * {@code --gallery [FOLDER]} renders the example {@link Gallery} instead (into {@code images/} by default);
 * with no arguments at all the command prints its usage and exits with 2. Exit codes: 0 on success, 2 for
 * anything that stops the picture (a bad argument, a bad scene file, an image that cannot be written, not
 * enough memory), with one line on the error stream and never a stack trace. The output path is checked
 * first, before the scene file is read.
 */
@Command(name = RenderCommand.NAME, mixinStandardHelpOptions = true, versionProvider = RenderCommand.Version.class,
        sortOptions = false, usageHelpAutoWidth = true,
        description = {"Renders a scene file (XML, see docs/scene-format.md) to an image, or with --gallery the"
                + " example gallery."},
        footerHeading = "%nExit codes:%n",
        footer = {"  0  the image (with --gallery, every picture of the gallery) is written",
                "  2  no arguments (this usage), bad arguments, a bad scene file, or the image cannot be written"
                        + " (one line says why)"})
public class RenderCommand implements Callable<Integer> {
    /** Exit code: the image is written. */
    public static final int OK = 0;
    /** Exit code: bad arguments, a bad scene file, or an image that cannot be written. */
    public static final int BAD_INPUT = 2;
    /** The most rendering threads the command starts. */
    public static final int MAX_THREADS = 1024;
    /** How the command is run, as its help and the README say: the runnable jar that {@code mvn package} builds. */
    public static final String NAME = "java -jar target/raytracer.jar";

    @Spec
    private CommandSpec spec;

    /** The folder {@code --gallery} renders into when it names none. */
    public static final String GALLERY_FOLDER = "images";
    /** The options that go with {@code --gallery}: the gallery's pictures keep their own settings. */
    private static final List<String> GALLERY_OPTIONS = List.of("--gallery", "--threads", "--quiet");

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE.xml", description = "the scene file")
    private Path sceneFile;

    @Option(names = "--gallery", arity = "0..1", paramLabel = "FOLDER", fallbackValue = GALLERY_FOLDER,
            description = "render the example gallery into FOLDER (default: " + GALLERY_FOLDER + ") instead of a"
                    + " scene file; only --threads and --quiet go with it")
    private Path gallery;

    @Option(names = {"-o", "--output"}, paramLabel = "FILE",
            description = "the image file, whose extension gives its format: png, jpg, jpeg or bmp (default: the"
                    + " scene file's name with .png instead of .xml, in the current directory)")
    private Path output;

    @Option(names = "--width", paramLabel = "W",
            description = "the image's width in pixels (default: the scene file's; given alone, the height "
                    + "follows the scene's aspect ratio)")
    private Integer width;

    @Option(names = "--height", paramLabel = "H",
            description = "the image's height in pixels (default: the scene file's; given alone, the width "
                    + "follows the scene's aspect ratio)")
    private Integer height;

    @Option(names = "--soft-shadows", negatable = true,
            description = "soft shadows from lights with an edge size, or hard shadows (default: the scene file's)")
    private Boolean softShadows;

    @Option(names = "--adaptive", negatable = true,
            description = "adaptive sampling of the lights' squares with soft shadows (default: the scene file's)")
    private Boolean adaptive;

    @Option(names = "--beams", paramLabel = "N",
            description = "soft shadows: N x N + 1 shadow rays per light (default: the scene file's)")
    private Integer beams;

    @Option(names = "--aa", paramLabel = "K",
            description = "anti-aliasing: K x K rays per pixel, 1 for none (default: the scene file's)")
    private Integer antiAliasing;

    @Option(names = "--gloss-rays", paramLabel = "G",
            description = "glossy and blurry surfaces: G x G spread rays at the first one a ray meets, one at each"
                    + " further one (default: the scene file's)")
    private Integer glossRays;

    @Option(names = "--seed", paramLabel = "S",
            description = "the seed of the random sampling (default: the scene file's)")
    private Long seed;

    @Option(names = "--adaptive-aa", negatable = true,
            description = "adaptive super-sampling: corners and centre of each pixel first, divided where they"
                    + " differ, down to the --aa grid (default: the scene file's)")
    private Boolean adaptiveSuperSampling;

    @Option(names = "--aperture", paramLabel = "A",
            description = "depth of field: the edge of the camera's square aperture, 0 for a pinhole camera"
                    + " (default: the scene file's)")
    private Double aperture;

    @Option(names = "--focus", paramLabel = "F",
            description = "depth of field: the distance along the camera's direction of the plane in focus"
                    + " (default: the scene file's, or its view plane's)")
    private Double focus;

    @Option(names = "--aperture-rays", paramLabel = "N",
            description = "depth of field: N x N rays through the aperture per point of a pixel (default: the"
                    + " scene file's)")
    private Integer apertureRays;

    @Option(names = "--threads", paramLabel = "T", defaultValue = "0",
            description = "the number of rendering threads, 0 for one per core (default: ${DEFAULT-VALUE})")
    private int threads;

    @Option(names = {"-q", "--quiet"},
            description = "no progress bar and no report: only a failure's line is printed")
    private boolean quiet;

    @Option(names = "--preview",
            description = "show the picture in a window as it renders, and keep the window open until it is"
                    + " closed (without a display, say so and render anyway)")
    private boolean preview;

    @Mixin
    private AnimationOptions animationOptions = new AnimationOptions();
    /** The frames of an animation, once the options are checked; null for a still picture. */
    private Animation animation;

    private final boolean terminal;

    /** A command whose progress bar prints one line now and then, as it does when the error stream is a file. */
    public RenderCommand() {
        this(false);
    }

    /**
     * A command.
     *
     * @param terminal true when the error stream is a terminal: the progress bar redraws its line in place
     */
    public RenderCommand(boolean terminal) {
        this.terminal = terminal;
    }

    /**
     * A command line running a render command: bad arguments, a bad scene file or an image that
     * cannot be written give one line on the error stream and exit code 2, never a stack trace.
     *
     * @param terminal true when the error stream is a terminal
     * @return the command line; set its out and err writers before executing it
     */
    public static CommandLine newCommandLine(boolean terminal) {
        return new CommandLine(new RenderCommand(terminal))
                .registerConverter(Path.class, RenderCommand::path)
                .setParameterExceptionHandler(RenderCommand::badArguments)
                .setExecutionExceptionHandler((e, commandLine, parseResult) ->
                        printFailure(commandLine, ((RenderCommand) commandLine.getCommand()).failure(e)));
    }

    /** The path an argument names; one that cannot be a path (in the C locale, say) is a bad argument saying why. */
    private static Path path(String name) {
        try {
            return FileNames.toPath(name);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.TypeConversionException(e.getMessage());
        }
    }

    /** Prints a bad argument's message, with picocli's suggestions and a hint, on one line. */
    private static int badArguments(CommandLine.ParameterException e, String[] args) {
        CommandLine commandLine = e.getCommandLine();
        StringWriter suggestions = new StringWriter();
        CommandLine.UnmatchedArgumentException.printSuggestions(e, new PrintWriter(suggestions));
        return printFailure(commandLine, oneLine(e.getMessage() + " " + suggestions) + " (see '"
                + commandLine.getCommandSpec().qualifiedName() + " --help')");
    }

    /** Prints a failure on one line of the error stream; returns the exit code for bad input. */
    private static int printFailure(CommandLine commandLine, String message) {
        commandLine.getErr().println(oneLine(message));
        commandLine.getErr().flush();
        return BAD_INPUT;
    }

    /** The line telling what stopped the picture, in the user's terms (never an exception's class). */
    private String failure(Exception e) {
        if (e instanceof SceneFileException || e instanceof UncheckedIOException || e instanceof Failure)
            return e.getMessage();
        String problem = e.getMessage() == null || e.getMessage().isBlank() ? "an internal error" : e.getMessage();
        return sceneFile + ": the scene cannot be rendered: " + problem;
    }

    /**
     * The text on one line: line breaks and the blanks around them become one space, and what is left that
     * a terminal could take for a command (a control character quoted from the input) a visible escape.
     */
    private static String oneLine(String text) {
        return text == null ? "" : Printable.of(text.strip().replaceAll("\\s*\\R\\s*", " "));
    }

    @Override
    public Integer call() {
        if (sceneFile == null && gallery == null && !animationOptions.assembles())
            return usage();
        if (gallery != null)
            return renderGallery();
        checkArguments();
        Path file = outputFile();
        if (animation != null) {
            Animator animator = new Animator(this, animation, file, animationOptions.fps());
            return animationOptions.assembles() ? animator.assemble(quiet) : animator.render(quiet, terminal, threads);
        }
        ImageWriter.checkOutput(file);
        Picture picture = picture(loadAnimation(), 0);
        Render render = newRender(picture, file).setMultithreading(threads);
        Preview model = preview ? new Preview(render.getImageWriter(), file.getFileName().toString()) : null;
        PreviewWindow window = model == null ? null : openWindow(model, file);
        noteIgnoredEdges(picture); // once the picture is sure to start: a failure before stays one line alone
        long start = System.nanoTime();
        if (quiet)
            render(picture, render.setProgressListener(model), () -> { });
        else
            renderWithBar(picture, render, model);
        double seconds = (System.nanoTime() - start) / 1e9;
        if (!quiet)
            report(file, picture, seconds, render.getRayTracer());
        if (window != null)
            awaitClosed(window);
        return OK;
    }

    /**
     * With neither a scene file nor {@code --gallery}: the usage on the error stream when nothing at all
     * was given, otherwise a bad argument (one line).
     *
     * @return the exit code for bad input
     */
    private int usage() {
        CommandLine commandLine = spec.commandLine();
        if (!commandLine.getParseResult().originalArgs().isEmpty())
            throw new CommandLine.ParameterException(commandLine,
                    "Missing required parameter: 'SCENE.xml' (or --gallery)");
        commandLine.usage(commandLine.getErr());
        commandLine.getErr().flush();
        return BAD_INPUT;
    }

    /**
     * Renders every picture of the gallery into the {@code --gallery} folder, a line for each on the
     * output stream (none with {@code --quiet}).
     *
     * @return the exit code: 0 once every picture is written
     */
    private int renderGallery() {
        CommandLine commandLine = spec.commandLine();
        if (sceneFile != null)
            throw new CommandLine.ParameterException(commandLine, "give a scene file or --gallery, not both");
        for (CommandLine.Model.OptionSpec option : commandLine.getParseResult().matchedOptions())
            if (!GALLERY_OPTIONS.contains(option.longestName()))
                throw new CommandLine.ParameterException(commandLine, option.longestName()
                        + " does not go with --gallery: the gallery's pictures keep their own settings"
                        + " (only --threads and --quiet go with it)");
        requireThreads();
        PrintWriter out = commandLine.getOut();
        for (Picture picture : Gallery.pictures()) {
            long start = System.nanoTime();
            Gallery.render(picture, gallery, threads);
            if (!quiet) {
                out.printf(Locale.ROOT, "%-40s %4dx%-4d %6.2f s%n", gallery.resolve(picture.name()
                        + ImageWriter.EXTENSION), picture.nX(), picture.nY(), (System.nanoTime() - start) / 1e9);
                out.flush();
            }
        }
        return OK;
    }

    /**
     * Renders with the progress bar on the error stream, and the preview, if any, told of the progress too.
     *
     * @param picture the picture
     * @param render  its render
     * @param model   the preview, or null
     */
    private void renderWithBar(Picture picture, Render render, Preview model) {
        try (PixelProgress progress = new PixelProgress(spec.commandLine().getErr(), terminal,
                (long) picture.nX() * picture.nY())) {
            LongConsumer listener = progress.listener();
            render.setProgressListener(model == null ? listener : listener.andThen(model));
            render(picture, render, progress::mute);
        }
    }

    /**
     * Notes, in one line on the error stream (none with {@code --quiet}), that the first light with an
     * edge casts hard shadows all the same because soft shadows are off: its square is ignored.
     *
     * @param picture the picture, with the command line's options applied
     */
    void noteIgnoredEdges(Picture picture) {
        if (quiet || picture.settings().softShadows())
            return;
        for (LightSource light : picture.scene().lights)
            if (light instanceof AreaLightSource area && area.getEdges() > 0) {
                PrintWriter err = spec.commandLine().getErr();
                err.println(oneLine(sceneFile + ": <" + (light instanceof SpotLight ? "spot-light" : "point-light")
                        + "> has edge " + number(area.getEdges()) + " but soft shadows are off: add"
                        + " soft-shadows=\"true\" to <render> or --soft-shadows"));
                err.flush();
                return;
            }
    }

    /** {@return a number as a person writes it: 40, not 40.0} */
    private static String number(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value)
                : Double.toString(value);
    }

    /**
     * Opens the preview window, or says in one line that there is no display for it.
     *
     * @param model the preview
     * @param file  the image file, named in the line
     * @return the window, or null when there is no display
     */
    private PreviewWindow openWindow(Preview model, Path file) {
        try {
            return PreviewWindow.open(model);
        } catch (HeadlessException e) {
            if (!quiet) {
                spec.commandLine().getErr().println(Printable.of(file) + ": there is no display to show the preview"
                        + " window on; rendering without it");
                spec.commandLine().getErr().flush();
            }
            return null;
        }
    }

    /** Keeps the preview window open until the user closes it. */
    private void awaitClosed(PreviewWindow window) {
        if (!quiet) {
            spec.commandLine().getOut().println("Close the preview window to finish.");
            spec.commandLine().getOut().flush();
        }
        try {
            window.awaitClosed();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** {@return the command line, for its streams} */
    CommandLine commandLine() {
        return spec.commandLine();
    }

    /** {@return the scene file} */
    Path sceneFile() {
        return sceneFile;
    }

    /** Reads the scene file; not enough memory or stack for it is one line too. */
    AnimatedScene loadAnimation() {
        return loading(() -> SceneLoader.loadAnimation(sceneFile));
    }

    /** The scene's picture at a time of its run, with the options applied; its bodies are built as for loading. */
    Picture picture(AnimatedScene scene, double time) {
        return adjust(loading(() -> scene.at(time)));
    }

    /** Runs a step of loading the scene: not enough memory or stack for it is one line. */
    private <T> T loading(Supplier<T> step) {
        try {
            return step.get();
        } catch (OutOfMemoryError e) {
            throw new Failure(sceneFile + ": not enough memory to load the scene: its <mesh> files are too large;"
                    + " use smaller meshes or give Java more memory (java -Xmx...)", e);
        } catch (StackOverflowError e) {
            throw new Failure(sceneFile + ": the scene's elements are nested too deeply to load; nest fewer"
                    + " <geometries> inside each other", e);
        }
    }

    /** The render of the picture; not enough memory for its image is one line naming the size. */
    Render newRender(Picture picture, Path file) {
        try {
            return picture.newRender(file);
        } catch (OutOfMemoryError e) {
            long megabytes = (long) picture.nX() * picture.nY() * Integer.BYTES >> 20;
            throw new Failure(file + ": not enough memory for a " + picture.nX() + " x " + picture.nY()
                    + " picture (" + megabytes + " MB); choose a smaller --width/--height or give Java more memory"
                    + " (java -Xmx...)", e);
        }
    }

    /**
     * Renders and writes the picture. On a failure the progress bar is muted, so the failure's line is
     * the only one; not enough memory while rendering is one line naming what to make smaller.
     *
     * @param picture the picture
     * @param render  its render
     * @param mute    silences the progress bar
     */
    void render(Picture picture, Render render, Runnable mute) {
        try {
            picture.render(render);
        } catch (OutOfMemoryError e) {
            mute.run();
            throw new Failure(sceneFile + ": not enough memory to render the scene at " + picture.nX() + " x "
                    + picture.nY() + "; choose a smaller --width/--height, fewer --beams or --aa, or give Java"
                    + " more memory (java -Xmx...)", e);
        } catch (RuntimeException e) {
            mute.run();
            throw e;
        }
    }

    /** Checks the options' values; a bad one is a bad argument (exit code 2). */
    private void checkArguments() {
        atLeastOne("--width", width);
        atLeastOne("--height", height);
        if (beams != null)
            requireGrid("--beams", beams);
        if (antiAliasing != null)
            requireGrid("--aa", antiAliasing);
        if (glossRays != null)
            requireGrid("--gloss-rays", glossRays);
        if (apertureRays != null)
            requireGrid("--aperture-rays", apertureRays);
        if (aperture != null)
            requireValid(() -> Camera.requireApertureSize(aperture, "--aperture"));
        if (focus != null)
            requireValid(() -> Camera.requireFocalDistance(focus, "--focus"));
        requireThreads();
        animation = animationOptions.check(spec.commandLine(), output);
        if (animation != null && preview)
            throw new CommandLine.ParameterException(spec.commandLine(), "--preview does not go with --frames");
        if (output != null && !Animation.isGif(output))
            try {
                ImageWriter.formatOf(output);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(spec.commandLine(), "-o: " + e.getMessage());
            }
    }

    private void requireThreads() {
        if (threads < 0 || threads > MAX_THREADS)
            throw new CommandLine.ParameterException(spec.commandLine(),
                    "--threads must be 0 (one per core) to " + MAX_THREADS + ", got " + threads);
    }

    private void requireGrid(String option, int value) {
        requireValid(() -> JitteredGrid.requireSqrtSamples(value, option));
    }

    /** Runs a check of an option's value; what it rejects is a bad argument. */
    private void requireValid(Runnable check) {
        try {
            check.run();
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(spec.commandLine(), e.getMessage());
        }
    }

    private void atLeastOne(String option, Integer value) {
        if (value != null && value < 1)
            throw new CommandLine.ParameterException(spec.commandLine(),
                    option + " must be 1 or more, got " + value);
    }

    /** The picture with the options given on the command line instead of the scene file's. */
    private Picture adjust(Picture picture) {
        RenderSettings settings = picture.settings();
        if (softShadows != null)
            settings = settings.withSoftShadows(softShadows);
        if (adaptive != null)
            settings = settings.withAdaptiveSoftShadows(adaptive);
        if (beams != null)
            settings = settings.withSqrtBeamNum(beams);
        if (antiAliasing != null)
            settings = settings.withAntiAliasing(antiAliasing);
        if (seed != null)
            settings = settings.withSeed(seed);
        if (glossRays != null)
            settings = settings.withSqrtGlossRays(glossRays);
        if (adaptiveSuperSampling != null)
            settings = settings.withAdaptiveSuperSampling(adaptiveSuperSampling);
        adjustLens(picture.camera());
        int w = picture.nX();
        int h = picture.nY();
        if (width != null && height != null) {
            w = width;
            h = height;
        } else if (width != null) {
            w = width;
            h = (int) Math.max(1, Math.round((double) width * picture.nY() / picture.nX()));
        } else if (height != null) {
            h = height;
            w = (int) Math.max(1, Math.round((double) height * picture.nX() / picture.nY()));
        }
        try {
            return picture.withSize(w, h).withSettings(settings);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(spec.commandLine(), "--width/--height: " + e.getMessage());
        }
    }

    /** Gives the camera the depth of field options that were given (checked already). */
    private void adjustLens(Camera camera) {
        if (aperture != null)
            camera.setApertureSize(aperture);
        if (focus != null)
            camera.setFocalDistance(focus);
        if (apertureRays != null)
            camera.setSqrtApertureRays(apertureRays);
    }

    /**
     * @return the image file: the one given with {@code -o}, or the scene file's name with {@code .png}
     * instead of {@code .xml}, in the current directory
     */
    Path outputFile() {
        if (output != null)
            return output;
        String name = sceneFile.getFileName().toString();
        if (name.toLowerCase(Locale.ROOT).endsWith(".xml"))
            name = name.substring(0, name.length() - ".xml".length());
        return Path.of(name + ImageWriter.EXTENSION);
    }

    /** Prints the image file, its size, the time and the ray counts (spread rays only when there are any). */
    private void report(Path file, Picture picture, double seconds, RayTracerBase tracer) {
        long primary = tracer.getPrimaryRaysCount();
        long shadow = tracer.getShadowRaysCount();
        long spread = tracer.getSpreadRaysCount();
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "Image:        %s%n", Printable.of(file.toAbsolutePath().normalize()));
        out.printf(Locale.ROOT, "Size:         %d x %d pixels%n", picture.nX(), picture.nY());
        out.printf(Locale.ROOT, "Time:         %.3f s%n", seconds);
        out.printf(Locale.ROOT, "Primary rays: %d%n", primary);
        out.printf(Locale.ROOT, "Shadow rays:  %d%n", shadow);
        if (spread > 0)
            out.printf(Locale.ROOT, "Spread rays:  %d%n", spread);
        out.printf(Locale.ROOT, "Rays/second:  %.0f%n", seconds > 0 ? (primary + shadow + spread) / seconds : 0.0);
        out.flush();
    }

    /** The version of this build, as the build wrote it into {@code app/version.properties}. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() throws IOException {
            Properties properties = new Properties();
            try (InputStream in = RenderCommand.class.getResourceAsStream("version.properties")) {
                if (in != null)
                    properties.load(in);
            }
            return new String[] { "raytracer " + properties.getProperty("version", "(version unknown)") };
        }
    }
}
