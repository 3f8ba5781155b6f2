package app;

import java.io.PrintWriter;

/**
 * The command-line entry point: runs the {@link RenderCommand render command} — {@code SCENE.xml
 * [options]} renders a scene file, {@code --gallery [FOLDER]} the example gallery (into {@code images/}
 * by default), and no arguments at all print the usage (exit code 2); see {@code --help}.
 */
public final class Main {
    private Main() {
    }

    /**
     * Runs the render command and exits with its exit code; after the gallery, which opens no window, it
     * returns instead, so that {@code mvn exec:java} ends as Maven does.
     *
     * @param args the render command's arguments
     */
    public static void main(String[] args) {
        int code = run(args, new PrintWriter(System.out, true), new PrintWriter(System.err, true),
                System.console() != null);
        if (code != RenderCommand.OK || !isGallery(args))
            System.exit(code);
    }

    /**
     * Runs the render command in this process.
     *
     * @param args     the command's arguments
     * @param out      where the command's results and help go
     * @param err      where its progress bar, notes, usage and error messages go
     * @param terminal true when the error stream is a terminal (the progress bar redraws its line)
     * @return the exit code: 0 on success, 2 on no arguments, bad arguments, a bad scene file or an image
     * that cannot be written
     */
    static int run(String[] args, PrintWriter out, PrintWriter err, boolean terminal) {
        return RenderCommand.newCommandLine(terminal).setOut(out).setErr(err).execute(args);
    }

    /** {@return whether the arguments ask for the gallery} */
    static boolean isGallery(String[] args) {
        for (String arg : args)
            if (arg.equals("--gallery") || arg.startsWith("--gallery="))
                return true;
        return false;
    }
}
