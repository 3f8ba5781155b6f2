package scenefile;

import java.nio.file.Path;

import primitives.Printable;

/**
 * A scene file that cannot be read: its message is one line naming the file, the line and column
 * where the parser knows them, and what is wrong — {@code scenes/a.xml:12:40: radius must be positive}.
 * The file's name and the problem, which may quote the file's text, are made {@link Printable printable}:
 * a control character in them reaches no terminal.
 */
public class SceneFileException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    /** The line or column of a problem whose place in the file is not known. */
    public static final int UNKNOWN = -1;

    /** The scene file. */
    private final transient Path file;
    /** The line of the problem, from 1, or {@link #UNKNOWN}. */
    private final int line;
    /** The column of the problem, from 1, or {@link #UNKNOWN}. */
    private final int column;
    /** What is wrong, without the place. */
    private final String problem;

    /**
     * A problem at a place in a scene file.
     *
     * @param file    the scene file
     * @param line    the line, from 1, or {@link #UNKNOWN}
     * @param column  the column, from 1, or {@link #UNKNOWN}
     * @param problem what is wrong
     * @param cause   the exception that revealed the problem, or null
     */
    public SceneFileException(Path file, int line, int column, String problem, Throwable cause) {
        super(Printable.of(where(file, line, column) + ": " + problem), cause);
        this.file = file;
        this.line = line;
        this.column = column;
        this.problem = Printable.of(problem);
    }

    /**
     * A problem with a whole scene file (it is missing, say).
     *
     * @param file    the scene file
     * @param problem what is wrong
     * @param cause   the exception that revealed the problem, or null
     */
    public SceneFileException(Path file, String problem, Throwable cause) {
        this(file, UNKNOWN, UNKNOWN, problem, cause);
    }

    private static String where(Path file, int line, int column) {
        if (line <= 0)
            return String.valueOf(file);
        return file + ":" + line + (column > 0 ? ":" + column : "");
    }

    /** {@return the scene file} */
    public Path getFile() {
        return file;
    }

    /** {@return the line of the problem, from 1, or {@link #UNKNOWN}} */
    public int getLine() {
        return line;
    }

    /** {@return the column of the problem, from 1, or {@link #UNKNOWN}} */
    public int getColumn() {
        return column;
    }

    /** {@return what is wrong, without the file and position, made printable} */
    public String getProblem() {
        return problem;
    }
}
