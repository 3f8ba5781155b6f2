package testutil;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.List;

import app.RenderCommand;

/**
 * Runs the command line in this process, its out and err writers captured, for the test classes of
 * {@code app}.
 */
public final class TestCommands {
    /** Not instantiable. */
    private TestCommands() {
    }

    /**
     * The result of one run of the command.
     *
     * @param code its exit code
     * @param out  what it printed on the output stream
     * @param err  what it printed on the error stream
     */
    public record Result(int code, String out, String err) {
        /** @return the error stream's lines */
        public List<String> errLines() {
            return err.lines().toList();
        }
    }

    /**
     * Runs the command, not on a terminal.
     *
     * @param args its arguments
     * @return its exit code and output
     */
    public static Result run(String... args) {
        return run(false, args);
    }

    /**
     * Runs the command.
     *
     * @param terminal whether it takes its error stream for a terminal
     * @param args     its arguments
     * @return its exit code and output
     */
    public static Result run(boolean terminal, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = RenderCommand.newCommandLine(terminal).setOut(new PrintWriter(out)).setErr(new PrintWriter(err))
                .execute(args);
        return new Result(code, out.toString(), err.toString());
    }
}
