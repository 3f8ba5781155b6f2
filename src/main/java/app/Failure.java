package app;

/**
 * A failure of the command whose message is the whole line to print (not enough memory, a frame
 * missing for {@code --assemble}): the command prints it as it is, with exit code 2.
 */
final class Failure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * A failure.
     *
     * @param line  the line to print
     * @param cause what revealed it, or null
     */
    Failure(String line, Throwable cause) {
        super(line, cause);
    }
}
